#include "sim/simulation.h"
#include "sim/core/prefault.h"

#include "sim/dynamics/energy.h"
#include "sim/dynamics/grab_sweep.h"
#include "sim/dynamics/rest_policy.h"
#include "sim/dynamics/stepper.h"

#include <cmath>

namespace carom {

Simulation::Simulation(const Scene& scene)
    : world_(scene.world), bodies_(std::make_shared<const Bodies>(makeBodies(scene))) {
  std::vector<BallState> state;
  reservePrefaulted(state, scene.balls.size());
  double mass = 0.0, twiceKinetic = 0.0;
  for (const Ball& ball : scene.balls) {
    state.push_back({ball.position, ball.velocity, false, ball.angularVelocity});
    mass += ball.mass;
    twiceKinetic += ball.mass * ball.velocity.squaredNorm();
  }
  collapseSpeed_ = collapseSpeed(mass > 0.0 ? std::sqrt(twiceKinetic / mass) : 0.0);
  rebuildStepper(state, 0.0);
}

Simulation::Simulation(const Simulation& other)
    : world_(other.world_),
      bodies_(other.bodies_),
      collapseSpeed_(other.collapseSpeed_),
      stats_(other.stats_),
      logCollisions_(other.logCollisions_),
      collisionLog_(other.collisionLog_),
      stepper_(other.stepper_->clone()),
      grabbed_(other.grabbed_),
      grabVelocity_(other.grabVelocity_),
      grabStopped_(other.grabStopped_),
      stopReport_(other.stopReport_) {}

Simulation::~Simulation() = default;

void Simulation::rebuildStepper(const std::vector<BallState>& state, double now) {
  const StepperSettings settings{world_.gravity, world_.timeStep, world_.integrator,
                                 collapseSpeed_};
  switch (world_.method) {
    case Method::Exact:
      stepper_ = makeExactStepper(*bodies_, settings, state, now);
      break;
    case Method::Swept:
      stepper_ = makeSweptStepper(*bodies_, settings, state, now);
      break;
    case Method::Discrete:
      stepper_ = makeDiscreteStepper(*bodies_, settings, state, now);
      break;
  }
  if (grabbed_ >= 0) stepper_->hold(grabbed_, grabVelocity_, stats_);
}

void Simulation::advance(double duration) {
  if (!(duration > 0.0)) return;
  stepper_->advanceTo(stepper_->now() + duration, stats_,
                      logCollisions_ ? &collisionLog_ : nullptr);
}

void Simulation::advanceTo(double time) {
  stepper_->advanceTo(time, stats_, logCollisions_ ? &collisionLog_ : nullptr);
}

void Simulation::step() {
  stepper_->advanceSteps(1, stats_, logCollisions_ ? &collisionLog_ : nullptr);
}

double Simulation::time() const {
  return stepper_->now();
}

void Simulation::setWorld(const World& world) {
  if (world == world_) return;
  std::vector<BallState> current = state();
  const double now = time();
  // Resting balls rested against the old gravity: let them all settle again.
  if (world.gravity != world_.gravity)
    for (BallState& ball : current) ball.resting = false;
  const bool frictionChanged = world.friction != world_.friction ||
                               world.rollingResistance != world_.rollingResistance ||
                               world.spinningFriction != world_.spinningFriction ||
                               world.tangentialRestitution != world_.tangentialRestitution;
  if (world.restitution != world_.restitution || frictionChanged) {
    auto bodies = std::make_shared<Bodies>(*bodies_);
    bodies->setWorldRestitution(world.restitution);
    bodies->setWorldFriction(world);
    bodies_ = std::move(bodies);
  }
  world_ = world;
  rebuildStepper(current, now);
}

std::vector<BallState> Simulation::state() const {
  return stepper_->state();
}

std::vector<Vec3> Simulation::positions() const {
  std::vector<Vec3> out;
  for (const BallState& s : state()) out.push_back(s.position);
  return out;
}

std::vector<Vec3> Simulation::velocities() const {
  std::vector<Vec3> out;
  for (const BallState& s : state()) out.push_back(s.velocity);
  return out;
}

std::vector<Vec3> Simulation::angularVelocities() const {
  std::vector<Vec3> out;
  for (const BallState& s : state()) out.push_back(s.angularVelocity);
  return out;
}

double Simulation::kineticEnergy() const {
  const std::vector<BallState> now = state();
  double translation = 0.0, rotation = 0.0;
  for (int i = 0; i < ballCount(); ++i) {
    translation += ballKineticEnergy(bodies_->mass[i], now[i].velocity);
    rotation += ballRotationalEnergy(bodies_->mass[i], bodies_->radius[i], now[i].angularVelocity);
  }
  return translation + rotation;
}

double Simulation::potentialEnergy() const {
  return carom::potentialEnergy(*bodies_, world_.gravity, positions());
}

Vec3 Simulation::momentum() const {
  Vec3 sum = Vec3::Zero();
  const std::vector<Vec3> v = velocities();
  for (int i = 0; i < ballCount(); ++i) sum += bodies_->mass[i] * v[i];
  return sum;
}

std::vector<std::string> Simulation::modelNotes() const {
  std::vector<std::string> notes = stepper_->notes();
  if (bodies_->cylinders.empty()) notes.push_back("no cylinders: no cylinder tests");
  if (bodies_->planes.empty()) notes.push_back("no planes: no plane tests");
  if (bodies_->boxes.empty()) notes.push_back("no boxes: no box tests");
  if (world_.method != Method::Discrete) {
    if (world_.gravity.isZero())
      notes.push_back("no gravity: nothing comes to rest");
    else
      notes.push_back("resting balls are not rescheduled");
  }
  return notes;
}

std::vector<CollisionRecord> Simulation::takeCollisions() {
  std::vector<CollisionRecord> taken;
  taken.swap(collisionLog_);
  return taken;
}

void Simulation::grab(int ball) {
  if (ball < 0 || ball >= ballCount()) return;
  grabbed_ = ball;
  grabVelocity_ = Vec3::Zero();
  grabStopped_ = false;
  stepper_->hold(ball, grabVelocity_, stats_);
}

void Simulation::pullGrabStop() {
  if (std::optional<GrabStop> stop = stepper_->takeGrabStop()) {
    grabStopped_ = true;
    grabVelocity_ = Vec3::Zero();
    stopReport_ = stop;
  }
}

void Simulation::steerGrab(const Vec3& velocity) {
  pullGrabStop();
  if (grabbed_ < 0 || grabStopped_ || !velocity.allFinite()) return;
  grabVelocity_ = velocity;
  stepper_->hold(grabbed_, velocity, stats_);
}

Vec3 Simulation::moveGrabbed(const Vec3& target) {
  pullGrabStop();
  const std::vector<BallState> now = state();
  if (grabbed_ < 0) return Vec3::Zero();
  const Vec3 from = now[grabbed_].position;
  if (grabStopped_ || !target.allFinite()) return from;
  const Vec3 to = slideTo(*bodies_, now, grabbed_, target - from);
  stepper_->place(to);
  return to;
}

void Simulation::releaseGrab(const Vec3& velocity) {
  if (grabbed_ < 0) return;
  pullGrabStop();
  stepper_->release(velocity.allFinite() ? velocity : Vec3::Zero());
  grabbed_ = -1;
  grabVelocity_ = Vec3::Zero();
  grabStopped_ = false;
}

std::optional<GrabStop> Simulation::takeGrabStop() {
  pullGrabStop();
  std::optional<GrabStop> stop;
  stop.swap(stopReport_);
  return stop;
}

std::size_t Simulation::memoryBytes() const {
  return sizeof(*this) + stepper_->memoryBytes() +
         collisionLog_.capacity() * sizeof(CollisionRecord);
}

}  // namespace carom
