// `swept`: the tutorial's scheme done right. Each time step the integrator kicks velocities,
// then balls sweep along straight lines through the step with the same earliest-contact-first
// loop as `exact`, so nothing passes through anything at any speed or step.

#include "sim/event_engine.h"
#include "sim/integrator.h"
#include "sim/stepper.h"

namespace carom {
namespace {

class SweptStepper final : public Stepper {
 public:
  SweptStepper(const Bodies& bodies, const StepperSettings& settings,
               const std::vector<BallState>& state, double now)
      : settings_(settings),
        engine_(bodies, state, now, settings.gravity, Vec3::Zero(), settings.collapseSpeed) {}

  void advanceTo(double end, RunStats& stats, std::vector<CollisionRecord>* log) override {
    const KickSplit split = kickSplit(settings_.integrator);
    stepUntil(engine_.now(), end, settings_.timeStep, [&](double h) {
      engine_.setHorizon(engine_.now() + h);
      // The previous step's trailing kick and this step's leading one are given together.
      kick(pendingKick_ + split.before * h);
      pendingKick_ = split.after * h;
      engine_.advanceTo(engine_.now() + h, stats, log);
      ++stats.steps;
      stats.ballSteps += engine_.ballCount();
    });
  }
  double now() const override { return engine_.now(); }
  std::vector<BallState> state() const override {
    std::vector<BallState> state = engine_.state();
    for (BallState& s : state)
      if (!s.resting) s.velocity += pendingKick_ * settings_.gravity;
    return state;
  }
  std::vector<std::string> notes() const override {
    return {std::string("swept: ") + std::string(integratorName(settings_.integrator)) +
                " kicks, straight sweeps with earliest-contact-first inside each step",
            engine_.gridSummary()};
  }

 private:
  void kick(double seconds) {
    std::vector<Vec3> velocities(engine_.ballCount());
    for (int i = 0; i < engine_.ballCount(); ++i)
      velocities[i] = engine_.stateOf(i).velocity + seconds * settings_.gravity;
    engine_.setVelocities(velocities);
  }

  StepperSettings settings_;
  EventEngine engine_;
  double pendingKick_ = 0.0;  // seconds of gravity owed to the velocities since the last step
};

}  // namespace

std::unique_ptr<Stepper> makeSweptStepper(const Bodies& bodies, const StepperSettings& settings,
                                          const std::vector<BallState>& state, double now) {
  return std::make_unique<SweptStepper>(bodies, settings, state, now);
}

}  // namespace carom
