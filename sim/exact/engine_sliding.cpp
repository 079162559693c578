// EventEngine's sliding (docs/physics.md, rule 2 of "Resting contact"): a ball in lasting contact
// with a plane, a box's face or a capped cylinder's cap, or with the crease of such a surface and
// a plane, follows gravity's component along it on an exact path, until it leaves the face's
// edge or the cap's rim (the surfaces themselves are SlideSurfaces').
//
// With friction (roughFaces_), a ball on a face is in one of the phases of face_friction.h
// (sliding with slip, rolling, still), each ending at its exact time (PhaseEnd), beside the
// frictionless slide that they extend; a ball in a crease still slides without friction.

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
  const Vec3& v = tracks_[i].motion.velocity;
  const Vec3& n = slides_.surface(plane).plane.normal;
  const double touching = tolerance::kTouchFraction * bodies_.radius[i];
  int other = kAlone;
  for (const StaticRef ref : cells_.staticsNear(i)) {
    if (slides_.holds(ref, plane)) continue;
    const StaticContact contact = staticContact(i, ref);
    if (contact.gap > touching) continue;
    // A wall the ball only touches, neither moving into it nor pressed against it, leaves the
    // slide alone (a ball sliding along a floor beside a wall).
    if (v.dot(contact.normal) >= 0.0 && slides_.gravity(plane).dot(contact.normal) >= 0.0) continue;
    if (ref.kind != StaticKind::Plane || other != kAlone) return kNoCapture;
    other = ref.index;
  }
  if (other == kAlone) return kAlone;
  const Vec3 line = n.cross(bodies_.planes[other].normal);
  if (line.norm() <= tolerance::kTouchFraction) return kNoCapture;  // parallel planes
  const Vec3 t = line.normalized();
  const Vec3 onPlane = v - v.dot(n) * n;
  const bool slow = (onPlane - onPlane.dot(t) * t).norm() <= slideSpeed_[i];
  return slow && slides_.gravity(plane).dot(bodies_.planes[other].normal) < 0.0 ? other
                                                                                : kNoCapture;
}

void EventEngine::startCrease(int i, int plane) {
  Particle& p = particles_[i];
  p.creasePlane = plane;
  const Vec3 t = slides_.surface(p.slidePlane)
                     .plane.normal.cross(slides_.surface(plane).plane.normal)
                     .normalized();
  creaseLine_[i] = t;
  creaseAcceleration_[i] = pathAcceleration_.dot(t) * t;
  keepOnPlane(i);
  changed(i);
}

void EventEngine::dropPlanesLeft(int i) {
  Particle& p = particles_[i];
  const Vec3& v = tracks_[i].motion.velocity;
  if (p.creasePlane >= 0 && v.dot(slides_.surface(p.creasePlane).plane.normal) > slideSpeed_[i])
    p.creasePlane = -1;
  if (p.slidePlane >= 0 && v.dot(slides_.surface(p.slidePlane).plane.normal) > slideSpeed_[i]) {
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
    const StaticRef owner = slides_.surface(k).owner;
    planes[count++] = {slides_.surface(k).plane.normal, restitutionWith(i, owner),
                       contactKindOf(owner.kind)};
    books_.noteRestitution(planes[count - 1].restitution);
  }
  reflectOffEach(m.velocity, std::span<const Surface>(planes, count),
                 tolerance::kMaxSimultaneousReflections,
                 [&](std::size_t k, double, std::uint64_t times) {
                   stats.collisions.add(planes[k].kind, times);
                 });
  dropPlanesLeft(i);
  keepOnPlane(i);
  changed(i);
  refreshFace(i, stats);
}

void EventEngine::refreshFace(int i, RunStats& stats) {
  if (!roughFaces_) return;
  FaceContact& face = faces_[i];
  const Particle& p = particles_[i];
  // A crease with friction is not modelled yet: the ball slides along it without (issue notes).
  if (p.slidePlane < 0 || p.creasePlane >= 0 || p.resting || p.held) {
    face = {};
    return;
  }
  const SlideSurfaces::Surface& surface = slides_.surface(p.slidePlane);
  const Vec3& n = surface.plane.normal;
  const double r = bodies_.radius[i];
  const FaceFrame frame = FaceFrame::of(n, gravity_);
  const ContactFriction friction = bodies_.contactFriction(i, shapeFriction(surface.owner));
  Motion& m = tracks_[i].motion;
  face.motion = faceMotion(m.velocity, spin_[i], r, frame, friction);
  face.normal = n;
  face.normalDecay = spinDecayRate(frame, friction, r);
  if (face.motion.turning) {
    TurningFace& turning = turningFaces_[i];
    turning.path.emplace(m.velocity, spin_[i], r, frame, friction, face.motion.phase);
    turning.from = m.position;
    turning.since = now_;
    // No finer than the position's round-off, which no contact time resolves either (a ball of
    // 1e-12 m took a segment every 1e-7 s).
    const double roundOff =
        4.0 * std::numeric_limits<double>::epsilon() * m.position.cwiseAbs().maxCoeff();
    // Nor shorter than the clock resolves (one tick, where the parabola parts from the path by
    // at most μ·g_n·π·tick²/8): no event time tells a shorter one from none.
    const double tick = std::nextafter(now_, std::numeric_limits<double>::infinity()) - now_;
    const TurningFacePath::Segment segment =
        turning.path->segment(std::max(tolerance::kTurningPathDeviation * r, roundOff), tick);
    face.motion.acceleration = segment.acceleration;
    face.motion.angularAcceleration = segment.angularAcceleration;
    face.motion.duration = segment.duration;
  }
  face.end = now_ + face.motion.duration;
  // Rolling is exactly that: the slip's round-off goes.
  if (face.motion.phase == FacePhase::Rolling)
    spin_[i] = spin_[i].dot(n) * n + rollingSpin(m.velocity, n, r);
  changed(i);
  if (face.motion.phase == FacePhase::Still) putToRest(i, stats);
}

