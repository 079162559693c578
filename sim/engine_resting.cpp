// EventEngine's resting (docs/physics.md, rules 3 and 4 of "Resting contact"): when a slow ball is
// held by the pushes of its contacts, alone and with its cluster, it stops; a hard hit wakes it.

#include "sim/event_engine.h"

#include "sim/contact_forces.h"
#include "sim/tolerances.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

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
    recordEnergy(k);
    p.collisionsInBurst = 0;
    changed(k);
    forEachNeighbour(k, [&](int m) {
      Particle& q = particles_[m];
      if (!q.resting) return;
      const Vec3 offset = tracks_[m].motion.position - tracks_[k].motion.position;
      if (offset.dot(gravity_) >= 0.0) return;  // beside or below: it does not rest on k
      const double gap = offset.norm() - bodies_.radius[k] - bodies_.radius[m];
      if (gap <= tolerance::kSupportGapFraction * std::min(bodies_.radius[k], bodies_.radius[m])) {
        q.resting = false;
        pending.push_back(m);
      }
    });
    if (k != i) predict(k);
  }
}

// Ball i can rest when pushes alone at its contacts hold it against gravity. Its supports are
// the static shapes, resting balls and slow balls (slower than the rest speed: neighbours leaning
// on each other in a pile come to rest one after the other) within kSupportGapFraction, the
// height of the hops that rule 1 gives a slow ball; and the supports that carry its weight must
// be ones it can touch all at once by moving no further than that. A ball hopping in a corner or
// in the groove between resting balls rests; one falling between walls that meet far below it
// (a narrow wedge) does not.
bool EventEngine::supported(int i, Vec3* settle) const {
  return heldAlone(i, settle) && clusterHolds(i);
}

// The gap and unit normal (towards ball i at `centre`) of a support: a static shape (its slot in
// statics_) or another ball.
EventEngine::SupportGap EventEngine::supportGap(int i, const Support& support,
                                                const Vec3& centre) const {
  if (support.ball < 0) {
    const StaticContact contact = staticContact(i, statics_[support.staticSlot], centre);
    return {contact.normal, contact.gap};
  }
  const int k = support.ball;
  const Vec3 d = centre - tracks_[k].motion.positionAt(now_, accelerationOf(k));
  const double distance = d.norm();
  return {d / distance, distance - bodies_.radius[i] - bodies_.radius[k]};
}

bool EventEngine::heldAlone(int i, Vec3* settle) const {
  const Vec3 centre = tracks_[i].motion.positionAt(now_, accelerationOf(i));
  const double r = bodies_.radius[i];
  const double reach = tolerance::kSupportGapFraction * r;
  std::vector<Support> supports;
  std::vector<ClusterContact> contacts;
  std::vector<double> gaps;
  const auto consider = [&](const Support& support) {
    const auto [n, gap] = supportGap(i, support, centre);
    if (gap > reach) return;
    supports.push_back(support);
    contacts.push_back({0, -1, n});
    gaps.push_back(gap);
  };
  const Particle& p = particles_[i];
  for (int s = p.staticBegin; s < p.staticEnd; ++s) consider({s, -1});
  std::vector<Support> moving;  // not supports, but the ball must not settle into them
  forEachNeighbour(i, [&](int k) {
    const Motion& mk = tracks_[k].motion;
    if (!particles_[k].resting && mk.velocityAt(now_, accelerationOf(k)).norm() >= restSpeed_[i]) {
      if (supportGap(i, {-1, k}, centre).gap <= reach) moving.push_back({-1, k});
      return;
    }
    consider({-1, k});
  });
  std::vector<bool> carries;
  if (!contactForcesBalance(gravity_, {bodies_.mass[i]}, contacts, tolerance::kForceBalance,
                            &carries))
    return false;
  std::vector<Support> carrying;
  for (std::size_t c = 0; c < contacts.size(); ++c)
    if (carries[c]) carrying.push_back(supports[c]);
  // The smallest move that closes the gaps of the supports carrying the weight, to first order
  // (n . d = -gap for each), then refined by Newton's method so that they touch to round-off.
  const auto closingStep = [&](const Vec3& at, double* residual) {
    const auto rows = static_cast<Eigen::Index>(carrying.size());
    Eigen::MatrixXd normals(rows, 3);
    Eigen::VectorXd closing(rows);
    for (Eigen::Index k = 0; k < rows; ++k) {
      const auto [n, gap] = supportGap(i, carrying[k], at);
      normals.row(k) = n.transpose();
      closing[k] = -gap;
    }
    const Vec3 step = normals.completeOrthogonalDecomposition().solve(closing);
    *residual = (normals * step - closing).norm();
    return step;
  };
  double residual = 0.0;
  Vec3 move = closingStep(centre, &residual);
  if (move.norm() > reach || residual > reach) return false;
  // Settle onto them (Newton's method); a contact the move would overlap joins the ones to
  // close, so that the ball ends touching it instead.
  for (int round = 0; round < 4; ++round) {
    for (int newton = 0; newton < 3; ++newton) move += closingStep(centre + move, &residual);
    bool joined = false;
    for (const std::vector<Support>* near : {&supports, &moving})
      for (const Support& support : *near) {
        if (supportGap(i, support, centre + move).gap >= -tolerance::kTouchFraction * r) continue;
        carrying.push_back(support);
        joined = true;
      }
    if (!joined) break;
  }
  // There, without overlapping anything, the contacts it touches to round-off must hold it.
  // Where they do not (3 balls of the 64 in test_rest's pile, whose settling would press into a
  // neighbour), it rests where it is, its supports within kSupportGapFraction.
  if (settle) *settle = Vec3::Zero();
  if (!clearAt(i, centre + move)) return true;
  std::vector<ClusterContact> touching;
  for (const Support& support : supports) {
    const auto [n, gap] = supportGap(i, support, centre + move);
    if (std::abs(gap) <= tolerance::kTouchFraction * r) touching.push_back({0, -1, n});
  }
  if (settle &&
      contactForcesBalance(gravity_, {bodies_.mass[i]}, touching, tolerance::kForceBalance))
    *settle = move;
  return true;
}

