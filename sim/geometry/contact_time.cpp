#include "sim/geometry/contact_time.h"

#include "sim/core/tolerances.h"
#include "sim/geometry/polynomial.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace carom {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();
// A straight approach's discriminant below this fraction of b^2 has lost at least half of its
// digits to cancellation (straightEntry).
constexpr double kCancelledDiscriminant = 1e-8;
// A capped cylinder's rim further than this many of its reaches (R + r) has a quartic whose
// terms lose at least half their digits to cancellation (ballCappedCylinderContactTime).
constexpr double kFarReaches = 1e4;

// Gap |u0 + u1 t + u2 t^2|^2 - rho^2 as a polynomial in t.
Polynomial squaredLengthMinus(const Vec3& u0, const Vec3& u1, const Vec3& u2, double rho) {
  Polynomial f;
  const double length = u0.norm();
  f.c[0] = (length - rho) * (length + rho);
  f.c[1] = 2.0 * u0.dot(u1);
  // Touching, with a rate along the normal within round-off of the speed
  // (kTangentRateFraction): its sign says nothing, and the next term (the speed across the
  // normal against the acceleration into the part) decides whether the path enters the part.
  // A ball sliding off a turned box's lower edge arrives there with a rate of 1e-17 of either
  // sign; the edge took a negative one for an approach and met the ball again and again at
  // the same instant, until the burst guard stopped it on the edge (test_boxes).
  if (std::abs(length - rho) <= tolerance::kTouchFraction * rho &&
      std::abs(f.c[1]) <= 2.0 * tolerance::kTangentRateFraction * length * u1.norm())
    f.c[1] = 0.0;
  f.c[2] = u1.squaredNorm() + 2.0 * u0.dot(u2);
  f.c[3] = 2.0 * u1.dot(u2);
  f.c[4] = u2.squaredNorm();
  return f;
}

// Same gap when the path is straight (u2 == 0): a quadratic with the cancellation-free
// (|u0| - rho)(|u0| + rho) constant term, so touching shapes give a gap of about zero.
double straightEntry(const Vec3& u0, const Vec3& u1, double rho, double horizon) {
  const double b = u0.dot(u1);
  if (b >= 0.0) return kNever;  // receding or sliding past: on a straight path it stays so
  const double a = u1.squaredNorm();
  const double length2 = u0.squaredNorm();
  // An approach within the round-off of the dot product is none: two touching balls whose
  // relative velocity is along their common tangent to a few ulps. The response computes the
  // same rate in another order and may find it receding: it then changes nothing, and the
  // contact, predicted again at once, looped at one instant (a bin of a Galton board,
  // test_contact_time). Skipping it changes no energy.
  if (b * b <= 1e-30 * a * length2) return kNever;
  // Touching, with a rate within round-off of the speed (kTangentRateFraction): a straight
  // path leaves the part, as squaredLengthMinus's next term would say.
  constexpr double kRoundOffRate2 =
      tolerance::kTangentRateFraction * tolerance::kTangentRateFraction;
  if (b * b <= kRoundOffRate2 * a * length2 &&
      std::abs(std::sqrt(length2) - rho) <= tolerance::kTouchFraction * rho)
    return kNever;
  // Most pairs miss by far: reject them on the cheap form before taking square roots, with
  // margins well above the rounding of the cheap form. (The contact comes no sooner than
  // c / (-2b).)
  const double roughC = length2 - rho * rho;
  if (roughC > 0.0 &&
      (b * b - a * roughC < -1e-12 * a * length2 || roughC > -2.0 * b * horizon * (1.0 + 1e-12)))
    return kNever;
  const double length = std::sqrt(length2);
  const double c = (length - rho) * (length + rho);
  if (c <= 0.0) return 0.0;  // touching or overlapping, and approaching
  double disc = b * b - a * c;
  // Approaching from many radii away, b^2 and a c agree in more digits than a double holds
  // (1e-12 m balls 1e9 m apart, head-on: 4e18 each, differing by 6e-23), and their difference
  // is round-off, which missed the contact. Lagrange's identity gives the same value as
  // a rho^2 - |u0 x u1|^2 without that cancellation; it is taken only when the first form has
  // lost so many digits, so that contacts found before keep their last bits.
  if (disc <= kCancelledDiscriminant * b * b) disc = a * rho * rho - u0.cross(u1).squaredNorm();
  if (disc <= 0.0) return kNever;  // misses, or only grazes
  const double t = c / (-b + std::sqrt(disc));
  return t <= horizon ? t : kNever;
}

