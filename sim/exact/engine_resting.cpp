// EventEngine's resting (docs/physics.md, rules 3 and 4 of "Resting contact"): when a slow ball is
// held by the pushes of its contacts, alone and with its cluster, it stops; a hard hit wakes it.

#include "sim/exact/event_engine.h"

#include "sim/core/tolerances.h"
#include "sim/dynamics/contact_forces.h"
#include "sim/dynamics/response.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace carom {

void EventEngine::putToRest(int i, RunStats& stats, const Vec3& settle) {
  Particle& p = particles_[i];
  moveTo(i, now_);
  tracks_[i].motion.position += settle;
  tracks_[i].motion.velocity.setZero();
  p.resting = true;
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
  const RestCheck check = restCheck(i);
  wakeEach(check.loosened, stats);
  if (check.holds) putToRest(i, stats, check.settle);
  return check.holds;
}

bool EventEngine::slow(int k) const {
  // Nothing rests on the held ball: it moves as the user steers it.
  return !particles_[k].resting && !particles_[k].held &&
         tracks_[k].motion.velocityAt(now_, accelerationOf(k)).norm() <
             tolerance::kSettleSpeedFactor * restSpeed_[k];
}

// The gap and unit normal (towards ball i at `centre`) of a support: a static shape or another
// ball.
EventEngine::SupportGap EventEngine::supportGap(int i, const Support& support,
                                                const Vec3& centre) const {
  if (support.ball < 0) {
    const StaticContact contact = staticContact(i, support.shape, centre);
    return {contact.normal, contact.gap};
  }
  const int k = support.ball;
  const Vec3 d = centre - tracks_[k].motion.positionAt(now_, accelerationOf(k));
  const double distance = d.norm();
  return {pairNormal(d, distance, -gravity_), distance - bodies_.radius[i] - bodies_.radius[k]};
}

EventEngine::NearContacts EventEngine::nearContacts(int i, const Vec3& centre) const {
  const double reach = tolerance::kSupportGapFraction * bodies_.radius[i];
  NearContacts near;
  const auto consider = [&](const Support& support, bool moving) {
    const SupportGap gap = supportGap(i, support, centre);
    if (gap.gap > reach) return;
    (moving ? near.moving : near.supports).push_back(support);
    if (!moving) near.normals.push_back(gap.normal);
  };
  for (const StaticRef shape : cells_.staticsNear(i)) consider({.shape = shape}, false);
  forEachNeighbour(i, [&](int k) {
    consider({.ball = k},
             particles_[k].held ||
                 (!particles_[k].resting &&
                  tracks_[k].motion.velocityAt(now_, accelerationOf(k)).norm() >= restSpeed_[i]));
  });
  return near;
}

// Rule 3 of "Resting contact". Ball i can rest when pushes alone at its contacts hold it against
// gravity. Its supports are the static shapes, resting balls and slow balls (neighbours leaning
// on each other in a pile come to rest one after the other) within kSupportGapFraction, the
// height of the hops that rule 1 gives a slow ball; and the supports that carry its weight must
// be ones it can touch all at once by moving no further than that. A ball hopping in a corner or
// in the groove between resting balls rests; one falling between walls that meet far below it
// (a narrow wedge) does not. Its cluster must hold too.
EventEngine::RestCheck EventEngine::restCheck(int i) const {
  RestCheck check;
  const Vec3 centre = tracks_[i].motion.positionAt(now_, accelerationOf(i));
  const NearContacts near = nearContacts(i, centre);
  std::vector<ClusterContact> contacts;
  for (const Vec3& normal : near.normals) contacts.push_back({0, -1, normal});
  std::vector<bool> carries;
  if (!contactForcesBalance(gravity_, {bodies_.mass[i]}, contacts, tolerance::kForceBalance,
                            &carries))
    return check;
  std::vector<Support> carrying;
  for (std::size_t c = 0; c < contacts.size(); ++c)
    if (carries[c]) carrying.push_back(near.supports[c]);
  const std::optional<Vec3> move = closingMove(i, centre, carrying);
  if (!move) return check;
  if (!clusterHolds(i)) return check;
  // Each resting ball that carries it must be able to: with that ball free as well (its other
  // contacts fixed), the cluster must still hold. One that cannot is loosened: it wakes, and
  // its own check, the same system seen from it, then fails as this one did. Three balls
  // placed in a frictionless pyramid spread whether the lower two rest or not when the top
  // arrives. A ball the burst guard stopped in its wedge is not loosened: woken, it would rattle
  // in the wedge at one instant until the guard stopped it again, and a ball leaning on it
  // would loosen it anew each time it touched, nanoseconds apart, for ever (a Galton funnel
  // jammed at its outlet, test_rest).
  for (const Support& support : carrying)
    if (support.ball >= 0 && particles_[support.ball].resting && !particles_[support.ball].wedged &&
        !clusterHolds(i, support.ball))
      check.loosened.push_back(support.ball);
  if (!check.loosened.empty()) return check;
  const std::optional<Vec3> settle = settlingMove(i, centre, near, *move, std::move(carrying));
  check.holds = settle.has_value();
  if (settle) check.settle = *settle;
  return check;
}

