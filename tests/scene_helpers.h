#pragma once
// Small builders for the scenes of the physics tests.

#include "sim/scene.h"

namespace carom::testing {

inline Ball makeBall(const Vec3& position, const Vec3& velocity, double radius = 0.1,
                     double mass = 1.0) {
  Ball ball;
  ball.position = position;
  ball.velocity = velocity;
  ball.radius = radius;
  ball.mass = mass;
  return ball;
}

inline Plane makePlane(const Vec3& point, const Vec3& normal) {
  Plane plane;
  plane.point = point;
  plane.normal = normal;
  return plane;
}

inline Box makeBox(const Vec3& center, const Vec3& half, std::optional<Rotation> rotation = {}) {
  Box box;
  box.center = center;
  box.halfExtents = half;
  box.rotation = rotation;
  return box;
}

// Infinite without a length.
inline Cylinder makeCylinder(const Vec3& point, const Vec3& axis, double radius,
                             std::optional<double> length = {}) {
  Cylinder cylinder;
  cylinder.point = point;
  cylinder.axis = axis;
  cylinder.radius = radius;
  cylinder.length = length;
  return cylinder;
}

}  // namespace carom::testing