// First time t >= 0 at which x0 + v t + a t^2 / 2 reaches zero going down, from x0 >= 0;
// a bounded closed form for the straight case, which needs no polynomial machinery.
double linearEntry(double gap, double rate, double horizon) {
  if (rate >= 0.0) return kNever;  // receding, or level: a straight path never turns back
  if (gap <= 0.0) return 0.0;
  const double t = gap / -rate;
  return t <= horizon ? t : kNever;
}

// First entry of |u0 + u1 t + u2 t^2| into rho, on a parabola or a straight path.
double sphereEntry(const Vec3& u0, const Vec3& u1, const Vec3& u2, double rho, double horizon) {
  if (u2.squaredNorm() == 0.0) return straightEntry(u0, u1, rho, horizon);
  // Too far to get within rho before the horizon however the path bends: no quartic to solve.
  // Most corners of a box beside a ball, and most neighbours in a pile of sliding balls, are.
  if (horizon < kNever) {
    const double distance = u0.norm();
    const double reach = (u1.norm() + u2.norm() * horizon) * horizon;
    if (distance - reach - rho > 1e-12 * (distance + reach)) return kNever;
  }
  return firstEntry(squaredLengthMinus(u0, u1, u2, rho), horizon);
}

// The times in [0, horizon] where a condition holds: a few closed intervals, ascending.
struct Intervals {
  struct Interval {
    double begin;
    double end;
  };
  // Six quadratic conditions meet in at most seven intervals.
  std::array<Interval, 8> items;
  int count = 0;
  void add(double begin, double end) {
    if (end > begin && count < static_cast<int>(items.size())) items[count++] = {begin, end};
  }
};

// Where a t^2 + b t + c <= 0 in [0, horizon]; a touch (a double root) is no interval.
Intervals nonPositive(double a, double b, double c, double horizon) {
  Intervals out;
  if (a == 0.0) {
    if (b == 0.0) {
      if (c <= 0.0) out.add(0.0, horizon);
    } else if (b > 0.0) {
      out.add(0.0, std::min(horizon, -c / b));
    } else {
      out.add(std::max(0.0, -c / b), horizon);
    }
    return out;
  }
  const double d = b * b - 4.0 * a * c;
  if (!(d > 0.0)) {
    if (a < 0.0) out.add(0.0, horizon);
    return out;
  }
  // Roots without cancellation: q / a and c / q.
  const double q = -0.5 * (b + std::copysign(std::sqrt(d), b));
  const double r0 = std::min(q / a, c / q), r1 = std::max(q / a, c / q);
  if (a > 0.0) {
    out.add(std::max(0.0, r0), std::min(horizon, r1));
  } else {
    out.add(0.0, std::min(horizon, r0));
    out.add(std::max(0.0, r1), horizon);
  }
  return out;
}

Intervals intersect(const Intervals& x, const Intervals& y) {
  Intervals out;
  for (int i = 0, j = 0; i < x.count && j < y.count;) {
    out.add(std::max(x.items[i].begin, y.items[j].begin), std::min(x.items[i].end, y.items[j].end));
    (x.items[i].end < y.items[j].end ? i : j)++;
  }
  return out;
}

// Where |x(t)| <= bound for x(t) = x0 + v t + a t^2 / 2.
Intervals withinSlab(double x0, double v, double a, double bound, double horizon) {
  return intersect(nonPositive(0.5 * a, v, x0 - bound, horizon),
                   nonPositive(-0.5 * a, -v, -x0 - bound, horizon));
}

// The path u0 + u1 t + u2 t^2 restarted at time t0.
struct Rebased {
  Vec3 u0, u1, u2;
};

