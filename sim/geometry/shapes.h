#pragma once
// Static geometry in the form the contact math wants: unit directions and precomputed offsets.

#include "sim/model/scene.h"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <numbers>

namespace carom {

struct PlaneShape {
  Vec3 normal;    // unit, towards the free side
  double offset;  // normal . point: the surface is normal . x == offset
  double gap(const Vec3& centre, double radius) const {
    return normal.dot(centre) - offset - radius;
  }
};

struct CylinderShape {
  Vec3 point;  // on the axis; for a capped cylinder the middle of its axis
  Vec3 axis;   // unit
  double radius;
  double halfLength = std::numeric_limits<double>::infinity();  // finite: capped
  bool capped() const { return halfLength < std::numeric_limits<double>::infinity(); }
  // Half the extent along each world axis around `point` (infinite unless capped).
  Vec3 reach() const {
    const Vec3 acrossAxis = (Vec3::Ones() - axis.cwiseProduct(axis)).cwiseMax(0.0).cwiseSqrt();
    return halfLength * axis.cwiseAbs() + radius * acrossAxis;
  }
  // Component of `x` perpendicular to the axis.
  Vec3 perpendicular(const Vec3& x) const { return x - axis.dot(x) * axis; }
  // The gap between a ball's surface and the cylinder's, and the unit normal from the cylinder's
  // surface towards the centre: from the closest point of side, cap or rim, or, for a centre
  // inside, out of the nearer of side and cap.
  struct Contact {
    Vec3 normal;
    double gap;
  };
  Contact contact(const Vec3& centre, double ballRadius) const {
    const Vec3 offset = centre - point;
    const double along = axis.dot(offset);
    const Vec3 across = offset - along * axis;
    const double distance = across.norm();
    // On the axis any direction across it will do.
    const Vec3 out = distance > 0.0 ? Vec3(across / distance) : axis.unitOrthogonal();
    const double outside = distance - radius;            // beyond the side
    const double beyond = std::abs(along) - halfLength;  // beyond the cap (-inf when infinite)
    const Vec3 capNormal = along < 0.0 ? Vec3(-axis) : axis;
    if (outside > 0.0 && beyond > 0.0) {  // nearest the rim
      const double rim = std::hypot(outside, beyond);
      return {(outside * out + beyond * capNormal) / rim, rim - ballRadius};
    }
    if (outside >= beyond) return {out, outside - ballRadius};
    return {capNormal, beyond - ballRadius};
  }
};

// A solid cuboid: its centre, its local axes (the columns of `axes`, orthonormal) and its half
// extents along them.
struct BoxShape {
  Vec3 center;
  Eigen::Matrix3d axes;
  Vec3 half;
  Vec3 toLocal(const Vec3& x) const { return axes.transpose() * (x - center); }
  // Half the extent along each world axis around the centre.
  Vec3 reach() const { return (axes * half.asDiagonal()).cwiseAbs().rowwise().sum(); }
  Vec3 closestPoint(const Vec3& x) const {
    const Vec3 local = toLocal(x);
    return center + axes * local.cwiseMax(-half).cwiseMin(half);
  }
  // The gap between a ball's surface and the box's, and the unit normal from the box's surface
  // towards the centre: from the closest point, or, for a centre inside, out of the nearest face.
  struct Contact {
    Vec3 normal;
    double gap;
  };
  Contact contact(const Vec3& centre, double ballRadius) const {
    const Vec3 local = toLocal(centre);
    const Vec3 outside = local.cwiseAbs() - half;
    if ((outside.array() > 0.0).any()) {
      const Vec3 offset = local - local.cwiseMax(-half).cwiseMin(half);
      const double distance = offset.norm();
      return {axes * (offset / distance), distance - ballRadius};
    }
    Eigen::Index face = 0;
    const double depth = outside.maxCoeff(&face);  // the least negative: the nearest face
    Vec3 n = Vec3::Zero();
    n[face] = local[face] < 0.0 ? -1.0 : 1.0;
    return {axes * n, depth - ballRadius};
  }
};

inline PlaneShape planeShape(const Plane& plane) {
  const Vec3 n = plane.normal.normalized();
  return {n, n.dot(plane.point)};
}

inline CylinderShape cylinderShape(const Cylinder& cylinder) {
  return {cylinder.point, cylinder.axis.normalized(), cylinder.radius,
          cylinder.length ? 0.5 * *cylinder.length : std::numeric_limits<double>::infinity()};
}

inline BoxShape boxShape(const Box& box) {
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  if (box.rotation)
    axes = Eigen::AngleAxisd(box.rotation->degrees * (std::numbers::pi / 180.0),
                             box.rotation->axis.normalized())
               .toRotationMatrix();
  return {box.center, axes, box.halfExtents};
}

}  // namespace carom
