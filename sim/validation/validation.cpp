#include "sim/validation/validation.h"

#include "sim/core/tolerances.h"
#include "sim/geometry/shapes.h"
#include "sim/validation/ball_overlap_finder.h"
#include "sim/validation/field_checker.h"
#include "sim/validation/validation_errors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>

namespace carom {
namespace {

namespace tol = tolerance;

using validation::BallOverlapFinder;
using validation::ErrorList;
using validation::FieldChecker;
using validation::objectPath;
using validation::overlapError;
using validation::overlaps;

using F = ValidationField;

bool checkPlane(const Plane& plane, std::size_t index, ErrorList* errors) {
  FieldChecker check(errors, ValidationSubject::Planes, index);
  check.vector(F::Point, plane.point);
  check.direction(F::Normal, plane.normal);
  check.info(plane);
  return check.ok();
}

bool checkCylinder(const Cylinder& cylinder, std::size_t index, ErrorList* errors) {
  FieldChecker check(errors, ValidationSubject::Cylinders, index);
  check.vector(F::Point, cylinder.point);
  check.direction(F::Axis, cylinder.axis);
  check.radius(F::Radius, cylinder.radius);
  if (cylinder.length) check.radius(F::Length, *cylinder.length);
  check.info(cylinder);
  return check.ok();
}

bool checkBox(const Box& box, std::size_t index, ErrorList* errors) {
  FieldChecker check(errors, ValidationSubject::Boxes, index);
  check.vector(F::Center, box.center);
  constexpr F kHalfExtents[] = {F::HalfExtentX, F::HalfExtentY, F::HalfExtentZ};
  for (int k = 0; k < 3; ++k) check.radius(kHalfExtents[k], box.halfExtents[k]);
  if (box.rotation) {
    check.direction(F::RotationAxis, box.rotation->axis);
    check.finiteBounded(F::RotationDegrees, box.rotation->degrees);
  }
  check.info(box);
  return check.ok();
}

bool checkBall(const Ball& ball, std::size_t index, ErrorList* errors) {
  FieldChecker check(errors, ValidationSubject::Balls, index);
  check.vector(F::Position, ball.position);
  check.vector(F::Velocity, ball.velocity);
  check.vector(F::AngularVelocity, ball.angularVelocity);
  check.radius(F::Radius, ball.radius);
  check.positiveBetween(F::Mass, ball.mass, tol::kMinMass, tol::kMaxMass);
  check.info(ball);
  return check.ok();
}

void checkWorld(const World& world, ErrorList& errors) {
  FieldChecker check(&errors, ValidationSubject::World);
  check.vector(F::Gravity, world.gravity);
  check.positiveBetween(F::TimeStep, world.timeStep, tol::kMinTimeStep, tol::kMaxTimeStep);
  check.restitution(F::Restitution, world.restitution);
  check.frictionCoefficient(F::Friction, world.friction);
  check.frictionCoefficient(F::RollingResistance, world.rollingResistance);
  check.frictionCoefficient(F::SpinningFriction, world.spinningFriction);
  check.restitution(F::TangentialRestitution, world.tangentialRestitution);
  if (world.autoMethod) {
    check.aboveZero(F::EnergyTolerance, world.autoMethod->energyPerSecond);
    check.aboveZero(F::PenetrationTolerance, world.autoMethod->penetrationFraction);
  }
}

bool checkCount(ValidationSubject list, std::size_t count, std::size_t limit, ErrorList& errors) {
  if (count <= limit) return true;
  ValidationError error;
  error.object = {list, std::nullopt};
  error.path = objectPath(error.object);
  error.message =
      "must have at most " + std::to_string(limit) + " entries (got " + std::to_string(count) + ")";
  error.problem = ValidationProblem::TooMany;
  error.value = double(count);
  error.high = double(limit);
  errors.add(std::move(error));
  return false;
}

// Shapes that passed their own checks, with their scene index, for the overlap tests.
struct IndexedPlane {
  std::size_t index;
  PlaneShape shape;
};

struct IndexedCylinder {
  std::size_t index;
  CylinderShape shape;
};

struct IndexedBox {
  std::size_t index;
  BoxShape shape;
};

// The shapes that passed their own checks, for the overlap tests.
struct StaticShapes {
  std::vector<IndexedPlane> planes;
  std::vector<IndexedCylinder> cylinders;
  std::vector<IndexedBox> boxes;
  bool empty() const { return planes.empty() && cylinders.empty() && boxes.empty(); }
};

void checkBallAgainstPlane(const Ball& ball, std::size_t ballIndex, const IndexedPlane& plane,
                           ErrorList& errors) {
  const double distance = plane.shape.gap(ball.position, 0.0);
  if (!overlaps(ball.radius - distance, ball.radius)) return;
  const ValidationObject other{ValidationSubject::Planes, plane.index};
  const double depth = ball.radius - distance;
  errors.add(distance < 0.0 ? overlapError(ballIndex, other, depth, -distance)
                            : overlapError(ballIndex, other, depth));
}

void checkBallAgainstCylinder(const Ball& ball, std::size_t ballIndex,
                              const IndexedCylinder& cylinder, ErrorList& errors) {
  const double depth = -cylinder.shape.contact(ball.position, ball.radius).gap;
  // An infinite cylinder's overlap is judged against the radii's sum, as its distance is taken.
  const double scale = cylinder.shape.capped() ? ball.radius : ball.radius + cylinder.shape.radius;
  if (overlaps(depth, scale))
    errors.add(overlapError(ballIndex, {ValidationSubject::Cylinders, cylinder.index}, depth));
}

void checkBallAgainstBox(const Ball& ball, std::size_t ballIndex, const IndexedBox& box,
                         ErrorList& errors) {
  const double depth = -box.shape.contact(ball.position, ball.radius).gap;
  if (overlaps(depth, ball.radius))
    errors.add(overlapError(ballIndex, {ValidationSubject::Boxes, box.index}, depth));
}

void checkBallAgainstStatics(const Ball& ball, std::size_t ballIndex, const StaticShapes& shapes,
                             ErrorList& errors) {
  for (const IndexedPlane& plane : shapes.planes)
    checkBallAgainstPlane(ball, ballIndex, plane, errors);
  for (const IndexedCylinder& cylinder : shapes.cylinders)
    checkBallAgainstCylinder(ball, ballIndex, cylinder, errors);
  for (const IndexedBox& box : shapes.boxes) checkBallAgainstBox(ball, ballIndex, box, errors);
}

void checkBalls(const Scene& scene, const StaticShapes& shapes, ErrorList& errors) {
  const auto& balls = scene.balls;
  std::vector<bool> usable(balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i) usable[i] = checkBall(balls[i], i, nullptr);
  BallOverlapFinder finder(balls, usable, errors.room());

  for (std::size_t i = 0; i < balls.size() && !errors.full(); ++i) {
    if (!usable[i]) {
      checkBall(balls[i], i, &errors);
      continue;
    }
    checkBallAgainstStatics(balls[i], i, shapes, errors);
    for (const auto& overlap : finder.overlapsOf(i))
      errors.add(overlapError(i, {ValidationSubject::Balls, overlap.earlier}, overlap.depth));
  }
}

bool checkCounts(const SceneCounts& counts, ErrorList& errors) {
  bool countsOk = checkCount(ValidationSubject::Planes, counts.planes, tol::kMaxPlanes, errors);
  countsOk &=
      checkCount(ValidationSubject::Cylinders, counts.cylinders, tol::kMaxCylinders, errors);
  countsOk &= checkCount(ValidationSubject::Boxes, counts.boxes, tol::kMaxBoxes, errors);
  countsOk &= checkCount(ValidationSubject::Balls, counts.balls, tol::kMaxBalls, errors);
  return countsOk;
}

bool checkCounts(const Scene& scene, ErrorList& errors) {
  return checkCounts(SceneCounts{scene.planes.size(), scene.cylinders.size(), scene.boxes.size(),
                                 scene.balls.size()},
                     errors);
}

// An edit of more balls than this is checked as a whole scene: a ball set against every other
// costs about a hundredth of what the grid spends on each ball.
constexpr std::size_t kMostBallsCheckedPairwise = 64;

bool contains(const std::vector<std::size_t>& sorted, std::size_t index) {
  return std::binary_search(sorted.begin(), sorted.end(), index);
}

}  // namespace

std::vector<ValidationError> validateCounts(const SceneCounts& counts) {
  ErrorList errors(4);
  checkCounts(counts, errors);
  return errors.take();
}

std::size_t characterCount(std::string_view utf8) {
  // Every character has one byte that is not a continuation byte (10xxxxxx).
  return static_cast<std::size_t>(std::count_if(utf8.begin(), utf8.end(), [](char byte) {
    return (static_cast<unsigned char>(byte) & 0xC0) != 0x80;
  }));
}

std::string excerpt(std::string_view utf8) {
  // As much as a message can quote and still read as one line.
  constexpr std::size_t kQuotedCharacters = 32;
  std::size_t characters = 0;
  for (std::size_t i = 0; i < utf8.size(); ++i) {
    if ((static_cast<unsigned char>(utf8[i]) & 0xC0) == 0x80) continue;
    if (characters++ == kQuotedCharacters) return std::string(utf8.substr(0, i)) + "\u2026";
  }
  return std::string(utf8);
}

std::vector<ValidationError> validateScene(const Scene& scene, std::size_t maxErrors) {
  ErrorList errors(maxErrors);
  // Counts first: a scene with absurdly many objects is refused before any of them is looked at.
  if (!checkCounts(scene, errors)) return errors.take();

  checkWorld(scene.world, errors);

  // Only well-formed shapes take part in overlap tests; the others are reported.
  StaticShapes shapes;
  for (std::size_t i = 0; i < scene.planes.size() && !errors.full(); ++i)
    if (checkPlane(scene.planes[i], i, &errors))
      shapes.planes.push_back({i, planeShape(scene.planes[i])});
  for (std::size_t i = 0; i < scene.cylinders.size() && !errors.full(); ++i)
    if (checkCylinder(scene.cylinders[i], i, &errors))
      shapes.cylinders.push_back({i, cylinderShape(scene.cylinders[i])});
  for (std::size_t i = 0; i < scene.boxes.size() && !errors.full(); ++i)
    if (checkBox(scene.boxes[i], i, &errors)) shapes.boxes.push_back({i, boxShape(scene.boxes[i])});
  if (!errors.full()) checkBalls(scene, shapes, errors);
  return errors.take();
}

std::vector<ValidationError> validateWorld(const World& world, std::size_t maxErrors) {
  ErrorList errors(maxErrors);
  checkWorld(world, errors);
  return errors.take();
}

std::vector<ValidationError> validateTolerance(const AccuracyTolerance& tolerance) {
  ErrorList errors(2);
  FieldChecker check(&errors, ValidationSubject::Tolerance);
  check.aboveZero(F::EnergyTolerance, tolerance.energyPerSecond);
  check.aboveZero(F::PenetrationTolerance, tolerance.penetrationFraction);
  return errors.take();
}

std::vector<ValidationError> validateObjects(const Scene& scene, SceneObjectIndices objects,
                                             std::size_t maxErrors) {
  for (auto* list : {&objects.planes, &objects.cylinders, &objects.boxes, &objects.balls}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
  // Each changed ball is set against every ball. When many changed (Use Current State changes
  // them all), the whole scene's check costs less, being a grid linear in the balls, and gives
  // the same answer: the rest of the scene was valid, and so is its world.
  if (objects.balls.size() > kMostBallsCheckedPairwise) return validateScene(scene, maxErrors);
  // Every problem is gathered, then put in file order (planes, cylinders, boxes, balls, each by
  // index)
  // so that the first one is the one validateScene would report first.
  struct Found {
    int list;
    std::size_t index;
    ValidationError error;
  };
  std::vector<Found> found;
  const auto collect = [&found](int list, std::size_t index, ErrorList& errors) {
    for (ValidationError& error : errors.take()) found.push_back({list, index, std::move(error)});
  };
  constexpr std::size_t kAll = std::numeric_limits<std::size_t>::max();
  {
    ErrorList errors(maxErrors);
    if (!checkCounts(scene, errors)) return errors.take();
  }

  // Changed shapes against every ball.
  constexpr int kBallList = 3;
  StaticShapes changed;
  for (std::size_t i : objects.planes) {
    if (i >= scene.planes.size()) continue;
    ErrorList errors(kAll);
    if (checkPlane(scene.planes[i], i, &errors))
      changed.planes.push_back({i, planeShape(scene.planes[i])});
    collect(0, i, errors);
  }
  for (std::size_t i : objects.cylinders) {
    if (i >= scene.cylinders.size()) continue;
    ErrorList errors(kAll);
    if (checkCylinder(scene.cylinders[i], i, &errors))
      changed.cylinders.push_back({i, cylinderShape(scene.cylinders[i])});
    collect(1, i, errors);
  }
  for (std::size_t i : objects.boxes) {
    if (i >= scene.boxes.size()) continue;
    ErrorList errors(kAll);
    if (checkBox(scene.boxes[i], i, &errors))
      changed.boxes.push_back({i, boxShape(scene.boxes[i])});
    collect(2, i, errors);
  }
  const auto& balls = scene.balls;
  if (!changed.empty()) {
    for (std::size_t i = 0; i < balls.size(); ++i) {
      if (contains(objects.balls, i)) continue;  // checked in full below
      ErrorList errors(kAll);
      checkBallAgainstStatics(balls[i], i, changed, errors);
      collect(kBallList, i, errors);
    }
  }

  // Changed balls against everything. The unchanged objects are valid, so only the changed
  // shapes and balls can fail their own checks.
  StaticShapes shapes;
  for (std::size_t i = 0; i < scene.planes.size(); ++i)
    if (!contains(objects.planes, i) || checkPlane(scene.planes[i], i, nullptr))
      shapes.planes.push_back({i, planeShape(scene.planes[i])});
  for (std::size_t i = 0; i < scene.cylinders.size(); ++i)
    if (!contains(objects.cylinders, i) || checkCylinder(scene.cylinders[i], i, nullptr))
      shapes.cylinders.push_back({i, cylinderShape(scene.cylinders[i])});
  for (std::size_t i = 0; i < scene.boxes.size(); ++i)
    if (!contains(objects.boxes, i) || checkBox(scene.boxes[i], i, nullptr))
      shapes.boxes.push_back({i, boxShape(scene.boxes[i])});
  for (std::size_t i : objects.balls) {
    if (i >= balls.size()) continue;
    ErrorList errors(kAll);
    if (!checkBall(balls[i], i, &errors)) {
      collect(kBallList, i, errors);
      continue;
    }
    checkBallAgainstStatics(balls[i], i, shapes, errors);
    collect(kBallList, i, errors);
    for (std::size_t j = 0; j < balls.size(); ++j) {
      // A pair of changed balls is looked at once, from its earlier ball.
      if (j == i || (j < i && contains(objects.balls, j))) continue;
      if (contains(objects.balls, j) && !checkBall(balls[j], j, nullptr)) continue;
      const double radiusSum = balls[i].radius + balls[j].radius;
      const double depth = radiusSum - (balls[i].position - balls[j].position).norm();
      if (!overlaps(depth, radiusSum)) continue;
      // Reported on the later ball, as validateScene does.
      ErrorList pair(kAll);
      pair.add(overlapError(std::max(i, j), {ValidationSubject::Balls, std::min(i, j)}, depth));
      collect(kBallList, std::max(i, j), pair);
    }
  }

  std::stable_sort(found.begin(), found.end(), [](const Found& a, const Found& b) {
    return std::tie(a.list, a.index) < std::tie(b.list, b.index);
  });
  std::vector<ValidationError> errors;
  for (std::size_t k = 0; k < found.size() && k < maxErrors; ++k)
    errors.push_back(std::move(found[k].error));
  return errors;
}

}  // namespace carom
