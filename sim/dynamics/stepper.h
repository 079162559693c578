#pragma once
// One stepping loop per method, behind one interface so the simulation can switch between them
// live: exact_stepper.cpp, swept_stepper.cpp, discrete_stepper.cpp.

#include "sim/dynamics/bodies.h"
#include "sim/dynamics/grab.h"
#include "sim/dynamics/run_stats.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
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

  // A copy that goes on exactly as this one would (its bodies are the same object).
  virtual std::unique_ptr<Stepper> clone() const = 0;
  // The memory the stepper holds, in bytes (its vectors' capacities).
  virtual std::size_t memoryBytes() const = 0;

  // The held ball (grab.h): `ball` follows a straight path at `velocity` from now on, with no
  // gravity and unlimited mass, until released; at most one ball is held. Holding another
  // releases the first at rest.
  virtual void hold(int ball, const Vec3& velocity, RunStats& stats) = 0;
  // The held ball is free again, at `velocity`.
  virtual void release(const Vec3& velocity) = 0;
  // Moves the held ball to `position` at now(), no time passing; the caller has made sure it
  // overlaps nothing there (Simulation::moveGrabbed).
  virtual void place(const Vec3& position) = 0;
  // Why the grab stopped since last asked, if it did: the held ball then stands still.
  virtual std::optional<GrabStop> takeGrabStop() = 0;
};

// `bodies` must outlive the stepper.
std::unique_ptr<Stepper> makeExactStepper(const Bodies& bodies, const StepperSettings& settings,
                                          const std::vector<BallState>& state, double now);
std::unique_ptr<Stepper> makeSweptStepper(const Bodies& bodies, const StepperSettings& settings,
                                          const std::vector<BallState>& state, double now);
std::unique_ptr<Stepper> makeDiscreteStepper(const Bodies& bodies, const StepperSettings& settings,
                                             const std::vector<BallState>& state, double now);

}  // namespace carom
