#pragma once
// A ball's path between events: constant acceleration from a reference time, so a parabola under
// gravity and a straight line without it. Positions are evaluated lazily at any later time.

#include "scene.h"

namespace carom {

struct Motion {
  Vec3 position = Vec3::Zero();      // at `since`
  Vec3 velocity = Vec3::Zero();      // at `since`
  Vec3 acceleration = Vec3::Zero();  // gravity for a free ball, zero at rest or inside a sweep
  double since = 0.0;

  Vec3 positionAt(double t) const {
    const double dt = t - since;
    return position + dt * (velocity + (0.5 * dt) * acceleration);
  }
  Vec3 velocityAt(double t) const { return velocity + (t - since) * acceleration; }
  void moveTo(double t) {
    position = positionAt(t);
    velocity = velocityAt(t);
    since = t;
  }
};

}  // namespace carom
