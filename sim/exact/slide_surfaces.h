#pragma once
// What a ball may slide on (docs/physics.md, rule 2 of "Resting contact"): the planes (same
// indices), then the six faces of each box, by box, axis and side, then the two caps of each
// cylinder, by cylinder and side (an infinite one's are never used); what gravity and the path
// acceleration are along each; and where a slide on a face or cap ends. The engine decides who
// slides (engine_sliding.cpp); this knows only the surfaces.

#include "sim/dynamics/bodies.h"
#include "sim/exact/static_ref.h"
#include "sim/geometry/contact_time.h"
#include "sim/geometry/motion.h"

#include <cstddef>
#include <vector>

namespace carom {

class SlideSurfaces {
 public:
  struct Surface {
    PlaneShape plane;  // a cap's normal tells which cap it is
    StaticRef owner;   // the plane itself, or the box or cylinder the face or cap belongs to
    int axis = -1;     // a box face's: the box's axis across it
  };

  SlideSurfaces(const Bodies& bodies, const Vec3& gravity, const Vec3& pathAcceleration);

  const Surface& surface(int s) const { return surfaces_[s]; }
  const Vec3& acceleration(int s) const { return acceleration_[s]; }  // path acceleration along s
  const Vec3& gravity(int s) const { return gravity_[s]; }            // gravity along s
  // Whether static shape `ref` is, or holds, surface s.
  bool holds(StaticRef ref, int s) const {
    const StaticRef owner = surfaces_[s].owner;
    return ref.kind == owner.kind && ref.index == owner.index;
  }
  // The surface that a ball centred at `position` meets at a contact with `ref`: the plane, the
  // box face (away from its edges and corners) or the cap (its centre within the disc); -1 for
  // any other part.
  int surfaceAt(const Vec3& position, StaticRef ref) const;
  // When a ball on `path`, sliding on box face or cap s, reaches the face's edge or the cap's
  // rim, from the path's start; `horizon` or more when not before it.
  double endTime(int s, const BallPath& path, double horizon) const;
  // Whether a ball moving as `m` with `acceleration` at the end of a slide on box face or cap s
  // would fly into the rounding of the face's edge or the cap's rim at once.
  bool bendsIntoEnd(int s, const Motion& m, const Vec3& acceleration) const;

  std::size_t memoryBytes() const;

 private:
  int boxFaceAt(const Vec3& position, int box) const;
  int capAt(const Vec3& position, int cylinder) const;
  double faceEndTime(const Surface& face, const BallPath& path, double horizon) const;
  double capEndTime(const Surface& cap, const BallPath& path, double horizon) const;
  bool bendsIntoEdge(const Surface& face, const Motion& m, const Vec3& acceleration) const;
  bool bendsIntoRim(const Surface& cap, const Motion& m, const Vec3& acceleration) const;

  const Bodies& bodies_;
  std::vector<Surface> surfaces_;
  int firstCap_ = 0;  // the first cap's index in surfaces_
  std::vector<Vec3> acceleration_;
  std::vector<Vec3> gravity_;
};

}  // namespace carom
