#pragma once
// How validation checks one field of an object against its rule (finite, within the limits of
// tolerances.h, positive, a direction, a name, a colour), and spells what it finds.

#include "sim/core/tolerances.h"
#include "sim/validation/validation.h"
#include "sim/validation/validation_errors.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>

namespace carom::validation {

// The numbers and text a problem quotes (ValidationError's).
struct Quoted {
  double value = 0.0;
  double low = 0.0;
  double high = 0.0;
  std::string quoted{};
};

// The checks below report into `errors` when given one and only answer otherwise, so the same
// rules decide both whether an object can take part in overlap tests and what is reported.
class FieldChecker {
 public:
  // Fields of `subject` (the world, a tolerance), or of entry `index` of its list; paths are
  // spelled only for a message, since a scene may hold a million balls.
  FieldChecker(ErrorList* errors, ValidationSubject subject,
               std::optional<std::size_t> index = std::nullopt)
      : errors_(errors), object_{subject, index} {}

  bool ok() const { return ok_; }

  void finiteBounded(ValidationField field, double value) {
    if (!std::isfinite(value)) return fail(field, ValidationProblem::NotFinite, "must be finite");
    if (std::abs(value) > tolerance::kMaxMagnitude) tooLarge(field, value);
  }

  // Returns whether the vector passed, so that a direction check can follow.
  bool vector(ValidationField field, const Vec3& value) {
    for (int i = 0; i < 3; ++i) {
      if (!std::isfinite(value[i])) {
        fail(field, ValidationProblem::NotFinite, "must be finite");
        return false;
      }
    }
    for (int i = 0; i < 3; ++i) {
      if (std::abs(value[i]) > tolerance::kMaxMagnitude) {
        tooLarge(field, value[i]);
        return false;
      }
    }
    return true;
  }

  void direction(ValidationField field, const Vec3& value) {
    if (vector(field, value) && value.norm() <= tolerance::kMinDirectionLength)
      fail(field, ValidationProblem::ZeroLength, "must not be zero-length");
  }

  void radius(ValidationField field, double value) {
    if (!std::isfinite(value)) return fail(field, ValidationProblem::NotFinite, "must be finite");
    if (value <= 0.0) return notPositive(field, value);
    if (value < tolerance::kMinRadius)
      return fail(field, ValidationProblem::TooSmall,
                  "must be at least " + formatNumber(tolerance::kMinRadius) + " (got " +
                      formatNumber(value) + ")",
                  {.value = value, .low = tolerance::kMinRadius});
    finiteBounded(field, value);
  }

  void positiveBetween(ValidationField field, double value, double low, double high) {
    if (!std::isfinite(value)) return fail(field, ValidationProblem::NotFinite, "must be finite");
    if (value <= 0.0) return notPositive(field, value);
    if (value < low || value > high) between(field, value, low, high);
  }

  void aboveZero(ValidationField field, double value) {
    if (!std::isfinite(value) || !(value > 0.0))
      fail(field, ValidationProblem::NotAboveZero,
           "must be a number above zero (got " + formatNumber(value) + ")", {.value = value});
  }

  // None (an object taking the world's value) passes.
  void inRange(ValidationField field, const std::optional<double>& value, double low, double high) {
    if (!value) return;
    if (!std::isfinite(*value)) return fail(field, ValidationProblem::NotFinite, "must be finite");
    if (*value < low || *value > high) between(field, *value, low, high);
  }

  void restitution(ValidationField field, const std::optional<double>& value) {
    inRange(field, value, 0.0, 1.0);
  }

  void frictionCoefficient(ValidationField field, const std::optional<double>& value) {
    inRange(field, value, 0.0, tolerance::kMaxFriction);
  }

  void info(const ObjectInfo& info) {
    const std::size_t nameLength = characterCount(info.name);
    if (nameLength > tolerance::kMaxNameCharacters)
      fail(ValidationField::Name, ValidationProblem::NameTooLong,
           "must be at most " + std::to_string(tolerance::kMaxNameCharacters) +
               " characters (got " + std::to_string(nameLength) + ")",
           {.value = double(nameLength), .high = double(tolerance::kMaxNameCharacters)});
    restitution(ValidationField::Restitution, info.restitution);
    frictionCoefficient(ValidationField::Friction, info.friction);
    frictionCoefficient(ValidationField::RollingResistance, info.rollingResistance);
    frictionCoefficient(ValidationField::SpinningFriction, info.spinningFriction);
    if (!isColor(info.color)) {
      std::string quoted = excerpt(info.color);
      fail(ValidationField::Color, ValidationProblem::BadColor,
           "must be empty or \"#rrggbb\" (got \"" + quoted + "\")", {.quoted = quoted});
    }
  }

 private:
  static bool isColor(const std::string& text) {
    if (text.empty()) return true;
    if (text.size() != 7 || text[0] != '#') return false;
    return std::all_of(text.begin() + 1, text.end(), [](char c) {
      return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
    });
  }

  void tooLarge(ValidationField field, double value) {
    fail(field, ValidationProblem::TooLarge,
         "must be at most " + formatNumber(tolerance::kMaxMagnitude) + " in magnitude (got " +
             formatNumber(value) + ")",
         {.value = value, .high = tolerance::kMaxMagnitude});
  }

  void notPositive(ValidationField field, double value) {
    fail(field, ValidationProblem::NotPositive,
         "must be positive (got " + formatNumber(value) + ")", {.value = value});
  }

  void between(ValidationField field, double value, double low, double high) {
    fail(field, ValidationProblem::NotBetween,
         "must be between " + formatNumber(low) + " and " + formatNumber(high) + " (got " +
             formatNumber(value) + ")",
         {.value = value, .low = low, .high = high});
  }

  void fail(ValidationField field, ValidationProblem problem, std::string message,
            Quoted quoted = {}) {
    ok_ = false;
    if (!errors_) return;
    ValidationError error;
    error.path = objectPath(object_) + std::string(fieldPath(field, object_.subject));
    error.message = std::move(message);
    error.problem = problem;
    error.object = object_;
    error.field = field;
    error.value = quoted.value;
    error.low = quoted.low;
    error.high = quoted.high;
    error.quoted = std::move(quoted.quoted);
    errors_->add(std::move(error));
  }

  ErrorList* errors_;
  ValidationObject object_;
  bool ok_ = true;
};

}  // namespace carom::validation
