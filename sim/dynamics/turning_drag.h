#pragma once
// A vector w on a face that a constant pull a·e drives and a drag of constant size k turns and
// shrinks: dw/dt = a·e - k·w/|w|. The slip of a ball sliding across the fall line of a tilted
// face obeys it (a = |g_t|, k = 7/2·μ·g_n), and so does the velocity of a ball rolling across it
// against rolling resistance (a = 5/7·|g_t|, k = μ_r·g_n). Neither has a polynomial path, but
// both have a closed form in s = tan(φ/2), φ the angle from e to w: with q = k/a,
//   w·e⊥ = C·s^q,  w·e = C·(s^(q-1) - s^(q+1))/2,
//   t(s) = C/(2a)·[(s0^(q-1) - s^(q-1))/(q-1) + (s0^(q+1) - s^(q+1))/(q+1)],
// and the integral of w over time is another such sum of powers of s (docs/physics.md, "Friction
// and spin"). s falls monotonically, so the s of a time is found by a bracketed Newton search to
// round-off. When q > 1, w reaches zero at a finite time (stopTime); otherwise it grows for
// ever while it turns towards e.

#include "sim/model/scene.h"

namespace carom {

class TurningDrag {
 public:
  // w0 must have a part across `pull`, both non-zero, and drag > 0.
  TurningDrag(const Vec3& w0, const Vec3& pull, double drag);

  struct State {
    Vec3 value;     // w(t)
    Vec3 integral;  // the integral of w from 0 to t
    double angle;   // φ(t), from e to w, in (0, π), or zero once w stopped
  };
  // At time t >= 0 after the start.
  State at(double t) const;
  // When w reaches zero: finite only when the drag beats the pull (q > 1).
  double stopTime() const { return stopTime_; }
  double startAngle() const;
  // How fast w's direction turns at the start (rad/s): a·sin φ0/|w0|.
  double startTurnRate() const;

 private:
  // The time at which ln(s0/s) = lambda, and its rate.
  double timeAt(double lambda) const;
  double rateAt(double lambda) const;
  double lambdaAt(double t) const;
  State stateAt(double lambda) const;

  Vec3 e_, across_;  // unit: along the pull, and across it towards w0
  double a_, q_;
  double s0_;       // tan(φ0/2)
  double across0_;  // w0·across (> 0)
  double plus_;     // |w0| + w0·e  = (w0·across)/s0
  double minus_;    // |w0| - w0·e  = (w0·across)·s0
  double stopTime_;
};

}  // namespace carom