bool EventEngine::clearAt(int i, const Vec3& centre) const {
  const double r = bodies_.radius[i];
  const double touching = tolerance::kTouchFraction * r;
  const Particle& p = particles_[i];
  for (int s = p.staticBegin; s < p.staticEnd; ++s)
    if (staticContact(i, statics_[s], centre).gap < -touching) return false;
  bool clear = true;
  forEachNeighbour(i, [&](int k) {
    const Vec3 d = centre - tracks_[k].motion.positionAt(now_, accelerationOf(k));
    clear = clear && d.norm() - r - bodies_.radius[k] >= -touching;
  });
  return clear;
}

// Ball i's cluster: i and the slow balls (slower than a settling ball, not yet resting) that
// touch it within the support gap, and theirs, breadth first up to kMaxClusterBalls. They are
// solved together, loads included: three slow balls in a frictionless pyramid are not held,
// though each alone would be. Resting balls, and balls past the limit, count as fixed, as
// statics do: a settled pile is rigid to a newcomer unless a hit wakes it (rule 4).
bool EventEngine::clusterHolds(int i) const {
  std::vector<int> members{i};
  std::vector<Vec3> centres{tracks_[i].motion.positionAt(now_, accelerationOf(i))};
  const auto memberIndex = [&](int k) {
    const auto found = std::find(members.begin(), members.end(), k);
    return found == members.end() ? -1 : static_cast<int>(found - members.begin());
  };
  std::vector<ClusterContact> contacts;
  for (std::size_t c = 0; c < members.size(); ++c) {
    const int k = members[c];
    const double rk = bodies_.radius[k];
    const Particle& p = particles_[k];
    for (int s = p.staticBegin; s < p.staticEnd; ++s) {
      const auto [n, gap, restitution] = staticContact(k, statics_[s], centres[c]);
      if (gap <= tolerance::kSupportGapFraction * rk)
        contacts.push_back({static_cast<int>(c), -1, n});
    }
    forEachNeighbour(k, [&](int m) {
      const int known = memberIndex(m);
      if (known >= 0 && known < static_cast<int>(c)) return;  // that contact is listed already
      const Particle& q = particles_[m];
      const Motion& mm = tracks_[m].motion;
      const bool slow = !q.resting && mm.velocityAt(now_, accelerationOf(m)).norm() <
                                          tolerance::kSettleSpeedFactor * restSpeed_[m];
      if (!q.resting && !slow) return;
      const Vec3 centre = known >= 0 ? centres[known] : mm.positionAt(now_, accelerationOf(m));
      const Vec3 d = centres[c] - centre;
      if (d.norm() - rk - bodies_.radius[m] >
          tolerance::kSupportGapFraction * std::min(rk, bodies_.radius[m]))
        return;
      int other = known;
      if (other < 0 && slow && static_cast<int>(members.size()) < tolerance::kMaxClusterBalls) {
        other = static_cast<int>(members.size());
        members.push_back(m);
        centres.push_back(centre);
      }
      contacts.push_back({static_cast<int>(c), other, d.normalized()});
    });
  }
  if (members.size() == 1) return true;  // alone among fixed supports: heldAlone decided it
  std::vector<double> masses(members.size());
  for (std::size_t c = 0; c < members.size(); ++c) masses[c] = bodies_.mass[members[c]];
  return contactForcesBalance(gravity_, masses, contacts, tolerance::kForceBalance);
}

}  // namespace carom
