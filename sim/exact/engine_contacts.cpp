// EventEngine's contacts: what a contact predicted and now due does to the balls, a ball with a
// static shape or two balls, with the rest policy's floors (rest_policy.h) and the burst guard.

#include "sim/core/tolerances.h"
#include "sim/dynamics/response.h"
#include "sim/dynamics/rest_policy.h"
#include "sim/exact/event_engine.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace carom {

void EventEngine::collideWithStatic(int i, StaticRef ref, int face, RunStats& stats,
                                    std::vector<CollisionRecord>* log) {
  books_.restore(i, tracks_[i].motion);
  const Motion& m = tracks_[i].motion;
  const double r = bodies_.radius[i];
  const auto [n, gap, restitution] = staticContact(i, ref);
  notePenetration(-gap, stats);
  const double approach = -m.velocity.dot(n);
  books_.noteRestitution(restitution);
  collideWithSurface(i, n, restitution, stats, face, impactFrictionWith(i, ref));
  if (!particles_[i].resting) {
    leaveTouchingStatics(i, stats);
    updateSlide(i, stats);
  }
  const ContactKind kind = contactKindOf(ref.kind);
  stats.collisions.add(kind);
  if (log) log->push_back({now_, kind, i, ref.index, m.position - r * n, approach});
  books_.close(i, 0.0, tracks_[i].motion);
  if (!particles_[i].resting) predict(i);
}

void EventEngine::collideBalls(int i, int j, RunStats& stats, std::vector<CollisionRecord>* log) {
  Particle& a = particles_[i];
  Particle& b = particles_[j];
  moveTo(i, now_);
  moveTo(j, now_);
  if (!a.resting) books_.restore(i, tracks_[i].motion);
  if (!b.resting) books_.restore(j, tracks_[j].motion);
  Motion& ma = tracks_[i].motion;
  Motion& mb = tracks_[j].motion;
  Vec3 n = mb.position - ma.position;
  const double distance = n.norm();
  const double radiusSum = bodies_.radius[i] + bodies_.radius[j];
  notePenetration(radiusSum - distance, stats);
  n = pairNormal(n, distance, ma.velocity - mb.velocity);  // centres that coincide: head-on
  const double approach = (ma.velocity - mb.velocity).dot(n);
  const double restitution = std::min(bodies_.restitution[i], bodies_.restitution[j]);
  books_.noteRestitution(restitution);
  // The contact was predicted, so it is resolved even when round-off makes the approach look
  // zero or negative here: the minimum separation then parts the pair, and the same contact
  // cannot be predicted again at this instant.
  // Too gentle to move a resting ball: it acts as an immovable surface, unless ball i would rest
  // on it and it cannot carry i (restCheck), when it wakes first.
  bool answered = false;
  double exchangedI = 0.0, exchangedJ = 0.0;
  if (b.resting && approach < tolerance::kSettleSpeedFactor * restSpeed_[i]) {
    answered = restsOnContact(i, -n, restitution, stats);
    if (!answered && b.resting) {
      bounceOffSurface(i, -n, restitution, stats, -1,
                       bodies_.rough ? bodies_.impactFriction(i, j) : ImpactFriction{});
      if (!a.resting) updateSlide(i, stats);
      answered = true;
    }
  }
  if (!answered) {
    if (b.resting) wake(j, stats);
    // A pair that gravity presses together (a falling ball on a sliding one) separates at no
    // less than the rest speed, as a ball on a floor would (rule 1 of rest_policy.h). Only an
    // inelastic pair can collapse: an elastic one parts at the slide speed, which it needs only
    // when it meets at no speed (balls placed touching, a frictionless pyramid).
    const auto [minimum, lossless] = pairFloor(i, j, n, restitution);
    // What the exchange alone gives each ball, without the minimum separation: the energy an
    // elastic pair's books keep (EnergyBooks::close).
    Vec3 exchangedA = ma.velocity, exchangedB = mb.velocity;
    resolveBallBall(exchangedA, exchangedB, bodies_.inverseMass[i], bodies_.inverseMass[j], n,
                    restitution, 0.0);
    exchangedI = 0.5 * (exchangedA.squaredNorm() - ma.velocity.squaredNorm());
    exchangedJ = 0.5 * (exchangedB.squaredNorm() - mb.velocity.squaredNorm());
    resolveBallBall(ma.velocity, mb.velocity, bodies_.inverseMass[i], bodies_.inverseMass[j], n,
                    restitution, minimum, lossless);
    if (bodies_.rough) {
      const ImpactFriction law = bodies_.impactFriction(i, j);
      if (law.friction > 0.0) {
        const double separation = (mb.velocity - ma.velocity).dot(n);
        applyImpactFriction(ma.velocity, spin_[i], mb.velocity, spin_[j], bodies_.radius[i],
                            bodies_.radius[j], bodies_.inverseMass[i], bodies_.inverseMass[j], n,
                            approach + separation, law);
        books_.noteFriction();
      }
    }
    changed(i);
    changed(j);
    updateSlide(i, stats);
    updateSlide(j, stats);
  }
  ++stats.collisions.ballBall;
  if (log)
    log->push_back(
        {now_, ContactKind::BallBall, i, j, ma.position + bodies_.radius[i] * n, approach});
  books_.close(i, exchangedI, tracks_[i].motion);
  // A resting ball that answered as a surface took no part.
  if (!answered) books_.close(j, exchangedJ, tracks_[j].motion);
  if (!a.resting) predict(i);
  if (!b.resting) predict(j);
}

