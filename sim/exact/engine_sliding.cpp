// EventEngine's sliding (docs/physics.md, rule 2 of "Resting contact"): a ball in lasting contact
// with a plane, a box's face or a capped cylinder's cap, or with the crease of such a surface and
// a plane, follows gravity's component along it on an exact path, until it leaves the face's
// edge or the cap's rim.

#include "sim/exact/event_engine.h"

#include "sim/core/tolerances.h"
#include "sim/dynamics/response.h"
#include "sim/geometry/contact_time.h"

#include <Eigen/Geometry>  // cross products

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

namespace carom {

// A slow contact with a pressing plane becomes a slide on it, or, when the ball also touches one
// other plane that it moves into or that gravity along the first presses it against, a slide
// along the crease line of the two. Only when what the capture takes (the velocity across the
// crease) is no faster than the slide speed: at the bottom of a narrow V a ball falling at
// metres a second meets each wall at a grazing angle, and reflections (leaveTouchingStatics)
// keep its speed where projecting it onto one wall after the other took all of it. A ball
// touching a cylinder or two more planes bounces instead.
int EventEngine::slideCapture(int i, int plane) const {
  const Particle& p = particles_[i];
  const Vec3& v = tracks_[i].motion.velocity;
  const Vec3& n = slideSurfaces_[plane].plane.normal;
  const double touching = tolerance::kTouchFraction * bodies_.radius[i];
  int other = kAlone;
  for (int s = p.staticBegin; s < p.staticEnd; ++s) {
    const StaticRef ref = statics_[s];
    if (holdsSurface(ref, plane)) continue;
    const StaticContact contact = staticContact(i, ref);
    if (contact.gap > touching) continue;
    // A wall the ball only touches, neither moving into it nor pressed against it, leaves the
    // slide alone (a ball sliding along a floor beside a wall).
    if (v.dot(contact.normal) >= 0.0 && slideGravity_[plane].dot(contact.normal) >= 0.0) continue;
    if (ref.kind != StaticKind::Plane || other != kAlone) return kNoCapture;
    other = ref.index;
  }
  if (other == kAlone) return kAlone;
  const Vec3 line = n.cross(bodies_.planes[other].normal);
  if (line.norm() <= tolerance::kTouchFraction) return kNoCapture;  // parallel planes
  const Vec3 t = line.normalized();
  const Vec3 onPlane = v - v.dot(n) * n;
  const bool slow = (onPlane - onPlane.dot(t) * t).norm() <= slideSpeed_[i];
  return slow && slideGravity_[plane].dot(bodies_.planes[other].normal) < 0.0 ? other : kNoCapture;
}

void EventEngine::startCrease(int i, int plane) {
  Particle& p = particles_[i];
  p.creasePlane = plane;
  const Vec3 t = slideSurfaces_[p.slidePlane]
                     .plane.normal.cross(slideSurfaces_[plane].plane.normal)
                     .normalized();
  creaseLine_[i] = t;
  creaseAcceleration_[i] = pathAcceleration_.dot(t) * t;
  keepOnPlane(i);
  changed(i);
}

void EventEngine::dropPlanesLeft(int i) {
  Particle& p = particles_[i];
  const Vec3& v = tracks_[i].motion.velocity;
  if (p.creasePlane >= 0 && v.dot(slideSurfaces_[p.creasePlane].plane.normal) > slideSpeed_[i])
    p.creasePlane = -1;
  if (p.slidePlane >= 0 && v.dot(slideSurfaces_[p.slidePlane].plane.normal) > slideSpeed_[i]) {
    p.slidePlane = p.creasePlane;
    p.creasePlane = -1;
  }
}

void EventEngine::startSliding(int i, int plane) {
  particles_[i].slidePlane = plane;
  particles_[i].creasePlane = -1;
  keepOnPlane(i);
  changed(i);
}

void EventEngine::updateSlide(int i, RunStats& stats) {
  Particle& p = particles_[i];
  if (p.slidePlane < 0) return;
  Motion& m = tracks_[i].motion;
  // Pushed into its plane(s) by another contact at this instant: they answer as contacts, in
  // turn while it still moves into one (a crease), as leaveTouchingStatics does.
  struct Surface {
    Vec3 normal;
    double restitution;
    ContactKind kind;  // a plane's, a box face's or a cap's
  };
  Surface planes[2];
  std::size_t count = 0;
  for (const int k : {p.slidePlane, p.creasePlane}) {
    if (k < 0) continue;
    const StaticRef owner = slideSurfaces_[k].owner;
    planes[count++] = {slideSurfaces_[k].plane.normal, restitutionWith(i, owner),
                       contactKindOf(owner.kind)};
    noteRestitution(planes[count - 1].restitution);
  }
  reflectOffEach(m.velocity, std::span<const Surface>(planes, count),
                 tolerance::kMaxSimultaneousReflections,
                 [&](std::size_t k, double) { stats.collisions.add(planes[k].kind); });
  dropPlanesLeft(i);
  keepOnPlane(i);
  changed(i);
}

void EventEngine::keepOnPlane(int i) {
  const Particle& p = particles_[i];
  if (p.slidePlane < 0) return;
  const PlaneShape& plane = slideSurfaces_[p.slidePlane].plane;
  Motion& m = tracks_[i].motion;
  const double r = bodies_.radius[i];
  // The corrections are round-off, but they would build up over a long slide: the normal speed
  // left is below a bounce of touching height (slideSpeed_), a lost energy of that order.
  if (p.creasePlane < 0) {
    m.position -= plane.gap(m.position, r) * plane.normal;
    m.velocity -= m.velocity.dot(plane.normal) * plane.normal;
    return;
  }
  // On the crease line: the move in the span of both normals that closes both gaps.
  const PlaneShape& other = slideSurfaces_[p.creasePlane].plane;
  const double c = plane.normal.dot(other.normal);
  const double gap = plane.gap(m.position, r), otherGap = other.gap(m.position, r);
  const double denominator = 1.0 - c * c;
  m.position += ((-gap + c * otherGap) / denominator) * plane.normal +
                ((-otherGap + c * gap) / denominator) * other.normal;
  m.velocity = m.velocity.dot(creaseLine_[i]) * creaseLine_[i];
}

int EventEngine::surfaceAt(int i, StaticRef ref) const {
  switch (ref.kind) {
    case StaticKind::Plane:
      return ref.index;
    case StaticKind::Box:
      return boxFaceAt(i, ref.index);
    case StaticKind::Cylinder:
      return capAt(i, ref.index);
  }
  return -1;
}

int EventEngine::boxFaceAt(int i, int box) const {
  const BoxShape& shape = bodies_.boxes[box];
  const Vec3 local = shape.toLocal(tracks_[i].motion.position);
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

int EventEngine::capAt(int i, int cylinder) const {
  const CylinderShape& shape = bodies_.cylinders[cylinder];
  const Vec3 offset = tracks_[i].motion.position - shape.point;
  const double along = shape.axis.dot(offset);
  // The centre within the cap's disc and beyond the cap or, inside the cylinder (a position
  // rounded coarser than the radius, as in boxFaceAt), nearer the cap than the side, as
  // CylinderShape::contact answers; an infinite cylinder has none.
  const double distance = shape.perpendicular(offset).norm();
  if (!(distance < shape.radius) || !(std::abs(along) - shape.halfLength > distance - shape.radius))
    return -1;
  return firstCap_ + 2 * cylinder + (along > 0.0);
}

void EventEngine::findSlideEnd(int i, const BallPath& path) {
  const int surface = particles_[i].slidePlane;
  const SlideSurface& s = slideSurfaces_[surface];
  Contact& best = predictions_[i].contact;
  const double horizon = std::min(best.time, horizon_) - now_;
  const double t = s.owner.kind == StaticKind::Box ? faceEndTime(s, path, horizon)
                                                   : capEndTime(s, path, horizon);
  if (t < horizon) best = {now_ + t, EventKind::SlideEnd, surface, 0};
}

// The face's two coordinates across its plane are quadratics in time: the first to pass its
// bound.
double EventEngine::faceEndTime(const SlideSurface& face, const BallPath& path,
                                double horizon) const {
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
double EventEngine::capEndTime(const SlideSurface& cap, const BallPath& path,
                               double horizon) const {
  const CylinderShape& cylinder = bodies_.cylinders[cap.owner.index];
  return circleExitTime(cylinder.perpendicular(path.position - cylinder.point),
                        cylinder.perpendicular(path.velocity),
                        0.5 * cylinder.perpendicular(path.acceleration), cylinder.radius, horizon);
}

void EventEngine::endSlide(int i, RunStats& stats, std::vector<CollisionRecord>* log) {
  // Past the edge or rim the ball flies, and meets the shape, if at all, as a contact; one too
  // slow to clear the rounding there meets it at once, with no face to slide on.
  const SlideSurface& surface = slideSurfaces_[particles_[i].slidePlane];
  moveTo(i, now_);
  particles_[i].slidePlane = particles_[i].creasePlane = -1;
  changed(i);
  const bool bends =
      surface.owner.kind == StaticKind::Box ? bendsIntoEdge(i, surface) : bendsIntoRim(i, surface);
  if (bends) {
    collideWithStatic(i, surface.owner, -1, stats, log);
    return;
  }
  predict(i);
}

// Across the edge (or rim) the centre is at u from the nearest point of the edge line (or rim
// circle), at the rounding's radius, and |u|^2 changes as 2 u.v t + (|v|^2 + u.a) t^2, with v and
// a across the edge: along it they do not change the distance. The slide keeps u.v at
// round-off, so the second term decides: gravity into the face bends the path into the rounding
// faster than the speed across the edge carries it out (|v|^2 < r g_n), as over the top of a peg.
bool EventEngine::bendsIntoEdge(int i, const SlideSurface& face) const {
  const BoxShape& shape = bodies_.boxes[face.owner.index];
  const Motion& m = tracks_[i].motion;
  const Vec3 local = shape.toLocal(m.position);
  // The axis it leaves the face across is the one it is nearest the end of (the other a
  // corner's); along the third the edge runs.
  const int faceAxis = face.axis, j = (faceAxis + 1) % 3, k = (faceAxis + 2) % 3;
  const int out = std::abs(local[j]) * shape.half[k] >= std::abs(local[k]) * shape.half[j] ? j : k;
  Vec3 u = Vec3::Zero();
  for (const int axis : {faceAxis, out})
    u[axis] = local[axis] - std::copysign(shape.half[axis], local[axis]);
  Vec3 v = shape.axes.transpose() * m.velocity;
  Vec3 a = shape.axes.transpose() * accelerationOf(i);
  const int along = 3 - faceAxis - out;
  v[along] = a[along] = 0.0;
  return v.squaredNorm() + u.dot(a) < 0.0;
}

// The same in the plane of the axis and the radial direction through the centre. The rim's
// curvature adds uOut (speed along the rim)^2 / R, nothing where the slide ends: there uOut is
// round-off.
bool EventEngine::bendsIntoRim(int i, const SlideSurface& cap) const {
  const CylinderShape& cylinder = bodies_.cylinders[cap.owner.index];
  const Motion& m = tracks_[i].motion;
  const Vec3& a = accelerationOf(i);
  const Vec3& n = cap.plane.normal;
  const Vec3 offset = m.position - cylinder.point;
  const Vec3 across = cylinder.perpendicular(offset);
  const double distance = across.norm();
  const Vec3 out = across / distance;
  const double uOut = distance - cylinder.radius, uUp = n.dot(offset) - cylinder.halfLength;
  const double vOut = out.dot(m.velocity), vUp = n.dot(m.velocity);
  return vOut * vOut + vUp * vUp + uOut * out.dot(a) + uUp * n.dot(a) < 0.0;
}

}  // namespace carom
