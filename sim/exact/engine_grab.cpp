// EventEngine's held ball (grab.h): a ball the user steers through the running simulation. It
// follows a straight path at the velocity it is given, ignores gravity and has unlimited mass:
// balls it meets answer as they would a moving wall, and static shapes stop its motion into
// them. Its contacts are predicted and solved as every other one, so nothing passes through it.

#include "sim/core/tolerances.h"
#include "sim/dynamics/response.h"
#include "sim/exact/event_engine.h"

#include <cmath>
#include <limits>

namespace carom {
namespace {

// A held ball in a corner of static shapes slides along them all; past this many turns (a
// corner of well under a degree) it stops instead.
constexpr long kMaxHeldSlideTurns = 10'000;

}  // namespace

void EventEngine::hold(int i, const Vec3& velocity, RunStats& stats) {
  if (held_.ball() >= 0 && held_.ball() != i) release(Vec3::Zero());
  Particle& p = particles_[i];
  moveTo(i, now_);
  if (held_.ball() != i) {
    // What rested on it (or it itself) must move as it does.
    if (p.resting)
      wake(i, stats);
    else
      wakeEach(restingAbove(i, -std::numeric_limits<double>::infinity()), stats);
    p.slidePlane = p.creasePlane = -1;
    p.collisionsInBurst = 0;
    p.wedged = false;
    p.held = true;
    held_.take(i);
    refreshFace(i, stats);
  }
  tracks_[i].motion.velocity = velocity;
  changed(i);
  predict(i);
}

void EventEngine::release(const Vec3& velocity) {
  if (held_.ball() < 0) return;
  const int i = held_.ball();
  moveTo(i, now_);
  particles_[i].held = false;
  held_.letGo();
  tracks_[i].motion.velocity = velocity;
  books_.record(i, tracks_[i].motion);  // `swept`'s books start from the throw
  changed(i);
  predict(i);
}

void EventEngine::place(const Vec3& position) {
  if (held_.ball() < 0) return;
  const int i = held_.ball();
  tracks_[i].motion.position = position;
  if (roughFaces_) spin_[i] = spinAt(i, now_);
  tracks_[i].motion.since = now_;
  cells_.place(i, position);
  changed(i);
  predict(i);
}

void EventEngine::heldMeetsStatic(int h, StaticRef ref, RunStats& stats,
                                  std::vector<CollisionRecord>* log) {
  moveTo(h, now_);
  Motion& m = tracks_[h].motion;
  const double r = bodies_.radius[h];
  const auto [n, gap, restitution] = staticContact(h, ref);
  notePenetration(-gap, stats);
  const double approach = -m.velocity.dot(n);
  // Every shape it touches stops the motion into it, the one met first among them.
  const double touching = tolerance::kTouchFraction * r;
  touchedStatics_.clear();
  touchedStatics_.push_back({n, 0.0, ref.kind});
  for (const StaticRef other : cells_.staticsNear(h)) {
    if (other.kind == ref.kind && other.index == ref.index) continue;
    const StaticContact contact = staticContact(h, other);
    if (contact.gap <= touching) touchedStatics_.push_back({contact.normal, 0.0, other.kind});
  }
  if (!reflectOffEach(m.velocity, touchedStatics_, kMaxHeldSlideTurns,
                      [](std::size_t, double, std::uint64_t) {}))
    m.velocity = Vec3::Zero();
  changed(h);
  const ContactKind kind = contactKindOf(ref.kind);
  stats.collisions.add(kind);
  if (log) log->push_back({now_, kind, h, ref.index, m.position - r * n, approach});
  predict(h);
}

void EventEngine::pushByHeld(int h, int o, RunStats& stats, std::vector<CollisionRecord>* log) {
  moveTo(h, now_);
  moveTo(o, now_);
  if (particles_[o].resting) wake(o, stats);
  books_.restore(o, tracks_[o].motion);
  Motion& mh = tracks_[h].motion;
  Motion& mo = tracks_[o].motion;
  Vec3 n = mo.position - mh.position;
  const double distance = n.norm();
  const double radiusSum = bodies_.radius[h] + bodies_.radius[o];
  notePenetration(radiusSum - distance, stats);
  n = pairNormal(n, distance, mh.velocity - mo.velocity);
  if (crushes(h, o, n)) stopGrab(GrabStopKind::Crush, o);
  if (held_.jams(mh.velocity, bodies_.radius[h], now_)) stopGrab(GrabStopKind::Jam, o);
  const double approach = (mh.velocity - mo.velocity).dot(n);
  const double restitution = std::min(bodies_.restitution[h], bodies_.restitution[o]);
  books_.noteRestitution(restitution);
  // The floor of collideBalls; the held ball feels no gravity (gravityOn).
  const auto [minimum, lossless] = pairFloor(h, o, n, restitution);
  Vec3 heldVelocity = mh.velocity, exchanged = mo.velocity;
  resolveBallBall(heldVelocity, exchanged, 0.0, bodies_.inverseMass[o], n, restitution, 0.0);
  const double exchangedEnergy = 0.5 * (exchanged.squaredNorm() - mo.velocity.squaredNorm());
  resolveBallBall(heldVelocity, mo.velocity, 0.0, bodies_.inverseMass[o], n, restitution, minimum,
                  lossless);
  changed(o);
  updateSlide(o, stats);
  ++stats.collisions.ballBall;
  if (log)
    log->push_back(
        {now_, ContactKind::BallBall, h, o, mh.position + bodies_.radius[h] * n, approach});
  books_.close(o, exchangedEnergy, tracks_[o].motion);
  predict(h);
  predict(o);
}

bool EventEngine::crushes(int h, int o, const Vec3& n) const {
  const double push = tracks_[h].motion.velocity.dot(n);
  if (!(push > 0.0)) return false;
  // Slipping out sideways takes push / sin(φ), φ the angle between the push and the way into
  // the obstacle: too fast when sin(φ) < 1 / kCrushEscapeFactor.
  const double headOn =
      std::sqrt(1.0 - 1.0 / (tolerance::kCrushEscapeFactor * tolerance::kCrushEscapeFactor));
  const double room = tolerance::kCrushRoomFraction * bodies_.radius[o];
  const auto blocks = [&](const Vec3& normal, double gap) {
    const double into = -n.dot(normal);  // cos(φ)
    return into > headOn && std::max(gap, 0.0) < room * into;
  };
  for (const StaticRef shape : cells_.staticsNear(o)) {
    const StaticContact contact = staticContact(o, shape);
    if (blocks(contact.normal, contact.gap)) return true;
  }
  bool blocked = false;
  forEachNeighbour(o, [&](int k) {
    if (blocked || !particles_[k].resting) return;
    Vec3 d = tracks_[o].motion.position - tracks_[k].motion.position;
    const double distance = d.norm();
    blocked = blocks(pairNormal(d, distance, -tracks_[o].motion.velocity),
                     distance - bodies_.radius[o] - bodies_.radius[k]);
  });
  return blocked;
}

void EventEngine::stopGrab(GrabStopKind kind, int other) {
  const int h = held_.ball();
  tracks_[h].motion.velocity = Vec3::Zero();
  changed(h);
  held_.stop(GrabStop{kind, h, other, now_});
}

}  // namespace carom