EventEngine::PairFloor EventEngine::pairFloor(int i, int j, const Vec3& n,
                                              double restitution) const {
  const bool pressed = (gravityOn(j) - gravityOn(i)).dot(n) < 0.0;
  const double separation = restitution >= 1.0 ? std::min(slideSpeed_[i], slideSpeed_[j])
                                               : std::min(restSpeed_[i], restSpeed_[j]);
  // Parting slower than round-off in the balls' own velocities parts nothing (kTangentRateFraction
  // of the speed, and of the pair's relative speed at most half that): the contact came again
  // at the same instant, for ever. The collapse speed is the scene's, and a light pair far
  // faster than its heavy balls (1e11 m/s against 20) took 1e-6 m/s, less than an ulp.
  constexpr double kRoundOffRate = 2.0 * tolerance::kTangentRateFraction;
  const double fastest2 =
      std::max(tracks_[i].motion.velocity.squaredNorm(), tracks_[j].motion.velocity.squaredNorm());
  // Any other inelastic pair under gravity loses nothing below the rest speed (rule 8).
  const double minimum = pressed ? std::max(collapseSpeed_, separation) : collapseSpeed_;
  return {minimum * minimum >= kRoundOffRate * kRoundOffRate * fastest2
              ? minimum
              : kRoundOffRate * std::sqrt(fastest2),
          pressed || restitution >= 1.0 ? 0.0 : separation};
}

void EventEngine::collideWithSurface(int i, const Vec3& n, double restitution, RunStats& stats,
                                     int plane, const ImpactFriction& law) {
  // Any slow contact may end in rest, also a sideways one: a ball on a floor trapped between a
  // wall and a resting ball would otherwise rattle between them. With friction, a ball on a face
  // that presses it rests when its phases say it is still (refreshFace), not by its speed.
  const bool facePhases = bodies_.rough && plane >= 0 && gravity_.dot(n) < 0.0;
  if (facePhases || !restsOnContact(i, n, restitution, stats))
    bounceOffSurface(i, n, restitution, stats, plane, law);
}

