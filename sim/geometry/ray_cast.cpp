#include "sim/geometry/ray_cast.h"

#include "sim/geometry/shapes.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace carom {
namespace {

// Sine of the angle below which a ray counts as parallel to a plane or a cylinder's axis. Unit
// vectors carry rounding of about 1e-16, so a ray built parallel may come out a hair off it and
// would then "meet" the shape some 1e16 lengths away; this keeps such rays from hitting at all.
constexpr double kParallel = 1e-12;

// Relative slack of the clipping test: a floor lying exactly on the box's bottom face must not be
// lost because its hit point came out 1e-16 below it.
constexpr double kClipRoundoff = 1e-9;

std::optional<Vec3> unitOf(const Vec3& v) {
  if (!v.allFinite()) return std::nullopt;
  // Stable: a direction of length 1e-200 or 1e200 is still a direction.
  const double length = v.stableNorm();
  if (!(length > 0.0)) return std::nullopt;
  return v / length;
}

struct Entry {
  double distance;  // along `unit`
  Vec3 normal;
};

// Where a ray from `offset` (relative to the centre) along `unit` enters a solid ball of
// `radius`, in as many dimensions as the vectors span: a sphere, or a cylinder's cross-section
// when everything lies in the plane across its axis. None from inside or on the surface.
std::optional<Entry> enterRound(const Vec3& offset, const Vec3& unit, double radius) {
  const double centreDistance = offset.norm();
  if (!(centreDistance > radius)) return std::nullopt;
  const double along = offset.dot(unit);
  if (!(along < 0.0)) return std::nullopt;  // heading away
  // Half the chord from the closest approach itself: the textbook b^2 - c cancels to nothing
  // when the ball is small and far away, or the ray grazes it.
  const Vec3 closest = offset - along * unit;
  const double miss = closest.norm();
  const double halfChordSquared = (radius - miss) * (radius + miss);
  if (!(halfChordSquared >= 0.0)) return std::nullopt;
  const double halfChord = std::sqrt(halfChordSquared);
  // The near root as the product of the roots over the far one, which has no -along - halfChord
  // to cancel when the origin is close to the surface.
  const double farRoot = halfChord - along;
  const double distance = (centreDistance - radius) * (centreDistance + radius) / farRoot;
  if (!(distance > 0.0) || !std::isfinite(distance)) return std::nullopt;
  // Closest approach minus the half chord, with no large terms to cancel.
  const Vec3 normal = (closest - halfChord * unit).stableNormalized();
  return Entry{distance, normal};
}

// Where a ray from `origin` along `unit` enters the solid box, by the slabs between each pair of
// opposite faces in the box's own frame: the ray is inside the box where it is inside all three
// slabs at once, so it enters at the latest of the slabs' entries. None from inside or on the
// surface, and when the ray misses.
std::optional<Entry> enterBox(const BoxShape& box, const Vec3& origin, const Vec3& unit) {
  const Vec3 local = box.toLocal(origin);
  const Vec3 along = box.axes.transpose() * unit;
  double entry = -std::numeric_limits<double>::infinity();
  double exit = std::numeric_limits<double>::infinity();
  int enteringAxis = -1;
  for (int k = 0; k < 3; ++k) {
    if (!(std::abs(along[k]) > kParallel)) {
      // Running along the slab: inside it all the way, or never.
      if (!(std::abs(local[k]) < box.half[k])) return std::nullopt;
      continue;
    }
    // The face the ray meets first is the one on the side it comes from.
    const double nearFace = along[k] > 0.0 ? -box.half[k] : box.half[k];
    const double near = (nearFace - local[k]) / along[k];
    const double far = (-nearFace - local[k]) / along[k];
    if (near > entry) {
      entry = near;
      enteringAxis = k;
    }
    exit = std::min(exit, far);
  }
  if (enteringAxis < 0 || !(entry > 0.0) || !(entry < exit) || !std::isfinite(entry))
    return std::nullopt;
  Vec3 normal = Vec3::Zero();
  normal[enteringAxis] = along[enteringAxis] > 0.0 ? -1.0 : 1.0;
  return Entry{entry, box.axes * normal};
}

// Where a ray enters a solid cylinder: its side (between the caps, for a capped one) or, for a
// capped one, a cap's disc. None from inside or on the surface, and when the ray misses.
std::optional<Entry> enterCylinder(const CylinderShape& shape, const Vec3& origin,
                                   const Vec3& unit) {
  std::optional<Entry> best;
  // In the plane across the axis the cylinder is a disc, crossed at `across` per unit of the
  // ray's length.
  const Vec3 across = shape.perpendicular(unit);
  const double acrossSpeed = across.norm();
  if (acrossSpeed > kParallel) {
    if (const std::optional<Entry> side = enterRound(shape.perpendicular(origin - shape.point),
                                                     across / acrossSpeed, shape.radius)) {
      const double distance = side->distance / acrossSpeed;
      const double along = shape.axis.dot(origin + distance * unit - shape.point);
      if (std::abs(along) <= shape.halfLength) best = Entry{distance, side->normal};
    }
  }
  if (!shape.capped()) return best;
  const double start = shape.axis.dot(origin - shape.point);
  const double axisSpeed = shape.axis.dot(unit);
  // From beyond a cap, towards it: the cap's plane crossed within the radius.
  if (std::abs(start) > shape.halfLength && axisSpeed * start < 0.0) {
    const double side = start > 0.0 ? 1.0 : -1.0;
    const double distance = (side * shape.halfLength - start) / axisSpeed;
    const Vec3 point = origin + distance * unit;
    if (shape.perpendicular(point - shape.point).norm() <= shape.radius &&
        (!best || distance < best->distance))
      best = Entry{distance, side * shape.axis};
  }
  return best;
}

class NearestHit {
 public:
  NearestHit(const Vec3& origin, const Eigen::AlignedBox3d* clip, double clipMargin)
      : origin_(origin), clip_(clip), clipMargin_(clipMargin) {}

