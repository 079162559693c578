// `swept`: the tutorial's scheme done right. Each time step the integrator kicks velocities,
// then balls sweep along straight lines through the step with the same earliest-contact-first
// loop as `exact`, so nothing passes through anything at any speed or step.

#include "sim/dynamics/stepper.h"
#include "sim/exact/event_engine.h"
#include "sim/stepped/integrator.h"
#include "sim/stepped/step_clock.h"

namespace carom {
namespace {

class SweptStepper final : public Stepper {
 public:
  SweptStepper(const Bodies& bodies, const StepperSettings& settings,
               const std::vector<BallState>& state, double now)
      : settings_(settings),
        engine_(bodies, state, now, settings.gravity, Vec3::Zero(), settings.collapseSpeed,
                settings.gravity.norm() * settings.timeStep),
        clock_(now, settings.timeStep) {}

  void advanceTo(double end, RunStats& stats, std::vector<CollisionRecord>* log) override {
    clock_.advanceTo(end, [&](double h, double stepEnd) { step(h, stepEnd, stats, log); });
  }
  void advanceSteps(std::uint64_t count, RunStats& stats,
                    std::vector<CollisionRecord>* log) override {
    clock_.advanceSteps(count, [&](double h, double stepEnd) { step(h, stepEnd, stats, log); });
  }
  double now() const override { return clock_.now(); }
  std::unique_ptr<Stepper> clone() const override { return std::make_unique<SweptStepper>(*this); }
  std::size_t memoryBytes() const override { return engine_.memoryBytes(); }
  void hold(int ball, const Vec3& velocity, RunStats& stats) override {
    engine_.hold(ball, velocity, stats);
  }
  void release(const Vec3& velocity) override { engine_.release(velocity); }
  void place(const Vec3& position) override { engine_.place(position); }
  std::optional<GrabStop> takeGrabStop() override { return engine_.takeGrabStop(); }
  std::vector<BallState> state() const override {
    std::vector<BallState> state = engine_.state();
    for (int i = 0; i < static_cast<int>(state.size()); ++i)
      if (!state[i].resting && i != engine_.held())
        state[i].velocity += pendingKick_ * settings_.gravity;
    return state;
  }
  std::vector<std::string> notes() const override {
    return {std::string("swept: ") + std::string(integratorName(settings_.integrator)) +
                " kicks, straight sweeps with earliest-contact-first inside each step",
            engine_.gridSummary()};
  }

 private:
  void step(double h, double stepEnd, RunStats& stats, std::vector<CollisionRecord>* log) {
    const KickSplit split = kickSplit(settings_.integrator);
    engine_.setHorizon(stepEnd);
    // The previous step's trailing kick and this step's leading one are given together.
    kick(pendingKick_ + split.before * h);
    pendingKick_ = split.after * h;
    engine_.advanceTo(stepEnd, stats, log);
    ++stats.steps;
    stats.ballSteps += engine_.ballCount();
  }

  void kick(double seconds) {
    std::vector<Vec3> velocities(engine_.ballCount());
    for (int i = 0; i < engine_.ballCount(); ++i)
      velocities[i] = engine_.stateOf(i).velocity + seconds * settings_.gravity;
    // The held ball feels no gravity (setVelocities leaves it alone).
    engine_.setVelocities(velocities);
  }

  StepperSettings settings_;
  EventEngine engine_;
  StepClock clock_;
  double pendingKick_ = 0.0;  // seconds of gravity owed to the velocities since the last step
};

}  // namespace

std::unique_ptr<Stepper> makeSweptStepper(const Bodies& bodies, const StepperSettings& settings,
                                          const std::vector<BallState>& state, double now) {
  return std::make_unique<SweptStepper>(bodies, settings, state, now);
}

}  // namespace carom