Rebased rebase(const Vec3& u0, const Vec3& u1, const Vec3& u2, double t0) {
  return {u0 + (u1 + u2 * t0) * t0, u1 + 2.0 * t0 * u2, u2};
}

// When a path inside a part (gap <= 0) first leaves it: the first entry of the negated gap.
double exitTime(Polynomial gap, double horizon) {
  for (double& c : gap.c) c = -c;
  return firstEntry(gap, horizon);
}

// The first entry of |u(t)| into rho within [0, end], for a part of the capped cylinder that the
// ball may be inside at the start without having entered it (touching a face and leaving, or
// sliding on it): then the part is entered again only after the path has left it.
double reentry(const Vec3& u0, const Vec3& u1, const Vec3& u2, double rho, double end, bool inside,
               bool approaching) {
  if (!inside) return sphereEntry(u0, u1, u2, rho, end);
  if (approaching) return 0.0;
  const double exit = exitTime(squaredLengthMinus(u0, u1, u2, rho), end);
  if (!(exit < end)) return kNever;
  const Rebased after = rebase(u0, u1, u2, exit);
  const double t = sphereEntry(after.u0, after.u1, after.u2, rho, end - exit);
  return t < kNever ? exit + t : kNever;
}

// (|q|^2 + R^2 - r^2)^2 - 4 R^2 |q_xy|^2 along q(t) = q0 + q1 t + q2 t^2, the ball's centre
// relative to a rim's centre in coordinates where the cylinder's axis is z: negative inside the
// torus swept by a ball of radius r around the rim of radius R. It factors as
// (d^2 - r^2)(d'^2 - r^2), d and d' the distances to the nearest and farthest rim point, which
// gives the constant term without cancellation. Degree 8 on a parabola, 4 on a straight path.
Polynomial rimGap(const Vec3& q0, const Vec3& q1, const Vec3& q2, double R, double r) {
  const std::array<double, 5> s{q0.squaredNorm() + R * R - r * r, 2.0 * q0.dot(q1),
                                q1.squaredNorm() + 2.0 * q0.dot(q2), 2.0 * q1.dot(q2),
                                q2.squaredNorm()};
  const Vec3 u0(q0.x(), q0.y(), 0.0), u1(q1.x(), q1.y(), 0.0), u2(q2.x(), q2.y(), 0.0);
  const std::array<double, 5> p{u0.squaredNorm(), 2.0 * u0.dot(u1),
                                u1.squaredNorm() + 2.0 * u0.dot(u2), 2.0 * u1.dot(u2),
                                u2.squaredNorm()};
  Polynomial f;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) f.c[i + j] += s[i] * s[j];
  for (int k = 0; k < 5; ++k) f.c[k] -= 4.0 * R * R * p[k];
  const double rho = u0.norm();
  const double nearest = std::hypot(rho - R, q0.z());
  const double farthest = std::hypot(rho + R, q0.z());
  f.c[0] = (nearest - r) * (nearest + r) * ((farthest - r) * (farthest + r));
  return f;
}

