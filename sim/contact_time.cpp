#include "sim/contact_time.h"

#include "sim/polynomial.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace carom {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

// Gap |u0 + u1 t + u2 t^2|^2 - rho^2 as a polynomial in t.
Polynomial squaredLengthMinus(const Vec3& u0, const Vec3& u1, const Vec3& u2, double rho) {
  Polynomial f;
  const double length = u0.norm();
  f.c[0] = (length - rho) * (length + rho);
  f.c[1] = 2.0 * u0.dot(u1);
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
  const double disc = b * b - a * c;
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
      if (begin > 0.0 || approaching) {
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
        consider(
            sphereEntry(p - Vec3(sx * h[0], sy * h[1], sz * h[2]), v, 0.5 * a, radius, horizon));
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
  if (u2.squaredNorm() == 0.0) return straightEntry(u0, u1, radiusSum, horizon);
  return firstEntry(squaredLengthMinus(u0, u1, u2, radiusSum), horizon);
}

double ballBallStraightContactTime(const Vec3& relativePosition, const Vec3& relativeVelocity,
                                   double radiusSum, double horizon) {
  return straightEntry(relativePosition, relativeVelocity, radiusSum, horizon);
}

double boundaryCrossingTime(double x0, double v, double a, double bound, bool upwards,
                            double horizon) {
  const double sign = upwards ? 1.0 : -1.0;
  if (a == 0.0) return linearEntry(sign * (bound - x0), -sign * v, horizon);
  return firstEntryQuadratic(-0.5 * sign * a, -sign * v, sign * (bound - x0), horizon);
}

}  // namespace carom
