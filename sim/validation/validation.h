#pragma once
// The one validation of scenes: the loader, the CLI and the editor all call this.

#include "sim/model/scene.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace carom {

// What a problem is about: the world, a tolerance given alone (carom-cli --tolerance), or a list
// of the scene's objects, or one entry of it.
enum class ValidationSubject { World, Tolerance, Planes, Cylinders, Boxes, Balls };

struct ValidationObject {
  ValidationSubject subject = ValidationSubject::World;
  std::optional<std::size_t> index;  // the entry; none for the world, a tolerance, a whole list
  bool operator==(const ValidationObject&) const = default;
};

// The field of the object a problem is in; None for a list's length and an overlap (which is the
// ball's position).
enum class ValidationField {
  None,
  Position,
  Velocity,
  AngularVelocity,
  Radius,
  Mass,
  Point,
  Normal,
  Axis,
  Length,
  Center,
  HalfExtentX,
  HalfExtentY,
  HalfExtentZ,
  RotationAxis,
  RotationDegrees,
  Name,
  Restitution,
  Friction,
  RollingResistance,
  SpinningFriction,
  TangentialRestitution,
  Color,
  Gravity,
  TimeStep,
  EnergyTolerance,
  PenetrationTolerance,
};

// Each of ValidationError's messages, with the numbers it quotes.
enum class ValidationProblem {
  NotFinite,      // "must be finite"
  TooLarge,       // |value| above `high`: "must be at most 1e12 in magnitude (got value)"
  NotPositive,    // value <= 0: "must be positive (got value)"
  TooSmall,       // value below `low`: "must be at least 1e-12 (got value)"
  NotBetween,     // value outside [low, high]: "must be between low and high (got value)"
  NotAboveZero,   // value <= 0 or not a number: "must be a number above zero (got value)"
  ZeroLength,     // a direction: "must not be zero-length"
  NameTooLong,    // `value` characters, at most `high`
  BadColor,       // `quoted` is not "#rrggbb"
  TooMany,        // a list of `value` entries, at most `high`
  Overlaps,       // the ball overlaps `other` by `value`
  BehindSurface,  // the ball's centre is `value` behind the surface of the plane `other`
};

struct ValidationError {
  std::string path;     // field path such as "balls[3].radius" or "world.timeStep"
  std::string message;  // what is wrong, such as "must be positive (got -1)"
  std::string text() const { return path.empty() ? message : path + ": " + message; }

  // The same problem as data, for the window to say in the user's words and language; path and
  // message stay the file's words for carom-cli and the loader. Filled by this header's checks.
  ValidationProblem problem = ValidationProblem::NotFinite;
  ValidationObject object{};
  ValidationField field = ValidationField::None;
  std::optional<ValidationObject> other{};  // what a ball overlaps
  double value = 0.0;
  double low = 0.0;
  double high = 0.0;
  std::string quoted{};  // a refused colour, shortened as the message quotes it
};

// All problems of the scene, in file order (at most `maxErrors`); empty when the scene is valid.
// Checks every number is finite and within the limits of tolerances.h, radii and masses are
// positive, as are a box's half extents, restitutions (also the world's tangential one) are in
// [0, 1], friction coefficients in [0, kMaxFriction], normals and axes (also a
// box's rotation axis) are not zero-length, names are at most kMaxNameCharacters long, colours
// are "#rrggbb", and that no ball overlaps another ball, a plane, a cylinder or a box (touching
// is fine).
std::vector<ValidationError> validateScene(const Scene& scene, std::size_t maxErrors = 20);

// The same rules for an edit, without looking at the whole scene again: `scene` was valid
// except for the objects listed (changed in place or appended), and its world is not checked.
// Returns what validateScene would, first problem first. Costs one pass over the balls per
// listed object, so a typed value in a scene of a million balls does not re-check them all.
struct SceneObjectIndices {
  std::vector<std::size_t> planes;
  std::vector<std::size_t> cylinders;
  std::vector<std::size_t> boxes;
  std::vector<std::size_t> balls;
};
std::vector<ValidationError> validateObjects(const Scene& scene, SceneObjectIndices objects,
                                             std::size_t maxErrors = 20);
// The lists' lengths alone, as validateScene checks them first: for readers that count a file's
// objects before they build any.
struct SceneCounts {
  std::size_t planes = 0;
  std::size_t cylinders = 0;
  std::size_t boxes = 0;
  std::size_t balls = 0;
};
std::vector<ValidationError> validateCounts(const SceneCounts& counts);
// The world's settings alone (gravity, time step, restitution, friction).
std::vector<ValidationError> validateWorld(const World& world, std::size_t maxErrors = 20);
// A tolerance given on its own (carom-cli --tolerance): paths "tolerance.energy" and
// "tolerance.penetration"; the same rule as a scene's world.tolerance.
std::vector<ValidationError> validateTolerance(const AccuracyTolerance& tolerance);

// Characters (Unicode code points) of UTF-8 text: the unit of the names' limit.
std::size_t characterCount(std::string_view utf8);

// Text from a scene file as a message quotes it: whole when short, else its first characters
// and "…", so that a message about a huge string (a colour, a method, a key) stays one line.
std::string excerpt(std::string_view utf8);

}  // namespace carom
