#pragma once
// Static geometry in the form the contact math wants: unit directions and precomputed offsets.

#include "sim/scene.h"

namespace carom {

struct PlaneShape {
  Vec3 normal;    // unit, towards the free side
  double offset;  // normal . point: the surface is normal . x == offset
  double gap(const Vec3& centre, double radius) const {
    return normal.dot(centre) - offset - radius;
  }
};

struct CylinderShape {
  Vec3 point;  // on the axis
  Vec3 axis;   // unit
  double radius;
  // Component of `x` perpendicular to the axis.
  Vec3 perpendicular(const Vec3& x) const { return x - axis.dot(x) * axis; }
  // Signed gap between a ball's surface and the cylinder's, and the outward normal at the ball.
  double gap(const Vec3& centre, double ballRadius) const {
    return perpendicular(centre - point).norm() - radius - ballRadius;
  }
};

inline PlaneShape planeShape(const Plane& plane) {
  const Vec3 n = plane.normal.normalized();
  return {n, n.dot(plane.point)};
}

inline CylinderShape cylinderShape(const Cylinder& cylinder) {
  return {cylinder.point, cylinder.axis.normalized(), cylinder.radius};
}

}  // namespace carom