void EventEngine::restOnFace(int i) {
  // Resting takes the rolling with the motion. On a face the spin about its normal stays, and
  // spinning friction takes it down; off any, friction holds the ball and its spin goes.
  FaceContact& face = faces_[i];
  const Particle& p = particles_[i];
  face = {};
  face.motion.phase = FacePhase::Still;
  if (p.slidePlane < 0 || p.creasePlane >= 0) {
    spin_[i].setZero();
    return;
  }
  const SlideSurfaces::Surface& surface = slides_.surface(p.slidePlane);
  const double r = bodies_.radius[i];
  face.normal = surface.plane.normal;
  face.normalDecay = spinDecayRate(FaceFrame::of(face.normal, gravity_),
                                   bodies_.contactFriction(i, shapeFriction(surface.owner)), r);
  spin_[i] = spin_[i].dot(face.normal) * face.normal;
}

void EventEngine::findPhaseEnd(int i) {
  const Particle& p = particles_[i];
  if (p.slidePlane < 0 || p.creasePlane >= 0 || p.resting) return;
  Contact& best = predictions_[i].contact;
  const double end = faces_[i].end;
  if (end < best.time && end <= horizon_) best = {end, EventKind::PhaseEnd, i, 0};
}

void EventEngine::endPhase(int i, RunStats& stats) {
  moveTo(i, now_);
  const FaceContact& face = faces_[i];
  // A turning phase ends a segment, and only at its last one the phase itself.
  if (!face.motion.turning || face.motion.duration == turningFaces_[i].path->end()) {
    Motion& m = tracks_[i].motion;
    const Vec3& n = face.normal;
    // What the closed form says happens now: the slip is zero, or the roll stopped.
    if (face.motion.phase == FacePhase::Sliding)
      spin_[i] = spin_[i].dot(n) * n + rollingSpin(m.velocity, n, bodies_.radius[i]);
    else if (face.motion.phase == FacePhase::Rolling) {
      m.velocity.setZero();
      spin_[i] = spin_[i].dot(n) * n;
    }
  }
  ++stats.facePhases;
  refreshFace(i, stats);
  if (!particles_[i].resting) predict(i);
}

void EventEngine::keepOnPlane(int i) {
  const Particle& p = particles_[i];
  if (p.slidePlane < 0) return;
  const PlaneShape& plane = slides_.surface(p.slidePlane).plane;
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
  const PlaneShape& other = slides_.surface(p.creasePlane).plane;
  const double c = plane.normal.dot(other.normal);
  const double gap = plane.gap(m.position, r), otherGap = other.gap(m.position, r);
  const double denominator = 1.0 - c * c;
  m.position += ((-gap + c * otherGap) / denominator) * plane.normal +
                ((-otherGap + c * gap) / denominator) * other.normal;
  m.velocity = m.velocity.dot(creaseLine_[i]) * creaseLine_[i];
}

void EventEngine::findSlideEnd(int i, const BallPath& path) {
  const int surface = particles_[i].slidePlane;
  Contact& best = predictions_[i].contact;
  const double horizon = std::min(best.time, horizon_) - now_;
  const double t = slides_.endTime(surface, path, horizon);
  if (t < horizon) best = {now_ + t, EventKind::SlideEnd, surface, 0};
}

void EventEngine::endSlide(int i, RunStats& stats, std::vector<CollisionRecord>* log) {
  // Past the edge or rim the ball flies, and meets the shape, if at all, as a contact; one too
  // slow to clear the rounding there meets it at once, with no face to slide on.
  const int surface = particles_[i].slidePlane;
  moveTo(i, now_);
  particles_[i].slidePlane = particles_[i].creasePlane = -1;
  changed(i);
  refreshFace(i, stats);
  if (slides_.bendsIntoEnd(surface, tracks_[i].motion, accelerationOf(i))) {
    collideWithStatic(i, slides_.surface(surface).owner, -1, stats, log);
    return;
  }
  predict(i);
}

}  // namespace carom
