#pragma once
// A ball's path on a face while the direction it moves in turns: a slide whose slip runs across
// the fall line of a tilted face, or a roll across it against rolling resistance (FaceMotion's
// `turning`). Exact at every time through TurningDrag, of the slip or of the velocity; and, for
// the contact solvers, which take polynomial paths, the parabola that stands in for it over a
// segment short enough that the two never part by more than a given distance (docs/physics.md,
// "Friction and spin").

#include "sim/dynamics/face_friction.h"
#include "sim/dynamics/turning_drag.h"

namespace carom {

class TurningFacePath {
 public:
  // From velocity v and angular velocity w now, in `phase` (Sliding or Rolling, turning).
  TurningFacePath(const Vec3& v, const Vec3& w, double radius, const FaceFrame& face,
                  const ContactFriction& friction, FacePhase phase);

  struct State {
    Vec3 displacement;  // of the centre since the start
    Vec3 velocity;
    Vec3 spinAlong;  // the angular velocity's part along the face (its part about the
                     // normal follows spinning friction, SpinPath)
  };
  // At time t >= 0 after the start.
  State at(double t) const;
  // When the phase ends by itself: the slip or the ball stops (infinity when it never does).
  double end() const { return drag_.stopTime(); }

  // The parabola from the start (the exact position and velocity, and `acceleration`) that meets
  // the path again at `duration` and stays within `deviation` of it in between, and the constant
  // angular acceleration that takes the spin to its value there. No shorter than `shortest`
  // (the clock's resolution: a segment that ends when it starts would start again forever)
  // unless the path ends before; parted by at most deviationBound(shortest) there.
  struct Segment {
    double duration;
    Vec3 acceleration;
    Vec3 angularAcceleration;
  };
  Segment segment(double deviation, double shortest) const;

 private:
  // How far the parabola through the path's ends at t may part from the path: its acceleration
  // is an average of the path's, whose direction turns by the angle swept, so the two
  // accelerations differ by at most centreDrag·angle, and a gap that is zero at both ends and
  // whose second derivative is at most M stays within M·t²/8.
  double deviationBound(double t) const;

  // What turns: the slip u = v - r·ω×n of a slide, pulled by g_t and held back by 7/2·μ·g_n
  // (the force μ·g_n on the centre and its torque on the spin); the velocity of a roll, pulled
  // by 5/7·g_t and held back by μ_r·g_n.
  struct Turning {
    Vec3 from, pull;
    double drag;
    double centreDrag;  // the friction force's size per unit mass on the centre
  };
  static Turning turningOf(const Vec3& v, const Vec3& w, double radius, const FaceFrame& face,
                           const ContactFriction& friction, bool sliding);

  bool sliding_;
  Turning turning_;
  TurningDrag drag_;
  Vec3 velocity_, along_, normal_;
  double radius_;
};

}  // namespace carom
