#pragma once
// The simulation of a scene under one of the three methods. This is the physics' public face:
// the CLI, the benchmarks and the GUI worker drive it.

#include "sim/dynamics/bodies.h"
#include "sim/dynamics/grab.h"
#include "sim/dynamics/run_stats.h"
#include "sim/model/scene.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace carom {

class Stepper;

class Simulation {
 public:
  // `scene` must be valid (validateScene(scene) empty); its world selects method and integrator.
  explicit Simulation(const Scene& scene);
  ~Simulation();
  // A copy goes on exactly as the original would, bit for bit, given the same calls (the
  // recording's keyframes, run_recording.h).
  Simulation(const Simulation& other);
  Simulation& operator=(const Simulation&) = delete;

  // Advances simulated time by `duration` (>= 0). `exact` goes from event to event and lands on
  // the target exactly; `swept` and `discrete` take steps of the world's time step, the last one
  // shortened so that the target is met. Their steps are counted from the time the world was
  // last set, so a target within rounding of a step's end takes whole steps only, however the
  // run is cut into calls (stepper.h, StepClock).
  void advance(double duration);
  // Advances to simulated time `time` (no-op when not after time()), as advance() does. Callers
  // cutting a run into pieces should give each piece's end here rather than its length, so
  // that the pieces' ends are not sums.
  void advanceTo(double time);
  // One whole step of the world's time step (`exact`: that much time).
  void step();

  double time() const;
  const World& world() const { return world_; }
  const Bodies& bodies() const { return *bodies_; }
  int ballCount() const { return bodies_->ballCount(); }

  // New world settings (valid), applied live from the current state on: the simulation
  // rebuilds what the changed fields need and keeps the balls where they are.
  void setWorld(const World& world);

  // Every ball at time(), in scene order.
  std::vector<BallState> state() const;
  std::vector<Vec3> positions() const;
  std::vector<Vec3> velocities() const;
  std::vector<Vec3> angularVelocities() const;

  // Of translation and rotation.
  double kineticEnergy() const;
  double potentialEnergy() const;  // relative to the origin: the sum of -m g . p
  double totalEnergy() const { return kineticEnergy() + potentialEnergy(); }
  Vec3 momentum() const;

  const RunStats& stats() const { return stats_; }
  // What the current method models and what it leaves out, one short phrase each.
  std::vector<std::string> modelNotes() const;

  // When on, every collision is recorded until taken (for explosions and sound).
  void setCollisionLog(bool on) { logCollisions_ = on; }
  std::vector<CollisionRecord> takeCollisions();

  // Grabbing (grab.h). `ball` is held where it is, still, until released; a ball already held
  // is released at rest first.
  void grab(int ball);
  // The held ball moves at `velocity` from now on, in a straight line (ignored once the grab
  // has stopped: it stands where it stopped until released).
  void steerGrab(const Vec3& velocity);
  // With no time passing (a paused run): moves the held ball straight towards `target` until
  // it touches something, then on along what it touches (grab_sweep.h); returns where it got.
  Vec3 moveGrabbed(const Vec3& target);
  // Lets the held ball go at `velocity`.
  void releaseGrab(const Vec3& velocity);
  int grabbed() const { return grabbed_; }
  bool grabStopped() const { return grabStopped_; }
  // Why the grab stopped since last asked, if it did.
  std::optional<GrabStop> takeGrabStop();

  // The memory this simulation holds, in bytes (the shared bodies not counted).
  std::size_t memoryBytes() const;

 private:
  void rebuildStepper(const std::vector<BallState>& state, double now);
  // Takes the stepper's news of a stopped grab, so that steering after it is ignored however
  // often the caller asks.
  void pullGrabStop();

  World world_;
  // Shared by copies; replaced, never changed, when the world's restitution changes.
  std::shared_ptr<const Bodies> bodies_;
  double collapseSpeed_ = 0.0;
  RunStats stats_;
  bool logCollisions_ = false;
  std::vector<CollisionRecord> collisionLog_;
  std::unique_ptr<Stepper> stepper_;
  int grabbed_ = -1;
  Vec3 grabVelocity_ = Vec3::Zero();
  bool grabStopped_ = false;
  std::optional<GrabStop> stopReport_;  // not yet taken
};

}  // namespace carom
