#include "ui/editor/standing.h"

#include "sim/geometry/shapes.h"
#include "ui/editor/object_kinds.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace carom::editor {
namespace {

// Touching, relative to the size of the numbers involved: placing leaves round-off between an
// object and its surface, a hand-written scene perhaps a little more.
constexpr double kTouching = 1e-6;
// 1 - cosine under which a normal counts as along a cylinder's axis.
constexpr double kAlong = 1e-9;

double touching(double scale) {
  return kTouching * (1.0 + std::abs(scale));
}

// A flat surface of the scene: a plane, or the face of `box` on its own axis `axis`.
struct Flat {
  Surface surface;
  std::optional<BoxShape> box;
  int axis = 0;
};

std::vector<Flat> flatsOf(const Scene& scene, const Selection& ignored) {
  const auto kept = [&](ObjectKind kind, std::size_t index) {
    return std::find(ignored.begin(), ignored.end(), ObjectRef{kind, int(index)}) == ignored.end();
  };
  std::vector<Flat> flats;
  for (std::size_t i = 0; i < scene.planes.size(); ++i)
    if (kept(ObjectKind::Plane, i))
      flats.push_back({{scene.planes[i].point, scene.planes[i].normal.normalized()}, {}, 0});
  for (std::size_t i = 0; i < scene.boxes.size(); ++i) {
    if (!kept(ObjectKind::Box, i)) continue;
    const BoxShape shape = boxShape(scene.boxes[i]);
    for (int k = 0; k < 3; ++k)
      for (const int side : {1, -1}) {
        const Vec3 normal = side * shape.axes.col(k);
        flats.push_back({{shape.center + shape.half[k] * normal, normal}, shape, k});
      }
  }
  return flats;
}

// Whether `x` seen along the flat's normal lies on it: always for a plane, within the face for
// a box's.
bool over(const Flat& flat, const Vec3& x) {
  if (!flat.box) return true;
  const Vec3 local = flat.box->toLocal(x);
  for (int k = 0; k < 3; ++k)
    if (k != flat.axis && std::abs(local[k]) > flat.box->half[k] + touching(flat.box->half[k]))
      return false;
  return true;
}

constexpr double kUnbounded = -std::numeric_limits<double>::infinity();

// The least of x · direction over the object's points (-infinity for one without an end that
// way).
double lowestAlong(const Ball& ball, const Vec3& direction) {
  return ball.position.dot(direction) - ball.radius;
}

double lowestAlong(const Plane&, const Vec3&) {
  return kUnbounded;
}

double lowestAlong(const Cylinder& cylinder, const Vec3& direction) {
  const double along = cylinder.axis.normalized().dot(direction);
  const double across = cylinder.radius * std::sqrt(std::max(0.0, 1.0 - along * along));
  if (!cylinder.length)
    return std::abs(along) < 1e-12 ? cylinder.point.dot(direction) - across : kUnbounded;
  return cylinder.point.dot(direction) - 0.5 * *cylinder.length * std::abs(along) - across;
}

double lowestAlong(const Box& box, const Vec3& direction) {
  const BoxShape shape = boxShape(box);
  return shape.center.dot(direction) -
         shape.half.dot((shape.axes.transpose() * direction).cwiseAbs());
}

double lowestAlong(const Scene& scene, const ObjectRef& ref, const Vec3& direction) {
  return visitObjects(scene, ref.kind, [&](const auto& objects) {
    return lowestAlong(objects[ref.index], direction);
  });
}

}  // namespace

std::vector<Surface> surfacesUnder(const Scene& scene, const ObjectRef& ref,
                                   const Selection& ignored) {
  const Vec3 centre = objectPosition(scene, ref);
  std::vector<Surface> under;
  for (const Flat& flat : flatsOf(scene, ignored)) {
    const Surface& surface = flat.surface;
    const double lowest = lowestAlong(scene, ref, surface.normal);
    const double level = surface.point.dot(surface.normal);
    if (std::abs(lowest - level) <= touching(std::max(std::abs(level), std::abs(lowest))) &&
        over(flat, centre))
      under.push_back(surface);
  }
  return under;
}

Cylinder withLength(const Scene& scene, const Cylinder& cylinder, std::optional<double> length) {
  Cylinder result = cylinder;
  result.length = length;
  const Vec3 axis = cylinder.axis.normalized();
  // Where it may stand, each with the way from there into the cylinder: a capped one's caps;
  // an infinite one rises from its point on either side, so the surface says which.
  struct Foot {
    Vec3 point;
    Vec3 inward;
  };
  for (const Flat& flat : flatsOf(scene, {})) {
    const Surface& surface = flat.surface;
    if (std::abs(surface.normal.dot(axis)) < 1.0 - kAlong) continue;
    std::vector<Foot> feet{{cylinder.point, surface.normal}};
    if (cylinder.length) {
      const double half = 0.5 * *cylinder.length;
      feet = {{cylinder.point - half * axis, axis}, {cylinder.point + half * axis, -axis}};
    }
    for (const Foot& foot : feet) {
      const double height = (foot.point - surface.point).dot(surface.normal);
      if (foot.inward.dot(surface.normal) <= 0.0 ||
          std::abs(height) > touching(foot.point.norm()) || !over(flat, foot.point))
        continue;
      result.point = foot.point + 0.5 * length.value_or(0.0) * foot.inward;
      return result;
    }
  }
  return result;
}

}  // namespace carom::editor
