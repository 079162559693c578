#include "sim/dynamics/response.h"

#include <Eigen/Geometry>  // cross products

#include <algorithm>
#include <cmath>
#include <limits>

namespace carom {

double resolveBallBall(Vec3& va, Vec3& vb, double inverseMassA, double inverseMassB, const Vec3& n,
                       double restitution, double minimumSeparation, double lossless) {
  const double approach = (va - vb).dot(n);
  const double totalInverse = inverseMassA + inverseMassB;
  if (totalInverse <= 0.0) return approach;
  // A pair that (by round-off) already separates keeps separating at no less than the minimum.
  const double closing = std::max(approach, 0.0);
  const double separation =
      std::max(separationSpeed(closing, restitution, minimumSeparation, lossless), -approach);
  // Change of relative normal speed, shared in proportion to inverse mass; written with weights
  // rather than an impulse so that mass ratios of 1e12 lose nothing to rounding.
  const double change = approach + separation;
  va -= (change * (inverseMassA / totalInverse)) * n;
  vb += (change * (inverseMassB / totalInverse)) * n;
  return approach;
}

bool resolveAgainstSurface(Vec3& v, const Vec3& n, double restitution, double minimumSeparation) {
  const double approach = -v.dot(n);
  Vec3 tangential = v + approach * n;
  // A ball that (by round-off) already leaves the surface keeps its own speed if that is more.
  const double bounce = std::max(restitution * approach, -approach);
  double separation = bounce;
  bool addedEnergy = false;
  if (bounce < minimumSeparation) {
    separation = minimumSeparation;
    // Energy left for the tangential motion if the bounce is to add none.
    const double budget =
        tangential.squaredNorm() + approach * approach - minimumSeparation * minimumSeparation;
    const double tangential2 = tangential.squaredNorm();
    if (budget >= 0.0 && tangential2 > 0.0) {
      if (budget < tangential2) tangential *= std::sqrt(budget / tangential2);
    } else {
      addedEnergy = true;
    }
  }
  v = tangential + separation * n;
  return addedEnergy;
}

namespace {

// The change in the contact point's tangential velocity u that Walton's law asks for, -(1+β)·u,
// cut to the Coulomb limit: for solid spheres a tangential impulse J changes u by 7/2·J·w (w the
// inverse mass, summed over a pair), and |J| ≤ μ·(normal impulse) = μ·normalChange/w.
Vec3 slipChange(const Vec3& u, const Vec3& n, double normalChange, const ImpactFriction& law) {
  const Vec3 tangential = u - u.dot(n) * n;
  Vec3 change = -(1.0 + law.tangentialRestitution) * tangential;
  const double limit = 3.5 * law.friction * std::max(normalChange, 0.0);
  const double size = change.norm();
  if (size > limit) change *= limit / size;  // sliding: the limit binds
  return change;
}

}  // namespace

void applyImpactFriction(Vec3& va, Vec3& wa, Vec3& vb, Vec3& wb, double ra, double rb,
                         double inverseMassA, double inverseMassB, const Vec3& n,
                         double normalChange, const ImpactFriction& law) {
  const double totalInverse = inverseMassA + inverseMassB;
  if (totalInverse <= 0.0) return;
  const Vec3 u = va - vb + (ra * wa + rb * wb).cross(n);
  const Vec3 change = slipChange(u, n, normalChange, law) / 3.5;
  // As in resolveBallBall, shared by weights rather than impulses.
  const Vec3 dva = change * (inverseMassA / totalInverse);
  const Vec3 dvb = -change * (inverseMassB / totalInverse);
  va += dva;
  vb += dvb;
  wa += (2.5 / ra) * n.cross(dva);
  wb -= (2.5 / rb) * n.cross(dvb);
}

void applyImpactFriction(Vec3& v, Vec3& w, double r, const Vec3& n, double normalChange,
                         const ImpactFriction& law) {
  const Vec3 u = v - r * w.cross(n);
  const Vec3 dv = slipChange(u, n, normalChange, law) / 3.5;
  v += dv;
  w -= (2.5 / r) * n.cross(dv);
}

std::optional<WedgeReflections> reflectInWedge(const Vec3& v, const Vec3& n0, const Vec3& n1) {
  Vec3 crease = n0.cross(n1);
  const double sine = crease.norm();
  if (!(sine > 0.0)) return std::nullopt;
  crease /= sine;
  // Across the crease: x along plane 0 into the wedge, y its normal; plane 1 runs at angle θ.
  Vec3 x = crease.cross(n0);
  if (x.dot(n1) < 0.0) x = -x;
  Vec3 along1 = crease.cross(n1);
  if (along1.dot(n0) < 0.0) along1 = -along1;
  const double theta = std::atan2(along1.dot(n0), along1.dot(x));
  const double vx = v.dot(x), vy = v.dot(n0), vc = v.dot(crease);
  const double speed = std::hypot(vx, vy);
  double psi = std::atan2(vy, vx);
  const bool intoFirst = v.dot(n0) < 0.0;
  if (!intoFirst && !(v.dot(n1) < 0.0)) return std::nullopt;
  // Met first is plane 0, or else plane 1, seen in the wedge mirrored across its bisector.
  if (!intoFirst) psi = theta - psi;
  if (psi > M_PI) psi -= 2.0 * M_PI;
  const double psi1 = -psi;  // after the first reflection, in (0, π)
  // After 2m+1 reflections the angle is psi1 - 2mθ, out when at most θ; after 2m+2 it is
  // (2m+2)θ - psi1, out when at least 0.
  const double turns = psi1 / theta;
  const double oddReflections = 2.0 * std::ceil(std::max((turns - 1.0) / 2.0, 0.0)) + 1.0;
  const double evenReflections = 2.0 * std::ceil(turns / 2.0);
  const double reflections = std::min(oddReflections, evenReflections);
  double out = reflections == oddReflections ? psi1 - (reflections - 1.0) * theta
                                             : reflections * theta - psi1;
  if (!intoFirst) out = theta - out;
  WedgeReflections result;
  result.velocity = vc * crease + speed * (std::cos(out) * x + std::sin(out) * n0);
  // Planes a few ulps from parallel take more reflections than a count holds: counted as many
  // as it can.
  constexpr double kMostCounted = 1.8e19;
  const std::uint64_t total = reflections < kMostCounted
                                  ? static_cast<std::uint64_t>(reflections)
                                  : std::numeric_limits<std::uint64_t>::max();
  const int first = intoFirst ? 0 : 1;
  result.count[first] = total / 2 + (total & 1);
  result.count[1 - first] = total / 2;
  const Vec3& nFirst = intoFirst ? n0 : n1;
  const Vec3& nSecond = intoFirst ? n1 : n0;
  result.approach[first] = -v.dot(nFirst);
  const Vec3 once = v - 2.0 * v.dot(nFirst) * nFirst;
  result.approach[1 - first] = std::max(-once.dot(nSecond), 0.0);
  return result;
}

double restoreSpecificEnergy(Vec3& v, const Vec3& position, const Vec3& gravity, double energy) {
  const Vec3 down = gravity.normalized();
  const double along = v.dot(down);
  const Vec3 across = v - along * down;
  const double twiceKinetic = 2.0 * (energy + gravity.dot(position));
  const double along2 = twiceKinetic - across.squaredNorm();
  if (along2 >= 0.0) {
    v = across + std::copysign(std::sqrt(along2), along) * down;
    return 0.0;
  }
  if (twiceKinetic > 0.0) {
    v = across * std::sqrt(twiceKinetic / across.squaredNorm());
    return 0.0;
  }
  v.setZero();
  return -0.5 * twiceKinetic;  // higher than its energy allows: the excess stays
}

}  // namespace carom