double ballCappedCylinderContactTime(const BallPath& ball, double radius,
                                     const CylinderShape& cylinder, double horizon) {
  // Coordinates with the axis as z and the origin at the middle of the axis.
  Eigen::Matrix3d frame;
  frame.col(2) = cylinder.axis;
  frame.col(0) = cylinder.axis.unitOrthogonal();
  frame.col(1) = frame.col(2).cross(frame.col(0));
  const Vec3 p = frame.transpose() * (ball.position - cylinder.point);
  const Vec3 v = frame.transpose() * ball.velocity;
  const Vec3 a = 0.5 * (frame.transpose() * ball.acceleration);  // p + v t + a t^2
  const double R = cylinder.radius;
  const double H = cylinder.halfLength;
  // The ball that cannot enter the bounding sphere grown by its radius cannot enter the cylinder.
  const double bound = std::hypot(R, H) + radius;
  if (p.squaredNorm() > bound * bound && sphereEntry(p, v, a, bound, horizon) == kNever)
    return kNever;
  const CylinderShape::Contact now = cylinder.contact(ball.position, radius);
  const double rate = now.normal.dot(ball.velocity);
  const bool approaching = rate < 0.0 || (rate == 0.0 && now.normal.dot(ball.acceleration) < 0.0);
  const auto across = [](const Vec3& x) { return Vec3(x.x(), x.y(), 0.0); };
  double first = kNever;
  // On a cap now with a normal speed of round-off (kTangentRateFraction), as on a box's face:
  // the ball meets the cap at once when gravity presses it in and it would sink deeper than
  // touching before its centre leaves the disc (`leave`, where it passes the rim).
  const auto meetsCapNow = [&](const Rebased& u, double alongEnd) {
    if (std::abs(v.z()) > tolerance::kTangentRateFraction * ball.velocity.norm())
      return approaching;
    const double side = p.z() >= 0.0 ? 1.0 : -1.0;
    if (!(side * a.z() < 0.0)) return false;
    const double leave = exitTime(squaredLengthMinus(u.u0, u.u1, u.u2, R), alongEnd);
    if (!(leave < kNever)) return true;
    const double depth = H + radius - side * (p.z() + (v.z() + a.z() * leave) * leave);
    return depth > tolerance::kTouchFraction * radius;
  };
  // The side grown by the radius within the length, and the caps grown by the radius within the
  // radius: a disc condition across the axis while the path is within a slab along it.
  const auto slabPart = [&](double halfThickness, double rho, bool cap) {
    const Intervals along = withinSlab(p.z(), v.z(), 2.0 * a.z(), halfThickness, kNever);
    for (int n = 0; n < along.count; ++n) {
      const double t0 = along.items[n].begin;
      if (t0 > std::min(horizon, first)) return;
      const Rebased u = rebase(across(p), across(v), across(a), t0);
      const double end = std::min(along.items[n].end, horizon) - t0;
      // Entering the slab inside the disc is entering through the slab's face.
      const bool inside = u.u0.norm() <= rho;
      double t;
      if (t0 > 0.0)
        t = inside ? 0.0 : sphereEntry(u.u0, u.u1, u.u2, rho, end);
      else
        t = reentry(u.u0, u.u1, u.u2, rho, end, inside,
                    inside && (cap ? meetsCapNow(u, along.items[n].end - t0) : approaching));
      if (t < kNever) {
        first = std::min(first, t0 + t);
        return;
      }
    }
  };
  slabPart(H, R + radius, false);
  slabPart(H + radius, R, true);
  // A rim thinner than the ball makes a spindle torus, which holds the sphere of radius
  // sqrt(r^2 - R^2) around its centre. Its quartic is negative only while the nearest rim point
  // is within r and the farthest is not, 2 R l / (r v) for a path l from the axis: at 1e12 m/s
  // past a rod of 1e-7 m, 1e-23 s, less than the time's resolution, and the ball went through.
  // Where the quartic finds no entry, the path's entry into that sphere is the rim's contact
  // (late by about the rim's radius); where it finds one, that one stands.
  const auto spindleEntry = [&](const Rebased& q, double end) {
    if (!(R < radius)) return kNever;
    return sphereEntry(q.u0, q.u1, q.u2, std::sqrt((radius - R) * (radius + R)), end);
  };
  // The rims: tori around the cap circles.
  for (const double side : {-1.0, 1.0}) {
    const Vec3 q0 = p - Vec3(0.0, 0.0, side * H);
    // The torus lies within the sphere of radius R + r around the rim's centre.
    const double reach = R + radius;
    const double near = q0.squaredNorm() > reach * reach
                            ? sphereEntry(q0, v, a, reach, std::min(horizon, first))
                            : 0.0;
    if (near == kNever) continue;  // never near this rim
    if (q0.squaredNorm() > kFarReaches * kFarReaches * reach * reach) {
      // From so far the quartic's terms agree in more than half their digits, and its root
      // was lost (a ball 1e11 m out missed the rim): solved from where the path enters the
      // sphere instead. Outside the torus there, and nearer ones keep their last bits.
      const Rebased q = rebase(q0, v, a, near);
      double t = firstEntry(rimGap(q.u0, q.u1, q.u2, R, radius), std::min(horizon, first) - near);
      if (!(t < kNever)) t = spindleEntry(q, std::min(horizon, first) - near);
      if (t < kNever) first = std::min(first, near + t);
      continue;
    }
    const Polynomial gap = rimGap(q0, v, a, R, radius);
    const bool inside = gap.c[0] <= 0.0;
    if (inside && approaching) {
      first = 0.0;
      continue;
    }
    Polynomial f = gap;
    double start = 0.0;
    if (inside) {
      // Touching the rim and leaving: entered again only after being clear of it.
      start = exitTime(gap, std::min(horizon, first));
      if (!(start < kNever)) continue;
      const Rebased q = rebase(q0, v, a, start);
      f = rimGap(q.u0, q.u1, q.u2, R, radius);
    }
    double t = firstEntry(f, std::min(horizon, first) - start);
    if (!(t < kNever) && !inside) t = spindleEntry({q0, v, a}, std::min(horizon, first));
    if (t < kNever) first = std::min(first, start + t);
  }
  return first <= horizon ? first : kNever;
}

}  // namespace

