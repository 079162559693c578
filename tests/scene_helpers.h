#pragma once
// Small builders for the scenes of the physics tests.

#include "sim/model/scene.h"

#include <QTest>

#include <cmath>
#include <initializer_list>

namespace carom::testing {

// Under the sanitizers (scripts/sanitize.sh sets CAROM_SANITIZER_RUN) a few cases leave out what
// instrumentation makes slow or meaningless: runs of thousands of simulated seconds, margins
// between measured costs. The plain suite runs them whole.
inline bool sanitizerRun() {
  return qEnvironmentVariableIsSet("CAROM_SANITIZER_RUN");
}

// An empty elastic world under 9.81 m/s^2 downwards.
inline Scene elasticSceneWithGravity() {
  Scene s;
  s.world.gravity = Vec3(0, -9.81, 0);
  s.world.restitution = 1.0;
  return s;
}

// QTest data rows, one per method, in an int column "method".
inline void addMethodRows(std::initializer_list<Method> methods) {
  QTest::addColumn<int>("method");
  for (const Method method : methods) QTest::newRow(methodName(method).data()) << int(method);
}

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

// A closed elastic room under gravity (walls at x, z = +-1, floor and ceiling at y = 0 and 2)
// with `count` balls of radius 0.05 in a lattice, moving every which way.
inline Scene elasticGasRoom(int count, Method method) {
  Scene s = elasticSceneWithGravity();
  s.world.method = method;
  s.world.timeStep = 1.0 / 120.0;
  s.planes = {makePlane({0, 0, 0}, {0, 1, 0}),  makePlane({0, 2, 0}, {0, -1, 0}),
              makePlane({-1, 0, 0}, {1, 0, 0}), makePlane({1, 0, 0}, {-1, 0, 0}),
              makePlane({0, 0, -1}, {0, 0, 1}), makePlane({0, 0, 1}, {0, 0, -1})};
  for (int k = 0; k < count; ++k) {
    const Vec3 p(-0.8 + 0.2 * (k % 9), 0.2 + 0.2 * ((k / 9) % 9), -0.8 + 0.2 * (k / 81));
    const Vec3 v(std::sin(1.7 * k), std::cos(2.3 * k), std::sin(0.9 * k + 1.0));
    s.balls.push_back(makeBall(p, 2.0 * v, 0.05));
  }
  return s;
}

}  // namespace carom::testing
