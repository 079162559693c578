#pragma once
// When shapes first touch: the contact-time math for every shape pair, in one place.
//
// Each function takes the states at a common "now" and returns the time from now until the
// shapes start to overlap, or +infinity when that does not happen before `horizon`. Shapes that
// already touch (or overlap) and approach give 0: such a contact fires at once. A contact that
// only grazes (touches and turns away) is not a collision. Times are never negative.

#include "sim/geometry/shapes.h"

#include <limits>

namespace carom {

// A ball's state at "now": centre, velocity and constant acceleration.
struct BallPath {
  Vec3 position;
  Vec3 velocity;
  Vec3 acceleration;
};

double ballPlaneContactTime(const BallPath& ball, double radius, const PlaneShape& plane,
                            double horizon);

double ballCylinderContactTime(const BallPath& ball, double radius, const CylinderShape& cylinder,
                               double horizon);

// The box grown by the ball's radius is the union of three face slabs, twelve edge cylinders
// and eight corner balls; its first entry is the earliest of theirs, each in closed form or as
// the first root of a quartic.
double ballBoxContactTime(const BallPath& ball, double radius, const BoxShape& box, double horizon);

// Balls a and b with radii summing to `radiusSum`.
double ballBallContactTime(const BallPath& a, const BallPath& b, double radiusSum, double horizon);

// The same when the balls' relative path is straight (both free under the same gravity, or no
// gravity): b's position and velocity relative to a's. The hot path of the event engine.
double ballBallStraightContactTime(const Vec3& relativePosition, const Vec3& relativeVelocity,
                                   double radiusSum, double horizon);

// Time until coordinate x(t) = x0 + v t + a t^2 / 2 first passes `bound` going upwards
// (x0 <= bound), or downwards when `upwards` is false; for moving balls between grid cells.
double boundaryCrossingTime(double x0, double v, double a, double bound, bool upwards,
                            double horizon);

// Time until |u0 + u1 t + u2 t^2|, within rho or at it, first passes rho going outwards: a ball
// sliding on a cap reaches its rim (u: the centre's offset across the axis). A quartic, a
// quadratic when u2 is zero (a level cap, or a straight sweep). 0 when at rho and moving out.
double circleExitTime(const Vec3& u0, const Vec3& u1, const Vec3& u2, double rho, double horizon);

// Time until a straight path x0 + v t leaves [lower, upper] (either may be infinite).
inline double straightExitTime(double x0, double v, double lower, double upper) {
  if (v > 0.0) return x0 < upper ? (upper - x0) / v : 0.0;
  if (v < 0.0) return x0 > lower ? (lower - x0) / v : 0.0;
  return std::numeric_limits<double>::infinity();
}

}  // namespace carom
