#include "sim/contact_time.h"

#include "sim/polynomial.h"

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

}  // namespace

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
