#include "sim/exact/slide_surfaces.h"

#include "sim/core/memory_bytes.h"
#include "sim/geometry/contact_time.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace carom {

SlideSurfaces::SlideSurfaces(const Bodies& bodies, const Vec3& gravity,
                             const Vec3& pathAcceleration)
    : bodies_(bodies) {
  for (int k = 0; k < static_cast<int>(bodies.planes.size()); ++k)
    surfaces_.push_back({bodies.planes[k], {StaticKind::Plane, k}});
  for (int k = 0; k < static_cast<int>(bodies.boxes.size()); ++k) {
    const BoxShape& box = bodies.boxes[k];
    for (int axis = 0; axis < 3; ++axis)
      for (const double side : {-1.0, 1.0}) {
        const Vec3 normal = side * box.axes.col(axis);
        surfaces_.push_back(
            {{normal, normal.dot(box.center) + box.half[axis]}, {StaticKind::Box, k}, axis});
      }
  }
  firstCap_ = static_cast<int>(surfaces_.size());
  for (int k = 0; k < static_cast<int>(bodies.cylinders.size()); ++k) {
    const CylinderShape& cylinder = bodies.cylinders[k];
    for (const double side : {-1.0, 1.0}) {
      const Vec3 normal = side * cylinder.axis;
      surfaces_.push_back(
          {{normal, normal.dot(cylinder.point) + cylinder.halfLength}, {StaticKind::Cylinder, k}});
    }
  }
  for (const Surface& surface : surfaces_) {
    const Vec3& n = surface.plane.normal;
    acceleration_.push_back(pathAcceleration - pathAcceleration.dot(n) * n);
    gravity_.push_back(gravity - gravity.dot(n) * n);
  }
}

int SlideSurfaces::surfaceAt(const Vec3& position, StaticRef ref) const {
  switch (ref.kind) {
    case StaticKind::Plane:
      return ref.index;
    case StaticKind::Box:
      return boxFaceAt(position, ref.index);
    case StaticKind::Cylinder:
      return capAt(position, ref.index);
  }
  return -1;
}

int SlideSurfaces::boxFaceAt(const Vec3& position, int box) const {
  const BoxShape& shape = bodies_.boxes[box];
  const Vec3 local = shape.toLocal(position);
  const Vec3 outside = local.cwiseAbs() - shape.half;
  int axis = -1;
  for (int k = 0; k < 3; ++k) {
    if (!(outside[k] > 0.0)) continue;
    if (axis >= 0) return -1;  // beyond two faces: an edge or a corner
    axis = k;
  }
  if (axis < 0) {
    // The centre inside the box, which only a position rounded coarser than the radius gives
    // (a 4e-6 m ball 8e11 m out, whose z has an ulp of 1e-4 m): the nearest face, as
    // BoxShape::contact answers. Else the ball hopped at the rest speed across a face it could
    // not slide on, 20 times a second for 1e8 s.
    Eigen::Index nearest = 0;
    outside.maxCoeff(&nearest);
    axis = static_cast<int>(nearest);
  }
  return static_cast<int>(bodies_.planes.size()) + 6 * box + 2 * axis + (local[axis] > 0.0);
}

int SlideSurfaces::capAt(const Vec3& position, int cylinder) const {
  const CylinderShape& shape = bodies_.cylinders[cylinder];
  const Vec3 offset = position - shape.point;
  const double along = shape.axis.dot(offset);
  // The centre within the cap's disc and beyond the cap or, inside the cylinder (a position
  // rounded coarser than the radius, as in boxFaceAt), nearer the cap than the side, as
  // CylinderShape::contact answers; an infinite cylinder has none.
  const double distance = shape.perpendicular(offset).norm();
  if (!(distance < shape.radius) || !(std::abs(along) - shape.halfLength > distance - shape.radius))
    return -1;
  return firstCap_ + 2 * cylinder + (along > 0.0);
}

double SlideSurfaces::endTime(int s, const BallPath& path, double horizon) const {
  const Surface& surface = surfaces_[s];
  return surface.owner.kind == StaticKind::Box ? faceEndTime(surface, path, horizon)
                                               : capEndTime(surface, path, horizon);
}

