#pragma once
// The time steps of `swept` and `discrete`, counted by index rather than summed.

#include <cmath>
#include <cstdint>
#include <limits>

namespace carom {

// Whole steps of `timeStep` counted by index from a time origin, so that step k ends at
// origin + k * timeStep however the run is cut into calls. Summing step lengths instead drifts by
// rounding, and a target that the drift put a hair past a step's end cost a sliver step.
class StepClock {
 public:
  StepClock(double origin, double timeStep)
      : origin_(origin), timeStep_(timeStep), stepEnd_(origin), now_(origin) {}

  // The time reached: the last step's end, or the target it was asked for when that was within
  // rounding of the step's end.
  double now() const { return now_; }

  // Calls step(h, stepEnd) for each step that takes the clock to `end`: whole steps of
  // h = timeStep ending on the clock's own step ends and, when `end` falls inside a step, a last
  // one shortened to meet it. A target within rounding of a step's end is that step's end: whole
  // steps only, the same ones however the run is cut, and now() reads the target.
  template <typename StepFunction>
  void advanceTo(double end, StepFunction&& step) {
    if (!(end > now_)) return;
    const double position = (end - origin_) / timeStep_;  // in steps from the origin
    const double nearest = std::round(position);
    // The caller's target and the clock's step ends are each a few roundings of time off.
    const double slack = 1e-9 + 64.0 * std::numeric_limits<double>::epsilon() * position;
    const bool onStepEnd = std::abs(position - nearest) <= slack;
    const double lastWhole = onStepEnd ? nearest : std::floor(position);
    while (static_cast<double>(steps_) < lastWhole) advanceSteps(1, step);
    if (onStepEnd) {
      if (static_cast<double>(steps_) == nearest) now_ = end;
      return;
    }
    if (!(end > stepEnd_)) return;
    step(end - stepEnd_, end);
    // Later whole steps count from here.
    origin_ = end;
    steps_ = 0;
    stepEnd_ = end;
    now_ = end;
  }

  // Calls step(h, stepEnd) `count` times, for whole steps.
  template <typename StepFunction>
  void advanceSteps(std::uint64_t count, StepFunction&& step) {
    for (std::uint64_t k = 0; k < count; ++k) {
      ++steps_;
      stepEnd_ = origin_ + static_cast<double>(steps_) * timeStep_;
      step(timeStep_, stepEnd_);
      now_ = stepEnd_;
    }
  }

 private:
  double origin_;
  double timeStep_;
  std::uint64_t steps_ = 0;  // whole steps since origin_
  double stepEnd_;           // where the last step ended
  double now_;
};

}  // namespace carom
