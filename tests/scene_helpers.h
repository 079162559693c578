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

}  // namespace carom::testing