// The smallest move that closes the gaps of `carrying` from `centre`, to first order (n . d =
// -gap for each); none when that is longer than kSupportGapFraction of the radius or cannot
// close them all.
std::optional<Vec3> EventEngine::closingMove(int i, const Vec3& centre,
                                             const std::vector<Support>& carrying) const {
  const double reach = tolerance::kSupportGapFraction * bodies_.radius[i];
  double residual = 0.0;
  const Vec3 move = closingStep(i, centre, carrying, &residual);
  if (move.norm() > reach || residual > reach) return std::nullopt;
  return move;
}

Vec3 EventEngine::closingStep(int i, const Vec3& at, const std::vector<Support>& supports,
                              double* residual) const {
  const auto rows = static_cast<Eigen::Index>(supports.size());
  Eigen::MatrixXd normals(rows, 3);
  Eigen::VectorXd closing(rows);
  for (Eigen::Index k = 0; k < rows; ++k) {
    const auto [n, gap] = supportGap(i, supports[k], at);
    normals.row(k) = n.transpose();
    closing[k] = -gap;
  }
  const Vec3 step = normals.completeOrthogonalDecomposition().solve(closing);
  *residual = (normals * step - closing).norm();
  return step;
}

// Where a resting ball settles: onto the supports carrying it, so that they touch it to
// round-off (Newton's method from the first-order move); a contact the move would overlap joins
// the ones to close, so that the ball ends touching it instead. There, without overlapping
// anything, the contacts it touches to round-off must hold it. Where that fails (the joined
// contacts cannot all be touched at once), it settles into the lowest pocket within reach
// (lowestPocket); failing that, it does not rest: it hops on at the rest speed until it lands
// where it can settle.
std::optional<Vec3> EventEngine::settlingMove(int i, const Vec3& centre, const NearContacts& near,
                                              Vec3 move, std::vector<Support> carrying) const {
  const double touching = tolerance::kTouchFraction * bodies_.radius[i];
  double residual = 0.0;
  for (int round = 0; round < 4; ++round) {
    for (int newton = 0; newton < 3; ++newton)
      move += closingStep(i, centre + move, carrying, &residual);
    bool joined = false;
    for (const std::vector<Support>* list : {&near.supports, &near.moving})
      for (const Support& support : *list) {
        if (supportGap(i, support, centre + move).gap >= -touching) continue;
        carrying.push_back(support);
        joined = true;
      }
    if (!joined) break;
  }
  if (heldAt(i, centre + move, near)) return move;
  return lowestPocket(i, centre, near);
}

bool EventEngine::heldAt(int i, const Vec3& centre, const NearContacts& near) const {
  if (!clearAt(i, centre)) return false;
  const double touching = tolerance::kTouchFraction * bodies_.radius[i];
  std::vector<ClusterContact> touchingContacts;
  for (const Support& support : near.supports) {
    const auto [n, gap] = supportGap(i, support, centre);
    if (std::abs(gap) <= touching) touchingContacts.push_back({0, -1, n});
  }
  return contactForcesBalance(gravity_, {bodies_.mass[i]}, touchingContacts,
                              tolerance::kForceBalance);
}