bool SlideSurfaces::bendsIntoEnd(int s, const Motion& m, const Vec3& acceleration) const {
  const Surface& surface = surfaces_[s];
  return surface.owner.kind == StaticKind::Box ? bendsIntoEdge(surface, m, acceleration)
                                               : bendsIntoRim(surface, m, acceleration);
}

// The face's two coordinates across its plane are quadratics in time: the first to pass its
// bound.
double SlideSurfaces::faceEndTime(const Surface& face, const BallPath& path, double horizon) const {
  const BoxShape& box = bodies_.boxes[face.owner.index];
  const Vec3 x = box.toLocal(path.position);
  const Vec3 v = box.axes.transpose() * path.velocity;
  const Vec3 a = box.axes.transpose() * path.acceleration;
  double first = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    if (axis == face.axis) continue;
    for (const bool upwards : {true, false})
      first = std::min(first, boundaryCrossingTime(x[axis], v[axis], a[axis],
                                                   upwards ? box.half[axis] : -box.half[axis],
                                                   upwards, std::min(first, horizon)));
  }
  return first;
}

// The centre's offset across the axis is p + v t + a t^2 / 2 in the cap's plane: it reaches the
// rim where its length reaches the radius.
double SlideSurfaces::capEndTime(const Surface& cap, const BallPath& path, double horizon) const {
  const CylinderShape& cylinder = bodies_.cylinders[cap.owner.index];
  return circleExitTime(cylinder.perpendicular(path.position - cylinder.point),
                        cylinder.perpendicular(path.velocity),
                        0.5 * cylinder.perpendicular(path.acceleration), cylinder.radius, horizon);
}

// Across the edge (or rim) the centre is at u from the nearest point of the edge line (or rim
// circle), at the rounding's radius, and |u|^2 changes as 2 u.v t + (|v|^2 + u.a) t^2, with v and
// a across the edge: along it they do not change the distance. The slide keeps u.v at
// round-off, so the second term decides: gravity into the face bends the path into the rounding
// faster than the speed across the edge carries it out (|v|^2 < r g_n), as over the top of a peg.
bool SlideSurfaces::bendsIntoEdge(const Surface& face, const Motion& m,
                                  const Vec3& acceleration) const {
  const BoxShape& shape = bodies_.boxes[face.owner.index];
  const Vec3 local = shape.toLocal(m.position);
  // The axis it leaves the face across is the one it is nearest the end of (the other a
  // corner's); along the third the edge runs.
  const int faceAxis = face.axis, j = (faceAxis + 1) % 3, k = (faceAxis + 2) % 3;
  const int out = std::abs(local[j]) * shape.half[k] >= std::abs(local[k]) * shape.half[j] ? j : k;
  Vec3 u = Vec3::Zero();
  for (const int axis : {faceAxis, out})
    u[axis] = local[axis] - std::copysign(shape.half[axis], local[axis]);
  Vec3 v = shape.axes.transpose() * m.velocity;
  Vec3 a = shape.axes.transpose() * acceleration;
  const int along = 3 - faceAxis - out;
  v[along] = a[along] = 0.0;
  return v.squaredNorm() + u.dot(a) < 0.0;
}

// The same in the plane of the axis and the radial direction through the centre. The rim's
// curvature adds uOut (speed along the rim)^2 / R, nothing where the slide ends: there uOut is
// round-off.
bool SlideSurfaces::bendsIntoRim(const Surface& cap, const Motion& m,
                                 const Vec3& acceleration) const {
  const CylinderShape& cylinder = bodies_.cylinders[cap.owner.index];
  const Vec3& a = acceleration;
  const Vec3& n = cap.plane.normal;
  const Vec3 offset = m.position - cylinder.point;
  const Vec3 across = cylinder.perpendicular(offset);
  const double distance = across.norm();
  const Vec3 out = across / distance;
  const double uOut = distance - cylinder.radius, uUp = n.dot(offset) - cylinder.halfLength;
  const double vOut = out.dot(m.velocity), vUp = n.dot(m.velocity);
  return vOut * vOut + vUp * vUp + uOut * out.dot(a) + uUp * n.dot(a) < 0.0;
}

std::size_t SlideSurfaces::memoryBytes() const {
  return carom::memoryBytes(surfaces_) + carom::memoryBytes(acceleration_) +
         carom::memoryBytes(gravity_);
}

}  // namespace carom
