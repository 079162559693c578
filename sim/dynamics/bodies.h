#pragma once
// What stays fixed during a run: the static shapes and each ball's size, mass and restitution,
// resolved once against the world so the steppers need not look at the scene again.

#include "sim/geometry/shapes.h"

#include <optional>
#include <vector>

namespace carom {

struct Bodies {
  std::vector<PlaneShape> planes;
  std::vector<double> planeRestitution;
  std::vector<CylinderShape> cylinders;
  std::vector<double> cylinderRestitution;
  std::vector<BoxShape> boxes;
  std::vector<double> boxRestitution;
  std::vector<double> radius;
  std::vector<double> mass;
  std::vector<double> inverseMass;
  std::vector<double> restitution;  // each ball's own value, or the world's
  double maxRadius = 0.0;
  // The objects' own values (none: the world's), kept to resolve the world's again.
  std::vector<std::optional<double>> planeOwnRestitution;
  std::vector<std::optional<double>> cylinderOwnRestitution;
  std::vector<std::optional<double>> boxOwnRestitution;
  std::vector<std::optional<double>> ownRestitution;

  int ballCount() const { return static_cast<int>(radius.size()); }
  // Every object without a value of its own takes `worldRestitution` from now on.
  void setWorldRestitution(double worldRestitution);
};

Bodies makeBodies(const Scene& scene);

// The state that moves: what steppers hand over to each other when the method changes.
struct BallState {
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  bool resting = false;  // put to rest by the rest policy: immovable until hit hard enough
};

}  // namespace carom