  // True if a hit at `distance` could still be the nearest: saves the clipping test.
  bool closer(double distance) const { return distance < best_.distance; }

  // Whether the view draws `drawnPoint`, for a hit `distance` along the ray.
  bool drawn(const Vec3& drawnPoint, double distance) const {
    if (clip_ == nullptr) return true;
    const double slack = kClipRoundoff * (clip_->diagonal().norm() + origin_.norm() + distance);
    return clip_->exteriorDistance(drawnPoint) <= clipMargin_ + slack;
  }

  void offer(ShapeKind kind, std::size_t index, double distance, const Vec3& point,
             const Vec3& normal) {
    if (closer(distance)) best_ = RayHit{kind, static_cast<int>(index), distance, point, normal};
  }

  std::optional<RayHit> best() const {
    if (best_.index < 0) return std::nullopt;
    return best_;
  }

 private:
  Vec3 origin_;
  const Eigen::AlignedBox3d* clip_;
  double clipMargin_;
  RayHit best_{ShapeKind::Ball, -1, std::numeric_limits<double>::infinity(), Vec3::Zero(),
               Vec3::Zero()};
};

}  // namespace

std::optional<RayHit> castRay(const Scene& scene, const Vec3& origin, const Vec3& direction,
                              const Eigen::AlignedBox3d* clip, double clipMargin) {
  const std::optional<Vec3> unit = unitOf(direction);
  if (!unit || !origin.allFinite()) return std::nullopt;
  NearestHit nearest(origin, clip, clipMargin);

  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    const Ball& ball = scene.balls[i];
    const std::optional<Entry> entry = enterRound(origin - ball.position, *unit, ball.radius);
    if (!entry) continue;
    nearest.offer(ShapeKind::Ball, i, entry->distance, origin + entry->distance * *unit,
                  entry->normal);
  }

  for (std::size_t i = 0; i < scene.planes.size(); ++i) {
    const PlaneShape shape = planeShape(scene.planes[i]);
    // Relative to the plane's own point: n.origin - offset would cancel far from the world's
    // origin.
    const double height = shape.normal.dot(origin - scene.planes[i].point);
    const double approach = -shape.normal.dot(*unit);
    // Behind the plane the ray is inside the solid, or sees only its undrawn back.
    if (!(height > 0.0) || !(approach > kParallel)) continue;
    const double distance = height / approach;
    if (!std::isfinite(distance) || !nearest.closer(distance)) continue;
    const Vec3 point = origin + distance * *unit;
    if (!nearest.drawn(point, distance)) continue;
    nearest.offer(ShapeKind::Plane, i, distance, point, shape.normal);
  }

  for (std::size_t i = 0; i < scene.cylinders.size(); ++i) {
    const CylinderShape shape = cylinderShape(scene.cylinders[i]);
    const std::optional<Entry> entry = enterCylinder(shape, origin, *unit);
    if (!entry || !std::isfinite(entry->distance) || !nearest.closer(entry->distance)) continue;
    const Vec3 point = origin + entry->distance * *unit;
    const Vec3 axisPoint = shape.point + shape.axis.dot(point - shape.point) * shape.axis;
    // A capped cylinder is drawn whole; an infinite one only within the clip.
    if (!shape.capped() && !nearest.drawn(axisPoint, entry->distance)) continue;
    nearest.offer(ShapeKind::Cylinder, i, entry->distance, point, entry->normal);
  }

  for (std::size_t i = 0; i < scene.boxes.size(); ++i) {
    const std::optional<Entry> entry = enterBox(boxShape(scene.boxes[i]), origin, *unit);
    if (!entry || !nearest.closer(entry->distance)) continue;
    nearest.offer(ShapeKind::Box, i, entry->distance, origin + entry->distance * *unit,
                  entry->normal);
  }
  return nearest.best();
}

std::optional<double> rayPlaneDistance(const Vec3& origin, const Vec3& direction,
                                       const Vec3& planePoint, const Vec3& planeNormal) {
  const std::optional<Vec3> unit = unitOf(direction);
  const std::optional<Vec3> normal = unitOf(planeNormal);
  if (!unit || !normal) return std::nullopt;
  const double along = normal->dot(*unit);
  if (!(std::abs(along) > kParallel)) return std::nullopt;
  const double distance = normal->dot(planePoint - origin) / along;
  if (!(distance > 0.0) || !std::isfinite(distance)) return std::nullopt;
  return distance;
}

}  // namespace carom