double ballBoxContactTime(const BallPath& ball, double radius, const BoxShape& box,
                          double horizon) {
  const Vec3 p = box.toLocal(ball.position);
  const Vec3 v = box.axes.transpose() * ball.velocity;
  const Vec3 a = box.axes.transpose() * ball.acceleration;
  const Vec3 h = box.half;
  // Most boxes are out of reach: the ball that cannot enter the box's bounding sphere grown by
  // its radius cannot enter the box.
  const double bound = h.norm() + radius;
  if (p.squaredNorm() > bound * bound && sphereEntry(p, v, 0.5 * a, bound, horizon) == kNever)
    return kNever;
  // Touching or overlapping now: a contact at once when it approaches, as for every shape; when
  // it leaves, the pieces it is inside now are not entered again until it has left them.
  const BoxShape::Contact now = box.contact(ball.position, radius);
  const double rate = now.normal.dot(ball.velocity);
  const bool approaching = rate < 0.0 || (rate == 0.0 && now.normal.dot(ball.acceleration) < 0.0);
  double first = kNever;
  const auto consider = [&](double t) { first = std::min(first, t); };
  // On face k now with a normal speed of round-off (kTangentRateFraction), its sign says
  // nothing: the ball meets the face at once when its acceleration presses it in and it would
  // sink deeper than touching before it is off the face (at `end`, past an edge). A ball
  // sliding off a turned box's lower edge is on the face by round-off: the face's plain rule
  // met it there again and again, until the burst guard stopped it on the edge.
  const auto meetsFaceNow = [&](int k, double end) {
    const double side = p[k] >= 0.0 ? 1.0 : -1.0;
    if (std::abs(v[k]) > tolerance::kTangentRateFraction * ball.velocity.norm()) return approaching;
    if (!(side * a[k] < 0.0)) return false;
    if (!(end < kNever)) return true;
    const double depth = h[k] + radius - side * (p[k] + (v[k] + 0.5 * a[k] * end) * end);
    return depth > tolerance::kTouchFraction * radius;
  };
  // The pieces' intervals run to infinity, so that an entry at the horizon itself counts.
  // The face slabs: the box grown by the radius along one axis only.
  for (int k = 0; k < 3; ++k) {
    Intervals inside = withinSlab(p[k], v[k], a[k], h[k] + radius, kNever);
    for (int j = 1; j < 3; ++j) {
      const int m = (k + j) % 3;
      inside = intersect(inside, withinSlab(p[m], v[m], a[m], h[m], kNever));
    }
    for (int n = 0; n < inside.count; ++n) {
      const double begin = inside.items[n].begin;
      if (begin > 0.0 || (begin == 0.0 && meetsFaceNow(k, inside.items[n].end))) {
        consider(begin);
        break;
      }
    }
  }
  // The edge cylinders: along axis k, within its extent, around each of its four edges.
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const Intervals along = withinSlab(p[k], v[k], a[k], h[k], kNever);
    for (const double si : {-1.0, 1.0}) {
      for (const double sj : {-1.0, 1.0}) {
        for (int n = 0; n < along.count; ++n) {
          const double t0 = along.items[n].begin;
          if (t0 > horizon) break;
          const Vec3 u0(p[i] + (v[i] + 0.5 * a[i] * t0) * t0 - si * h[i],
                        p[j] + (v[j] + 0.5 * a[j] * t0) * t0 - sj * h[j], 0.0);
          const Vec3 u1(v[i] + a[i] * t0, v[j] + a[j] * t0, 0.0);
          const Vec3 u2(0.5 * a[i], 0.5 * a[j], 0.0);
          // Entering the extent inside the cylinder is entering through its end, which lies
          // within the corner ball: found there too, and no later than here.
          double t =
              t0 > 0.0 && u0.norm() <= radius
                  ? 0.0
                  : sphereEntry(u0, u1, u2, radius, std::min(along.items[n].end, horizon) - t0);
          if (t < kNever) {
            consider(t0 + t);
            break;
          }
        }
      }
    }
  }
  // The corner balls.
  for (const double sx : {-1.0, 1.0})
    for (const double sy : {-1.0, 1.0})
      for (const double sz : {-1.0, 1.0})
        consider(sphereEntry(p - Vec3(sx * h[0], sy * h[1], sz * h[2]), v, 0.5 * a, radius,
                             std::min(horizon, first)));
  return first <= horizon ? first : kNever;
}

