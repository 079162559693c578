#pragma once
// One stepping loop per method, behind one interface so the simulation can switch between them
// live: exact_stepper.cpp, swept_stepper.cpp, discrete_stepper.cpp.

#include "sim/bodies.h"
#include "sim/run_stats.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace carom {

struct StepperSettings {
  Vec3 gravity = Vec3::Zero();
  double timeStep = 1.0 / 60.0;
  Integrator integrator = Integrator::SymplecticEuler;
  double collapseSpeed = 0.0;  // rest_policy.h
};

class Stepper {
 public:
  virtual ~Stepper() = default;
  // Advances to time `end` >= now(); `log`, when given, receives every collision.
  virtual void advanceTo(double end, RunStats& stats, std::vector<CollisionRecord>* log) = 0;
  // Advances by `count` whole time steps (`exact`: by that much time).
  virtual void advanceSteps(std::uint64_t count, RunStats& stats,
                            std::vector<CollisionRecord>* log) = 0;
  virtual double now() const = 0;
  virtual std::vector<BallState> state() const = 0;
  // What this method models, one short phrase each.
  virtual std::vector<std::string> notes() const = 0;
};

// `bodies` must outlive the stepper.
std::unique_ptr<Stepper> makeExactStepper(const Bodies& bodies, const StepperSettings& settings,
                                          const std::vector<BallState>& state, double now);
std::unique_ptr<Stepper> makeSweptStepper(const Bodies& bodies, const StepperSettings& settings,
                                          const std::vector<BallState>& state, double now);
std::unique_ptr<Stepper> makeDiscreteStepper(const Bodies& bodies, const StepperSettings& settings,
                                             const std::vector<BallState>& state, double now);

}  // namespace carom
