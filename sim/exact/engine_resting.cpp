// EventEngine's resting (docs/physics.md, rules 3 and 4 of "Resting contact"): when a slow ball is
// held by the pushes of its contacts, alone and with its cluster, it stops (whether it is held is
// RestCheck's question, rest_check.h); a hard hit wakes it.

#include "sim/core/tolerances.h"
#include "sim/exact/event_engine.h"
#include "sim/exact/rest_check.h"

#include <algorithm>
#include <limits>

namespace carom {

void EventEngine::putToRest(int i, RunStats& stats, const Vec3& settle) {
  Particle& p = particles_[i];
  moveTo(i, now_);
  tracks_[i].motion.position += settle;
  tracks_[i].motion.velocity.setZero();
  p.resting = true;
  if (roughFaces_) restOnFace(i);
  changed(i);
  ++stats.restings;
  predictions_[i].contact = {};
  predictions_[i].crossing = {};
  schedule(i);
  warnNeighbours(i);
  // A resting ball above that rested on i while i still moved is left with a gap: it falls the
  // gap and settles again.
  wakeEach(restingAbove(i, tolerance::kTouchFraction), stats);
}

void EventEngine::wakeEach(const std::vector<int>& balls, RunStats& stats) {
  for (const int m : balls) {
    if (!particles_[m].resting) continue;  // woken with another one
    wake(m, stats);
    predict(m);
  }
}

std::vector<int> EventEngine::restingAbove(int k, double minGapFraction) const {
  std::vector<int> above;
  forEachNeighbour(k, [&](int m) {
    if (!particles_[m].resting) return;
    const Vec3 offset = tracks_[m].motion.position - tracks_[k].motion.position;
    if (offset.dot(gravity_) >= 0.0) return;  // beside or below: it does not rest on k
    const double smaller = std::min(bodies_.radius[k], bodies_.radius[m]);
    const double gap = offset.norm() - bodies_.radius[k] - bodies_.radius[m];
    if (gap > minGapFraction * smaller && gap <= tolerance::kSupportGapFraction * smaller)
      above.push_back(m);
  });
  return above;
}

void EventEngine::wake(int i, RunStats& stats) {
  // Resting balls touching a woken ball from above may have rested on it: wake them, and
  // whatever rests on them.
  std::vector<int> pending{i};
  particles_[i].resting = false;
  while (!pending.empty()) {
    const int k = pending.back();
    pending.pop_back();
    Particle& p = particles_[k];
    ++stats.wakes;
    if (roughFaces_) spin_[k] = spinAt(k, now_);
    tracks_[k].motion.since = now_;  // starts to fall from here
    p.collisionsInBurst = 0;
    p.wedged = false;
    changed(k);
    for (const int m : restingAbove(k, -std::numeric_limits<double>::infinity())) {
      particles_[m].resting = false;
      pending.push_back(m);
    }
    if (k != i) predict(k);
  }
}

bool EventEngine::restsOnContact(int i, const Vec3& n, double restitution, RunStats& stats) {
  const Vec3& v = tracks_[i].motion.velocity;
  // Resting takes the ball's kinetic energy. An inelastic ball would lose it in its bounces
  // anyway; an elastic one would not, so it rests only as slow as its slide speed (a bounce of
  // round-off height, how fast elastic pairs part): an elastic ball sliding slowly across a
  // floor, or pushed off a frictionless pyramid, keeps its speed.
  const double slowest = restitution >= 1.0 ? slideSpeed_[i] : restSpeed_[i];
  const double settle = tolerance::kSettleSpeedFactor * slowest;
  const double approach = -v.dot(n);
  if (approach >= settle || (v + approach * n).norm() >= settle) return false;
  const RestCheck::Result check = RestCheck(*this).of(i);
  wakeEach(check.loosened, stats);
  if (check.holds) putToRest(i, stats, check.settle);
  return check.holds;
}

}  // namespace carom
