#pragma once
// A ball's path between events: constant acceleration from a reference time, so a parabola under
// gravity and a straight line without it. Positions are evaluated lazily at any later time. The
// acceleration is not stored: every free ball shares gravity, a ball sliding on a plane has
// gravity's component along it (one per plane), and a resting one has none.

#include "sim/model/scene.h"

namespace carom {

struct Motion {
  Vec3 position = Vec3::Zero();  // at `since`
  Vec3 velocity = Vec3::Zero();  // at `since`
  double since = 0.0;

  Vec3 positionAt(double t, const Vec3& acceleration) const {
    const double dt = t - since;
    return position + dt * (velocity + (0.5 * dt) * acceleration);
  }
  Vec3 velocityAt(double t, const Vec3& acceleration) const {
    return velocity + (t - since) * acceleration;
  }
  void moveTo(double t, const Vec3& acceleration) {
    position = positionAt(t, acceleration);
    velocity = velocityAt(t, acceleration);
    since = t;
  }
};

}  // namespace carom
