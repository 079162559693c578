#include "sim/validation/validation_errors.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace carom::validation {

std::string formatNumber(double value, int significantDigits) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value < 0 ? "-inf" : "inf";
  char buffer[64];
  const auto result = significantDigits > 0
                          ? std::to_chars(buffer, buffer + sizeof buffer, value,
                                          std::chars_format::general, significantDigits)
                          : std::to_chars(buffer, buffer + sizeof buffer, value);
  std::string text(buffer, result.ptr);
  const auto e = text.find('e');
  if (e == std::string::npos) return text;
  std::string exponent = text.substr(e + 1);
  const bool negative = exponent.front() == '-';
  if (exponent.front() == '+' || negative) exponent.erase(0, 1);
  exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
  return text.substr(0, e + 1) + (negative ? "-" : "") + exponent;
}

std::string formatDepth(double value) {
  return formatNumber(value, 6);
}

namespace {

// The subject's name in paths: the file's key.
std::string_view subjectKey(ValidationSubject subject) {
  switch (subject) {
    case ValidationSubject::World:
      return "world";
    case ValidationSubject::Tolerance:
      return "tolerance";
    case ValidationSubject::Planes:
      return "planes";
    case ValidationSubject::Cylinders:
      return "cylinders";
    case ValidationSubject::Boxes:
      return "boxes";
    case ValidationSubject::Balls:
      return "balls";
  }
  return {};
}

}  // namespace

std::string objectPath(const ValidationObject& object) {
  std::string path(subjectKey(object.subject));
  if (object.index) {
    path += '[';
    path += std::to_string(*object.index);
    path += ']';
  }
  return path;
}

std::string_view fieldPath(ValidationField field, ValidationSubject subject) {
  using F = ValidationField;
  const bool alone = subject == ValidationSubject::Tolerance;
  switch (field) {
    case F::None:
      return {};
    case F::Position:
      return ".position";
    case F::Velocity:
      return ".velocity";
    case F::AngularVelocity:
      return ".angularVelocity";
    case F::Radius:
      return ".radius";
    case F::Mass:
      return ".mass";
    case F::Point:
      return ".point";
    case F::Normal:
      return ".normal";
    case F::Axis:
      return ".axis";
    case F::Length:
      return ".length";
    case F::Center:
      return ".center";
    case F::HalfExtentX:
      return ".halfExtents[0]";
    case F::HalfExtentY:
      return ".halfExtents[1]";
    case F::HalfExtentZ:
      return ".halfExtents[2]";
    case F::RotationAxis:
      return ".rotation.axis";
    case F::RotationDegrees:
      return ".rotation.degrees";
    case F::Name:
      return ".name";
    case F::Restitution:
      return ".restitution";
    case F::Friction:
      return ".friction";
    case F::RollingResistance:
      return ".rollingResistance";
    case F::SpinningFriction:
      return ".spinningFriction";
    case F::TangentialRestitution:
      return ".tangentialRestitution";
    case F::Color:
      return ".color";
    case F::Gravity:
      return ".gravity";
    case F::TimeStep:
      return ".timeStep";
    case F::EnergyTolerance:
      return alone ? ".energy" : ".tolerance[0]";
    case F::PenetrationTolerance:
      return alone ? ".penetration" : ".tolerance[1]";
  }
  return {};
}

ValidationError overlapError(std::size_t ball, ValidationObject other, double depth,
                             std::optional<double> behind) {
  ValidationError error;
  error.object = {ValidationSubject::Balls, ball};
  error.path = objectPath(error.object) + ".position";
  error.other = other;
  if (behind) {
    error.problem = ValidationProblem::BehindSurface;
    error.value = *behind;
    error.message =
        "overlaps " + objectPath(other) + " (is " + formatDepth(*behind) + " behind its surface)";
  } else {
    error.problem = ValidationProblem::Overlaps;
    error.value = depth;
    error.message = "overlaps " + objectPath(other) + " by " + formatDepth(depth);
  }
  return error;
}

}  // namespace carom::validation