// The lowest place along gravity, within kSupportGapFraction of the radius, where ball i touches
// one, two or three of its supports to round-off, overlaps nothing and is held by what it
// touches: the pocket a frictionless ball would roll into. Each such set of supports is tried
// (a ball touches a handful, so there are at most some tens).
std::optional<Vec3> EventEngine::lowestPocket(int i, const Vec3& centre,
                                              const NearContacts& near) const {
  const double reach = tolerance::kSupportGapFraction * bodies_.radius[i];
  const double touching = tolerance::kTouchFraction * bodies_.radius[i];
  const int count = static_cast<int>(near.supports.size());
  std::optional<Vec3> best;
  std::vector<Support> touched;
  const auto tryTouching = [&]() {
    double residual = 0.0;
    Vec3 move = closingStep(i, centre, touched, &residual);
    for (int newton = 0; newton < 4 && move.norm() <= reach; ++newton)
      move += closingStep(i, centre + move, touched, &residual);
    if (move.norm() > reach) return;
    for (const Support& support : touched)
      if (std::abs(supportGap(i, support, centre + move).gap) > touching) return;
    if (best && gravity_.dot(move) <= gravity_.dot(*best)) return;
    if (heldAt(i, centre + move, near)) best = move;
  };
  for (int a = 0; a < count; ++a) {
    touched = {near.supports[a]};
    tryTouching();
    for (int b = a + 1; b < count; ++b) {
      touched = {near.supports[a], near.supports[b]};
      tryTouching();
      for (int c = b + 1; c < count; ++c) {
        touched = {near.supports[a], near.supports[b], near.supports[c]};
        tryTouching();
      }
    }
  }
  return best;
}

bool EventEngine::clearAt(int i, const Vec3& centre) const {
  const double r = bodies_.radius[i];
  const double touching = tolerance::kTouchFraction * r;
  for (const StaticRef shape : cells_.staticsNear(i))
    if (staticContact(i, shape, centre).gap < -touching) return false;
  bool clear = true;
  forEachNeighbour(i, [&](int k) {
    const Vec3 d = centre - tracks_[k].motion.positionAt(now_, accelerationOf(k));
    clear = clear && d.norm() - r - bodies_.radius[k] >= -touching;
  });
  return clear;
}

// Ball i's cluster: i and the slow balls that touch it within the support gap, and theirs,
// breadth first up to kMaxClusterBalls. They are solved together, loads included: three slow
// balls in a frictionless pyramid are not held, though each alone would be. Resting balls, and
// balls past the limit, count as fixed, as statics do, except `freed`, a resting ball that
// takes part as the slow ones do.
bool EventEngine::clusterHolds(int i, int freed) const {
  std::vector<int> members{i};
  std::vector<Vec3> centres{tracks_[i].motion.positionAt(now_, accelerationOf(i))};
  if (freed >= 0) {
    members.push_back(freed);
    centres.push_back(tracks_[freed].motion.position);
  }
  const auto memberIndex = [&](int k) {
    const auto found = std::find(members.begin(), members.end(), k);
    return found == members.end() ? -1 : static_cast<int>(found - members.begin());
  };
  std::vector<ClusterContact> contacts;
  for (std::size_t c = 0; c < members.size(); ++c) {
    const int k = members[c];
    const double rk = bodies_.radius[k];
    for (const StaticRef shape : cells_.staticsNear(k)) {
      const auto [n, gap, restitution] = staticContact(k, shape, centres[c]);
      if (gap <= tolerance::kSupportGapFraction * rk)
        contacts.push_back({static_cast<int>(c), -1, n});
    }
    forEachNeighbour(k, [&](int m) {
      const int known = memberIndex(m);
      if (known >= 0 && known < static_cast<int>(c)) return;  // that contact is listed already
      const bool resting = particles_[m].resting;
      if (!resting && !slow(m)) return;
      const Vec3 centre =
          known >= 0 ? centres[known] : tracks_[m].motion.positionAt(now_, accelerationOf(m));
      const Vec3 d = centres[c] - centre;
      if (d.norm() - rk - bodies_.radius[m] >
          tolerance::kSupportGapFraction * std::min(rk, bodies_.radius[m]))
        return;
      int other = known;
      if (other < 0 && !resting && static_cast<int>(members.size()) < tolerance::kMaxClusterBalls) {
        other = static_cast<int>(members.size());
        members.push_back(m);
        centres.push_back(centre);
      }
      contacts.push_back({static_cast<int>(c), other, d.normalized()});
    });
  }
  if (members.size() == 1) return true;  // alone among fixed supports: restCheck decided it
  std::vector<double> masses(members.size());
  for (std::size_t c = 0; c < members.size(); ++c) masses[c] = bodies_.mass[members[c]];
  return contactForcesBalance(gravity_, masses, contacts, tolerance::kForceBalance);
}

}  // namespace carom