double ballPlaneContactTime(const BallPath& ball, double radius, const PlaneShape& plane,
                            double horizon) {
  const double gap = plane.gap(ball.position, radius);
  const double normalAcceleration = plane.normal.dot(ball.acceleration);
  const double normalVelocity = plane.normal.dot(ball.velocity);
  if (normalAcceleration == 0.0) return linearEntry(gap, normalVelocity, horizon);
  return firstEntryQuadratic(0.5 * normalAcceleration, normalVelocity, gap, horizon);
}

double ballCylinderContactTime(const BallPath& ball, double radius, const CylinderShape& cylinder,
                               double horizon) {
  if (cylinder.capped()) return ballCappedCylinderContactTime(ball, radius, cylinder, horizon);
  const Vec3 u0 = cylinder.perpendicular(ball.position - cylinder.point);
  const Vec3 u1 = cylinder.perpendicular(ball.velocity);
  const Vec3 u2 = 0.5 * cylinder.perpendicular(ball.acceleration);
  const double rho = cylinder.radius + radius;
  // Gravity along the axis (or none) keeps the perpendicular path straight: a quadratic.
  if (u2.squaredNorm() == 0.0) return straightEntry(u0, u1, rho, horizon);
  return firstEntry(squaredLengthMinus(u0, u1, u2, rho), horizon);
}

double ballBallContactTime(const BallPath& a, const BallPath& b, double radiusSum, double horizon) {
  const Vec3 u0 = b.position - a.position;
  const Vec3 u1 = b.velocity - a.velocity;
  const Vec3 u2 = 0.5 * (b.acceleration - a.acceleration);
  // Free balls share gravity, so relative paths are straight unless one of them rests or
  // slides.
  return sphereEntry(u0, u1, u2, radiusSum, horizon);
}

double ballBallStraightContactTime(const Vec3& relativePosition, const Vec3& relativeVelocity,
                                   double radiusSum, double horizon) {
  return straightEntry(relativePosition, relativeVelocity, radiusSum, horizon);
}

double circleExitTime(const Vec3& u0, const Vec3& u1, const Vec3& u2, double rho, double horizon) {
  return exitTime(squaredLengthMinus(u0, u1, u2, rho), horizon);
}

double boundaryCrossingTime(double x0, double v, double a, double bound, bool upwards,
                            double horizon) {
  const double sign = upwards ? 1.0 : -1.0;
  if (a == 0.0) return linearEntry(sign * (bound - x0), -sign * v, horizon);
  return firstEntryQuadratic(-0.5 * sign * a, -sign * v, sign * (bound - x0), horizon);
}

}  // namespace carom
