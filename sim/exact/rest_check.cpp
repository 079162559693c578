#include "sim/exact/rest_check.h"

#include "sim/core/tolerances.h"
#include "sim/dynamics/contact_forces.h"
#include "sim/dynamics/response.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <utility>

namespace carom {

double RestCheck::frictionWith(int i, const Support& support) const {
  if (!bodies_.rough) return 0.0;
  if (support.ball >= 0) return bodies_.impactFriction(i, support.ball).friction;
  return bodies_.impactFriction(i, engine_.shapeFriction(support.shape)).friction;
}

bool RestCheck::slow(int k) const {
  // Nothing rests on the held ball: it moves as the user steers it.
  return !particles_[k].resting && !particles_[k].held &&
         tracks_[k].motion.velocityAt(now_, engine_.accelerationOf(k)).norm() <
             tolerance::kSettleSpeedFactor * restSpeed_[k];
}

// The gap and unit normal (towards ball i at `centre`) of a support: a static shape or another
// ball.
RestCheck::SupportGap RestCheck::supportGap(int i, const Support& support,
                                            const Vec3& centre) const {
  if (support.ball < 0) {
    const auto contact = engine_.staticContact(i, support.shape, centre);
    return {contact.normal, contact.gap};
  }
  const int k = support.ball;
  const Vec3 d = centre - tracks_[k].motion.positionAt(now_, engine_.accelerationOf(k));
  const double distance = d.norm();
  return {pairNormal(d, distance, -gravity_), distance - bodies_.radius[i] - bodies_.radius[k]};
}

RestCheck::NearContacts RestCheck::nearContacts(int i, const Vec3& centre) const {
  const double reach = tolerance::kSupportGapFraction * bodies_.radius[i];
  NearContacts near;
  const auto consider = [&](const Support& support, bool moving) {
    const SupportGap gap = supportGap(i, support, centre);
    if (gap.gap > reach) return;
    (moving ? near.moving : near.supports).push_back(support);
    if (!moving) near.normals.push_back(gap.normal);
  };
  for (const StaticRef shape : cells_.staticsNear(i)) consider({.shape = shape}, false);
  cells_.forEachNeighbour(i, [&](int k) {
    consider({.ball = k},
             particles_[k].held ||
                 (!particles_[k].resting &&
                  tracks_[k].motion.velocityAt(now_, engine_.accelerationOf(k)).norm() >=
                      restSpeed_[i]));
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
RestCheck::Result RestCheck::of(int i) const {
  Result check;
  const Vec3 centre = tracks_[i].motion.positionAt(now_, engine_.accelerationOf(i));
  const NearContacts near = nearContacts(i, centre);
  std::vector<Support> carrying;
  const std::optional<Vec3> move = holdsWhereItIs(i, centre, near, &carrying);
  if (!move || !clusterHolds(i)) return check;
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

// Rule 3's first test of ball i at `centre`: pushes at what it touches hold it with the balls it
// touches fixed, and the supports that carry it can be closed together. Returns the first-order
// closing move and the supports carrying it.
std::optional<Vec3> RestCheck::holdsWhereItIs(int i, const Vec3& centre, const NearContacts& near,
                                              std::vector<Support>* carryingOut) const {
  std::optional<Vec3> move;
  std::vector<Support> carrying;
  // The balance may pick supports it cannot close together: a ball caged among resting balls,
  // rattling between those above and below it a few nanometres apart, is held by the nearest
  // while the balance leaned on one farther below. The farthest supports are then left out:
  // those beyond 10^-3 of the radius, then beyond 10^-4, down to kTouchFraction, until a set
  // holds it and closes.
  const double touching = tolerance::kTouchFraction * bodies_.radius[i];
  std::vector<double> gaps;
  for (const Support& support : near.supports) gaps.push_back(supportGap(i, support, centre).gap);
  std::size_t previous = 0;  // supports in the last set tried
  for (double within = std::numeric_limits<double>::infinity(); !move && within >= touching;
       within = std::isinf(within) ? tolerance::kSupportGapFraction * bodies_.radius[i] / 10.0
                                   : within / 10.0) {
    std::vector<ClusterContact> contacts;
    std::vector<Support> supports;
    for (std::size_t c = 0; c < near.normals.size(); ++c) {
      if (gaps[c] > within) continue;
      contacts.push_back({0, -1, near.normals[c], frictionWith(i, near.supports[c])});
      supports.push_back(near.supports[c]);
    }
    if (supports.size() == previous) continue;  // the set already tried
    previous = supports.size();
    std::vector<bool> carries;
    if (!contactForcesBalance(gravity_, {bodies_.mass[i]}, {bodies_.radius[i]}, contacts,
                              tolerance::kForceBalance, &carries)) {
      if (std::isinf(within)) break;  // fewer supports cannot hold it either
      continue;
    }
    carrying.clear();
    for (std::size_t c = 0; c < contacts.size(); ++c)
      if (carries[c]) carrying.push_back(supports[c]);
    move = closingMove(i, centre, carrying);
  }
  if (!move) return std::nullopt;
  if (carryingOut) *carryingOut = std::move(carrying);
  return move;
}

// The smallest move that closes the gaps of `carrying` from `centre`, to first order (n . d =
// -gap for each); none when that is longer than kSupportGapFraction of the radius or cannot
// close them all.
std::optional<Vec3> RestCheck::closingMove(int i, const Vec3& centre,
                                           const std::vector<Support>& carrying) const {
  const double reach = tolerance::kSupportGapFraction * bodies_.radius[i];
  double residual = 0.0;
  const Vec3 move = closingStep(i, centre, carrying, &residual);
  if (move.norm() > reach || residual > reach) return std::nullopt;
  return move;
}

Vec3 RestCheck::closingStep(int i, const Vec3& at, const std::vector<Support>& supports,
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
std::optional<Vec3> RestCheck::settlingMove(int i, const Vec3& centre, const NearContacts& near,
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

bool RestCheck::heldAt(int i, const Vec3& centre, const NearContacts& near) const {
  if (!clearAt(i, centre)) return false;
  const double touching = tolerance::kTouchFraction * bodies_.radius[i];
  std::vector<ClusterContact> touchingContacts;
  for (const Support& support : near.supports) {
    const auto [n, gap] = supportGap(i, support, centre);
    if (std::abs(gap) <= touching) touchingContacts.push_back({0, -1, n, frictionWith(i, support)});
  }
  return contactForcesBalance(gravity_, {bodies_.mass[i]}, {bodies_.radius[i]}, touchingContacts,
                              tolerance::kForceBalance);
}

// The lowest place along gravity, within kSupportGapFraction of the radius, where ball i touches
// one, two or three of its supports to round-off, overlaps nothing and is held by what it
// touches: the pocket a frictionless ball would roll into. Each such set of supports is tried
// (a ball touches a handful, so there are at most some tens).
std::optional<Vec3> RestCheck::lowestPocket(int i, const Vec3& centre,
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

bool RestCheck::clearAt(int i, const Vec3& centre) const {
  const double r = bodies_.radius[i];
  const double touching = tolerance::kTouchFraction * r;
  for (const StaticRef shape : cells_.staticsNear(i))
    if (engine_.staticContact(i, shape, centre).gap < -touching) return false;
  bool clear = true;
  cells_.forEachNeighbour(i, [&](int k) {
    const Vec3 d = centre - tracks_[k].motion.positionAt(now_, engine_.accelerationOf(k));
    clear = clear && d.norm() - r - bodies_.radius[k] >= -touching;
  });
  return clear;
}

// Ball i's cluster: i and the slow balls that touch it within the support gap, and theirs,
// breadth first up to kMaxClusterBalls. They are solved together, loads included: three slow
// balls in a frictionless pyramid are not held, though each alone would be. Resting balls, and
// balls past the limit, count as fixed, as statics do, except `freed`, a resting ball that
// takes part as the slow ones do.
bool RestCheck::clusterHolds(int i, int freed) const {
  std::vector<int> members{i};
  std::vector<Vec3> centres{tracks_[i].motion.positionAt(now_, engine_.accelerationOf(i))};
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
      const auto [n, gap, restitution] = engine_.staticContact(k, shape, centres[c]);
      if (gap <= tolerance::kSupportGapFraction * rk)
        contacts.push_back({static_cast<int>(c), -1, n, frictionWith(k, {.shape = shape})});
    }
    cells_.forEachNeighbour(k, [&](int m) {
      const int known = memberIndex(m);
      if (known >= 0 && known < static_cast<int>(c)) return;  // that contact is listed already
      const bool resting = particles_[m].resting;
      if (!resting && !slow(m)) return;
      const Vec3 centre = known >= 0
                              ? centres[known]
                              : tracks_[m].motion.positionAt(now_, engine_.accelerationOf(m));
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
      contacts.push_back(
          {static_cast<int>(c), other, d.normalized(), frictionWith(k, {.ball = m})});
    });
  }
  if (members.size() == 1) return true;  // alone among fixed supports: restCheck decided it
  std::vector<double> masses(members.size()), radii(members.size());
  for (std::size_t c = 0; c < members.size(); ++c) {
    masses[c] = bodies_.mass[members[c]];
    radii[c] = bodies_.radius[members[c]];
  }
  return contactForcesBalance(gravity_, masses, radii, contacts, tolerance::kForceBalance);
}

}  // namespace carom
