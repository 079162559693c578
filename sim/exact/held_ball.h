#pragma once
// Which ball the user holds in the event engine (grab.h), why the grab stopped, and the held
// ball's burst guard. How the held ball moves and meets others is the engine's
// (engine_grab.cpp).

#include "sim/core/tolerances.h"
#include "sim/dynamics/grab.h"
#include "sim/model/scene.h"

#include <limits>
#include <optional>

namespace carom {

class HeldBall {
 public:
  int ball() const { return ball_; }  // -1 when none is held
  // Holds ball i, with a fresh burst guard.
  void take(int i) {
    ball_ = i;
    pushesInBurst_ = 0;
    lastPush_ = -std::numeric_limits<double>::infinity();
  }
  void letGo() { ball_ = -1; }

  // The burst guard (kMaxCollisionsInBurst): counts a push at `now` by the held ball of radius
  // `radius` moving at `velocity`, and tells whether the pushes in a row, each after a
  // negligible travel, got it nowhere (a jam of several balls).
  bool jams(const Vec3& velocity, double radius, double now) {
    const double travel = velocity.norm() * (now - lastPush_);
    bool jammed = false;
    if (velocity.isZero() || travel > tolerance::kBurstTravelFraction * radius)
      pushesInBurst_ = 0;
    else
      jammed = ++pushesInBurst_ > tolerance::kMaxCollisionsInBurst;
    lastPush_ = now;
    return jammed;
  }

  void stop(const GrabStop& stop) { stop_ = stop; }
  std::optional<GrabStop> takeStop() {
    std::optional<GrabStop> stop;
    stop.swap(stop_);
    return stop;
  }

 private:
  int ball_ = -1;
  std::optional<GrabStop> stop_;
  // Pushes in a row, each after a negligible travel, and when the last one was.
  int pushesInBurst_ = 0;
  double lastPush_ = -std::numeric_limits<double>::infinity();
};

}  // namespace carom
