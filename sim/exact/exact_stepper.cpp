// `exact`: event-driven. Balls follow their true paths (parabolas under gravity) from event to
// event; every contact time is solved for.

#include "sim/dynamics/stepper.h"
#include "sim/exact/event_engine.h"

namespace carom {
namespace {

class ExactStepper final : public Stepper {
 public:
  ExactStepper(const Bodies& bodies, const StepperSettings& settings,
               const std::vector<BallState>& state, double now)
      : gravity_(settings.gravity),
        timeStep_(settings.timeStep),
        engine_(bodies, state, now, settings.gravity, settings.gravity, settings.collapseSpeed) {}

  void advanceTo(double end, RunStats& stats, std::vector<CollisionRecord>* log) override {
    engine_.advanceTo(end, stats, log);
  }
  void advanceSteps(std::uint64_t count, RunStats& stats,
                    std::vector<CollisionRecord>* log) override {
    engine_.advanceTo(engine_.now() + static_cast<double>(count) * timeStep_, stats, log);
  }
  double now() const override { return engine_.now(); }
  std::unique_ptr<Stepper> clone() const override { return std::make_unique<ExactStepper>(*this); }
  std::size_t memoryBytes() const override { return engine_.memoryBytes(); }
  void hold(int ball, const Vec3& velocity, RunStats& stats) override {
    engine_.hold(ball, velocity, stats);
  }
  void release(const Vec3& velocity) override { engine_.release(velocity); }
  void place(const Vec3& position) override { engine_.place(position); }
  std::optional<GrabStop> takeGrabStop() override { return engine_.takeGrabStop(); }
  std::vector<BallState> state() const override { return engine_.state(); }
  std::vector<std::string> notes() const override {
    std::vector<std::string> notes{"exact: event-driven, contact times solved, never sampled"};
    notes.push_back(gravity_.isZero() ? "no gravity: straight paths, quadratic contact times"
                                      : "gravity: parabolic paths; cylinder contacts are quartics");
    notes.push_back(engine_.gridSummary());
    return notes;
  }

 private:
  Vec3 gravity_;
  double timeStep_;
  EventEngine engine_;
};

}  // namespace

std::unique_ptr<Stepper> makeExactStepper(const Bodies& bodies, const StepperSettings& settings,
                                          const std::vector<BallState>& state, double now) {
  return std::make_unique<ExactStepper>(bodies, settings, state, now);
}

}  // namespace carom
