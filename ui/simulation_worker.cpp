#include "ui/simulation_worker.h"

#include "sim/measures.h"
#include "sim/simulation.h"

#include <QTimer>

#include <algorithm>

namespace carom::ui {
namespace {

// The worker wakes this often; each wake does at most a budget of work so that it stays
// responsive to the GUI's requests.
constexpr int kTickMilliseconds = 8;
constexpr double kWorkBudgetSeconds = 0.025;
// When the physics falls further behind than this, the backlog is dropped: simulated time then
// runs slower than asked, and the status bar says so, instead of jumping.
constexpr double kMaxBacklogSeconds = 0.25;
// Once dropped, the backlog builds again over a few batches; the warning stays up this long.
constexpr double kFallingBehindHoldSeconds = 1.0;
// The explosion and sound queue is capped; the view and the speakers could not use more.
constexpr std::size_t kMaxPendingCollisions = 4096;

}  // namespace

SimulationWorker::SimulationWorker(SnapshotExchange& exchange, QObject* parent)
    : QObject(parent), exchange_(exchange) {}

SimulationWorker::~SimulationWorker() = default;

void SimulationWorker::loadScene(const carom::Scene& scene, std::uint64_t number) {
  scene_ = scene;
  startNumber_ = number;
  reset();
}

void SimulationWorker::reset() {
  simulation_ = std::make_unique<Simulation>(scene_);
  simulation_->setCollisionLog(true);
  initialEnergy_ = simulation_->totalEnergy();
  watch_.rebase(*simulation_);
  owed_ = 0.0;
  sinceBacklogDropped_ = std::numeric_limits<double>::infinity();
  if (!timer_) {
    timer_ = new QTimer(this);  // created here so that it lives on the worker's thread
    timer_->setTimerType(Qt::PreciseTimer);
    connect(timer_, &QTimer::timeout, this, &SimulationWorker::tick);
    timer_->start(kTickMilliseconds);
    clock_.start();
  }
  publish();
}

void SimulationWorker::setRunning(bool running) {
  running_ = running;
  owed_ = 0.0;
  sinceBacklogDropped_ = std::numeric_limits<double>::infinity();
  factorSimulated_ = factorReal_ = 0.0;
  clock_.restart();
  publish();
}

void SimulationWorker::stepOnce() {
  if (!simulation_) return;
  running_ = false;
  simulation_->step();
  watchStep();
  publish();
}

void SimulationWorker::setSpeed(double factor) {
  speed_ = std::max(0.0, factor);
}

void SimulationWorker::setWorld(const carom::World& world) {
  if (!simulation_) return;
  const bool newGravity = world.gravity != scene_.world.gravity;
  scene_.world = world;
  simulation_->setWorld(world);
  if (newGravity) initialEnergy_ = simulation_->totalEnergy();  // measured in the new field
  // New settings do work on the balls (stronger gravity, a livelier restitution): the energy
  // the watch compares with starts again here.
  watch_.rebase(*simulation_);
  publish();
}

void SimulationWorker::setWatchSettings(const carom::WatchSettings& settings) {
  watch_.setSettings(settings);
}

bool SimulationWorker::watchStep() {
  std::optional<WatchEvent> event = watch_.check(*simulation_);
  if (!event) return true;
  watchEvent_ = std::move(event);
  ++watchEvents_;
  running_ = false;
  owed_ = 0.0;
  return false;
}

void SimulationWorker::tick() {
  const double elapsed = clock_.nsecsElapsed() * 1e-9;
  clock_.restart();
  if (!running_ || !simulation_) return;
  owed_ += elapsed * speed_;
  QElapsedTimer work;
  work.start();
  const double before = simulation_->time();
  const double dt = simulation_->world().timeStep;
  // Whole steps, so that swept and discrete runs do not depend on the frame rate.
  while (owed_ >= dt && work.nsecsElapsed() * 1e-9 < kWorkBudgetSeconds) {
    simulation_->step();
    owed_ -= dt;
    if (!watchStep()) break;
  }
  sinceBacklogDropped_ += elapsed;
  if (owed_ > kMaxBacklogSeconds * std::max(speed_, 1e-9) + dt) {
    owed_ = 0.0;
    sinceBacklogDropped_ = 0.0;
  }
  // Averaged over about half a second, so the figure does not flicker with each batch.
  factorSimulated_ += simulation_->time() - before;
  factorReal_ += elapsed;
  if (factorReal_ >= 0.5) {
    lastRealTimeFactor_ = factorSimulated_ / factorReal_;
    factorSimulated_ = factorReal_ = 0.0;
  }
  publish();
}

void SimulationWorker::publish() {
  if (!simulation_) return;
  auto snapshot = std::make_shared<SimulationSnapshot>();
  snapshot->startNumber = startNumber_;
  snapshot->time = simulation_->time();
  // One read of the state serves the positions and both energies.
  for (const BallState& ball : simulation_->state()) {
    snapshot->positions.push_back(ball.position);
    snapshot->velocities.push_back(ball.velocity);
  }
  std::vector<CollisionRecord> fresh = simulation_->takeCollisions();
  if (fresh.size() > kMaxPendingCollisions)
    fresh.erase(fresh.begin(), fresh.end() - kMaxPendingCollisions);
  snapshot->collisions = std::move(fresh);
  snapshot->kineticEnergy = kineticEnergy(simulation_->bodies(), snapshot->velocities);
  snapshot->potentialEnergy =
      potentialEnergy(simulation_->bodies(), simulation_->world().gravity, snapshot->positions);
  snapshot->initialEnergy = initialEnergy_;
  snapshot->stats = simulation_->stats();
  snapshot->world = simulation_->world();
  snapshot->running = running_;
  snapshot->realTimeFactor = running_ ? lastRealTimeFactor_ : 0.0;
  snapshot->fallingBehind = running_ && sinceBacklogDropped_ < kFallingBehindHoldSeconds;
  snapshot->watchEvent = watchEvent_;
  snapshot->watchEvents = watchEvents_;
  if (exchange_.publish(std::move(snapshot))) emit snapshotPublished();
}

}  // namespace carom::ui