void EventEngine::bounceOffSurface(int i, const Vec3& n, double restitution, RunStats& stats,
                                   int plane, const ImpactFriction& law) {
  Particle& p = particles_[i];
  Motion& m = tracks_[i].motion;
  const double approach = -m.velocity.dot(n);
  const double speed = m.velocity.norm();
  const bool pressed = pressesAlong(gravity_, -n);
  const double rest = restSpeed_[i];
  const int capture =
      plane >= 0 && pressed && restitution * std::max(approach, 0.0) <= slideSpeed_[i]
          ? slideCapture(i, plane)
          : kNoCapture;
  if (capture != kNoCapture) {
    startSliding(i, plane);
    if (capture != kAlone) startCrease(i, capture);
    // A ball that lands without bouncing (restitution 0) and little sideways speed rests; with
    // friction its phases decide.
    if (!bodies_.rough && restsOnContact(i, n, restitution, stats)) return;
  } else {
    // A plane needs no minimum: a ball bouncing on it slower than a bounce of touching height
    // slides instead (above), and so bounces in finitely many events.
    // An elastic contact cannot collapse either: it needs a minimum only to part when it meets
    // at no speed, and takes the slide speed's.
    const double pressedMinimum = plane >= 0 ? 0.0 : restitution >= 1.0 ? slideSpeed_[i] : rest;
    const double minimum = pressed ? pressedMinimum : collapseSpeed_;
    if (restitution * std::max(approach, 0.0) < minimum) ++stats.minimumBounces;
    resolveAgainstSurface(m.velocity, n, restitution, minimum);
    if (law.friction > 0.0) {
      applyImpactFriction(m.velocity, spin_[i], bodies_.radius[i], n, m.velocity.dot(n) + approach,
                          law);
      books_.noteFriction();
    }
    changed(i);
  }
  // A cycle of contacts that lets time advance by round-off only must not hang the run. The
  // flight since the last contact is negligible by the ball's own measure, its speed times the
  // time against its size, so a fast ball crossing a box is never taken for a wedged one; or
  // when it is within a few ulps of the ball's position, which it cannot move (a ball 1e12 m
  // out hopping along a cylinder stayed where it was and hopped for ever).
  const double positionRoundOff =
      4.0 * std::numeric_limits<double>::epsilon() * m.position.cwiseAbs().maxCoeff();
  if ((now_ - p.lastSurfaceCollision) * speed <=
      std::max(tolerance::kBurstTravelFraction * bodies_.radius[i], positionRoundOff)) {
    if (++p.collisionsInBurst > tolerance::kMaxCollisionsInBurst) {
      // Once per burst: a ball that bursts again before any real flight (one whose position
      // cannot move, far out) rests as before.
      if (!p.leftWedge && leaveWedge(i, stats)) {
        p.collisionsInBurst = 0;
        p.leftWedge = true;
      } else {
        putToRest(i, stats);
        p.wedged = true;
      }
    }
  } else {
    p.collisionsInBurst = 0;
    p.leftWedge = false;
  }
  p.lastSurfaceCollision = now_;
}

EventEngine::StaticContact EventEngine::staticContact(int i, StaticRef ref,
                                                      const Vec3& position) const {
  const double r = bodies_.radius[i];
  if (ref.kind == StaticKind::Box) {
    const BoxShape::Contact contact = bodies_.boxes[ref.index].contact(position, r);
    return {contact.normal, contact.gap, restitutionWith(i, ref)};
  }
  if (ref.kind == StaticKind::Cylinder) {
    const CylinderShape::Contact contact = bodies_.cylinders[ref.index].contact(position, r);
    return {contact.normal, contact.gap, restitutionWith(i, ref)};
  }
  const PlaneShape& plane = bodies_.planes[ref.index];
  return {plane.normal, plane.gap(position, r), restitutionWith(i, ref)};
}

const ContactFriction& EventEngine::shapeFriction(StaticRef ref) const {
  return bodies_.shapeFriction(contactKindOf(ref.kind), ref.index);
}

ImpactFriction EventEngine::impactFrictionWith(int i, StaticRef ref) const {
  if (!bodies_.rough) return {};
  return bodies_.impactFriction(i, shapeFriction(ref));
}

double EventEngine::restitutionWith(int i, StaticRef ref) const {
  const std::vector<double>& shapes = ref.kind == StaticKind::Box ? bodies_.boxRestitution
                                      : ref.kind == StaticKind::Cylinder
                                          ? bodies_.cylinderRestitution
                                          : bodies_.planeRestitution;
  return std::min(bodies_.restitution[i], shapes[ref.index]);
}

// A ball touching several static shapes at once (the bottom of a narrow wedge) leaves them all
// in the one event: it reflects off each shape it still moves into, in turn, as events at the
// same instant would, until it moves into none. In a wedge of angle θ that takes about π/θ
// reflections, each a few dot products, where as events each would count towards the burst
// guard and end in rest with the energy gone. Past kMaxSimultaneousReflections (wedges under
// about 3e-7 rad, or a ball jammed between parallel walls) the burst guard's rest applies.
void EventEngine::leaveTouchingStatics(int i, RunStats& stats) {
  const Particle& p = particles_[i];
  const double touching = tolerance::kTouchFraction * bodies_.radius[i];
  touchedStatics_.clear();
  for (const StaticRef ref : cells_.staticsNear(i)) {
    if (slidesAgainst(p, ref)) continue;  // see updateSlide
    const auto [n, gap, restitution] = staticContact(i, ref);
    if (gap <= touching) touchedStatics_.push_back({n, restitution, ref.kind});
  }
  // No minimum separation here: in a wedge opening slower than the rest speed it would send
  // the ball from one wall into the other for ever. An inelastic ball slows down in the loop
  // instead, and then rests by the supports rule at its next contact.
  const bool left = reflectOffEach(
      tracks_[i].motion.velocity, touchedStatics_, tolerance::kMaxSimultaneousReflections,
      [&](std::size_t k, double, std::uint64_t times) {
        books_.noteRestitution(touchedStatics_[k].restitution);
        stats.collisions.add(contactKindOf(touchedStatics_[k].kind), times);
      });
  if (left)
    changed(i);
  else
    putToRest(i, stats);
}

// A ball bouncing down a narrow wedge off-centre meets its walls ever more often, with flights
// that shrink to nothing about where it turns (in a wedge of 1e-6 rad, a millionth of a
// millimetre off the middle is enough), and the burst guard then stopped it with all its
// energy gone. Before that, the ball reflects off every static shape within
// kSupportGapFraction of its radius at once, as a ball touching them all would
// (leaveTouchingStatics): the reflections keep its speed; only the point where it turns moves,
// to where the walls are within that gap of it (in a V of angle θ, up to gap/θ higher). It
// leaves when it then moves away from them all at more than twice its rest speed, and so flies
// for a while before it meets any; a slower one (a ball settling in the V) rests as before.
bool EventEngine::leaveWedge(int i, RunStats& stats) {
  Particle& p = particles_[i];
  const double reach = tolerance::kSupportGapFraction * bodies_.radius[i];
  touchedStatics_.clear();
  // The faces it slides on count too: it leaves them with the rest.
  for (const StaticRef ref : cells_.staticsNear(i)) {
    const auto [n, gap, restitution] = staticContact(i, ref);
    if (gap <= reach) touchedStatics_.push_back({n, restitution, ref.kind});
  }
  // Only among static shapes: a ball in a burst against other balls rests as before.
  bool ballNear = false;
  const Vec3& centre = tracks_[i].motion.position;
  forEachNeighbour(i, [&](int k) {
    const double gap = (tracks_[k].motion.positionAt(now_, accelerationOf(k)) - centre).norm() -
                       bodies_.radius[i] - bodies_.radius[k];
    ballNear = ballNear || gap <= reach;
  });
  if (ballNear || touchedStatics_.empty()) return false;
  Vec3 v = tracks_[i].motion.velocity;
  std::vector<std::uint64_t> reflected(touchedStatics_.size(), 0);
  const bool left =
      reflectOffEach(v, touchedStatics_, tolerance::kMaxSimultaneousReflections,
                     [&](std::size_t k, double, std::uint64_t times) { reflected[k] += times; });
  if (!left || v.norm() <= tolerance::kSettleSpeedFactor * restSpeed_[i]) return false;
  for (const TouchedStatic& touched : touchedStatics_)
    if (v.dot(touched.normal) < 0.0) return false;
  for (std::size_t k = 0; k < reflected.size(); ++k) {
    if (reflected[k] == 0) continue;
    books_.noteRestitution(touchedStatics_[k].restitution);
    stats.collisions.add(contactKindOf(touchedStatics_[k].kind), reflected[k]);
  }
  tracks_[i].motion.velocity = v;
  p.slidePlane = p.creasePlane = -1;
  changed(i);
  refreshFace(i, stats);
  return true;
}

void EventEngine::notePenetration(double overlap, RunStats& stats) const {
  stats.maxPenetration = std::max(stats.maxPenetration, overlap);
}

}  // namespace carom
