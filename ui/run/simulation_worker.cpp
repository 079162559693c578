#include "ui/run/simulation_worker.h"

#include "sim/dynamics/energy.h"
#include "sim/measure/run_recording.h"
#include "sim/simulation.h"

#include <QElapsedTimer>
#include <QTimer>

#include <algorithm>
#include <cmath>

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
// Simulated m/s: fast enough for a hard throw across a room, slow enough not to fling a ball
// out of sight.
constexpr double kDefaultThrowLimit = 50.0;
// Recorded frames are sums of steps: a frame that should fall exactly on a video frame's moment
// may come out a rounding error after it. A nanosecond is far below any time step.
constexpr double kVideoTimeSlack = 1e-9;

}  // namespace

SimulationWorker::SimulationWorker(SnapshotExchange& exchange, QObject* parent)
    : QObject(parent),
      exchange_(exchange),
      recordingBudget_(RunRecording::kDefaultBudgetBytes),
      throwLimit_(kDefaultThrowLimit) {}

SimulationWorker::~SimulationWorker() = default;

void SimulationWorker::loadScene(const carom::Scene& scene, std::uint64_t number) {
  scene_ = scene;
  startNumber_ = number;
  reset();
}

void SimulationWorker::reset() {
  abandonVideo();
  simulation_ = std::make_unique<Simulation>(scene_);
  recording_ = std::make_unique<RunRecording>(*simulation_, recordingBudget_);
  shown_.reset();
  grabTarget_.reset();
  grabStop_.reset();
  throwCapped_ = false;
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
  if (running) goOnFromShownFrame();
  running_ = running;
  owed_ = 0.0;
  sinceBacklogDropped_ = std::numeric_limits<double>::infinity();
  factorSimulated_ = factorReal_ = 0.0;
  clock_.restart();
  publish();
}

void SimulationWorker::stepOnce() {
  if (!simulation_) return;
  goOnFromShownFrame();
  running_ = false;
  recording_->step(*simulation_);
  noteGrabStop();
  watchStep();
  publish();
}

void SimulationWorker::setSpeed(double factor) {
  speed_ = std::max(0.0, factor);
}

void SimulationWorker::setWorld(const carom::World& world) {
  if (!simulation_) return;
  goOnFromShownFrame();
  const bool newGravity = world.gravity != simulation_->world().gravity;
  scene_.world = world;
  intervene({Intervention::Kind::SetWorld, -1, Vec3::Zero(), world});
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
  // A held ball does work on what it pushes: the energy the watch compares with follows it
  // until the ball is let go.
  if (simulation_->grabbed() >= 0) watch_.rebase(*simulation_);
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
  makeVideoFrames();
  if (!running_ || !simulation_) return;
  owed_ += elapsed * speed_;
  QElapsedTimer work;
  work.start();
  const double before = simulation_->time();
  const double dt = simulation_->world().timeStep;
  // The held ball heads for its target, to reach it as this batch's steps end.
  if (grabTarget_ && simulation_->grabbed() >= 0 && !simulation_->grabStopped() && owed_ >= dt) {
    const double batch = std::floor(owed_ / dt) * dt;
    const Vec3 from = simulation_->state()[simulation_->grabbed()].position;
    intervene({Intervention::Kind::Steer, -1, (*grabTarget_ - from) / batch, {}});
  }
  // Whole steps, so that swept and discrete runs do not depend on the frame rate.
  while (owed_ >= dt && work.nsecsElapsed() * 1e-9 < kWorkBudgetSeconds) {
    recording_->step(*simulation_);
    owed_ -= dt;
    if (!watchStep()) break;
  }
  noteGrabStop();
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

void SimulationWorker::showFrame(std::uint64_t frame) {
  if (!simulation_) return;
  running_ = false;
  frame = std::min(frame, recording_->frameCount());
  QElapsedTimer clock;
  clock.start();
  if (frame == recording_->frameCount()) {
    shown_.reset();
  } else if (shown_ && shownFrame_ <= frame && recording_->keyframeBefore(frame) <= shownFrame_) {
    recording_->replay(*shown_, shownFrame_, frame);  // on from the frame shown
  } else {
    shown_ = recording_->reproduce(frame);
  }
  shownFrame_ = frame;
  lastScrubMilliseconds_ = clock.nsecsElapsed() * 1e-6;
  simulation_->takeCollisions();  // no explosions from the present while looking back
  publish();
}

void SimulationWorker::setRecordingBudget(std::size_t bytes) {
  recordingBudget_ = bytes;
  if (recording_) recording_->setBudgetBytes(bytes);
  publish();
}

void SimulationWorker::goOnFromShownFrame() {
  if (!shown_) return;
  abandonVideo();  // the frames it replays are about to be forgotten
  recording_->truncate(shownFrame_);
  simulation_ = std::move(shown_);
  simulation_->setCollisionLog(true);
  grabTarget_.reset();
  grabStop_.reset();
  // A frame in the middle of a grab goes on without the hand that held it.
  if (simulation_->grabbed() >= 0) intervene({Intervention::Kind::Release, -1, Vec3::Zero(), {}});
  // The watch compares with the frame the run goes on from.
  watch_.rebase(*simulation_);
}

void SimulationWorker::exportVideo(std::shared_ptr<VideoFrameQueue> frames, double from, double to,
                                   int fps) {
  abandonVideo();
  if (!frames) return;
  if (!simulation_ || fps <= 0 || !(from >= 0.0) || !(to >= from)) {
    frames->abandon();
    return;
  }
  auto job = std::make_unique<VideoJob>();
  job->frames = std::move(frames);
  // A fresh copy from the keyframe before the stretch: the live run and the frame shown stay
  // as they are.
  job->frame = recording_->keyframeAtTime(from);
  job->replay = recording_->reproduce(job->frame);
  job->replay->setCollisionLog(true);
  job->replay->takeCollisions();
  job->lastFrame = recording_->frameCount();
  job->from = from;
  job->fps = fps;
  video_ = std::move(job);
  makeVideoFrames();
}

void SimulationWorker::abandonVideo() {
  if (video_) video_->frames->abandon();
  video_.reset();
}

void SimulationWorker::makeVideoFrames() {
  if (!video_) return;
  VideoJob& job = *video_;
  VideoFrameQueue& queue = *job.frames;
  QElapsedTimer work;
  work.start();
  // The work is cut into pieces between recorded frames, so that a cancel or another request
  // waits at most a tick's budget.
  for (;;) {
    if (queue.cancelled()) {
      video_.reset();
      return;
    }
    if (job.next >= queue.count()) {
      video_.reset();  // all made; the GUI counts them
      return;
    }
    if (queue.room() == 0 || work.nsecsElapsed() * 1e-9 >= kWorkBudgetSeconds) return;
    const double moment = videoFrameTime(job.from, job.fps, job.next);
    Simulation& replay = *job.replay;
    // Recorded frames are at step ends: the replay's frame is due if it is not after the
    // moment (the first frame there is, whatever its time, stands in before it).
    if (!job.haveHeld || replay.time() <= moment + kVideoTimeSlack) {
      job.held.clear();
      for (const BallState& ball : replay.state()) job.held.push_back(ball.position);
      job.heldTime = replay.time();
      job.haveHeld = true;
      // The collisions of the step that ended here are seen from this state on.
      job.heldCollisions.insert(job.heldCollisions.end(), job.stepCollisions.begin(),
                                job.stepCollisions.end());
      if (job.heldCollisions.size() > kMaxPendingCollisions)
        job.heldCollisions.erase(job.heldCollisions.begin(),
                                 job.heldCollisions.end() - kMaxPendingCollisions);
      if (job.frame < job.lastFrame) {
        recording_->replay(replay, job.frame, job.frame + 1);
        ++job.frame;
        job.stepCollisions = replay.takeCollisions();
        continue;
      }
    }
    // The replay is past the moment, or at the last recorded frame: what is held is shown.
    queue.push({job.next, moment, job.heldTime, job.held, std::move(job.heldCollisions)});
    job.heldCollisions.clear();
    ++job.next;
  }
}

void SimulationWorker::intervene(const Intervention& what) {
  recording_->intervene(what, *simulation_);
}

void SimulationWorker::grab(int ball) {
  if (!simulation_ || ball < 0 || ball >= simulation_->ballCount()) return;
  goOnFromShownFrame();
  intervene({Intervention::Kind::Grab, ball, Vec3::Zero(), {}});
  watch_.rebase(*simulation_);
  grabTarget_.reset();
  grabStop_.reset();
  throwCapped_ = false;
  publish();
}

void SimulationWorker::moveGrab(const Vec3& target) {
  if (!simulation_ || simulation_->grabbed() < 0 || !target.allFinite()) return;
  grabTarget_ = target;
  if (!running_ && !simulation_->grabStopped()) {
    intervene({Intervention::Kind::Move, -1, target, {}});
    publish();
  }
}

void SimulationWorker::releaseGrab(const Vec3& velocity) {
  if (!simulation_ || simulation_->grabbed() < 0) return;
  noteGrabStop();
  Vec3 thrown = velocity.allFinite() && !simulation_->grabStopped() ? velocity : Vec3::Zero();
  // The cursor's velocity is per real second; running at a speed factor, the ball followed it
  // at that factor's inverse in simulated time.
  if (running_ && speed_ > 0.0) thrown /= speed_;
  throwCapped_ = thrown.norm() > throwLimit_;
  if (throwCapped_) thrown *= throwLimit_ / thrown.norm();
  intervene({Intervention::Kind::Release, -1, thrown, {}});
  watch_.rebase(*simulation_);  // the throw gave the ball its energy
  grabTarget_.reset();
  grabStop_.reset();
  publish();
}

void SimulationWorker::setThrowLimit(double speed) {
  if (speed > 0.0) throwLimit_ = speed;
}

void SimulationWorker::noteGrabStop() {
  if (std::optional<GrabStop> stop = simulation_->takeGrabStop()) grabStop_ = stop;
}

void SimulationWorker::publish() {
  if (!simulation_) return;
  const Simulation& sim = shown_ ? *shown_ : *simulation_;
  auto snapshot = std::make_shared<SimulationSnapshot>();
  snapshot->startNumber = startNumber_;
  snapshot->time = sim.time();
  // One read of the state serves the positions and both energies.
  for (const BallState& ball : sim.state()) {
    snapshot->positions.push_back(ball.position);
    snapshot->velocities.push_back(ball.velocity);
    snapshot->angularVelocities.push_back(ball.angularVelocity);
  }
  snapshot->frameCount = recording_->frameCount();
  snapshot->frame = shown_ ? shownFrame_ : snapshot->frameCount;
  snapshot->latestTime = simulation_->time();
  snapshot->recordingBytes = recording_->memoryBytes();
  snapshot->keyframes = recording_->keyframeCount();
  snapshot->scrubMilliseconds = lastScrubMilliseconds_;
  snapshot->grabbed = sim.grabbed();
  snapshot->grabStop = shown_ ? std::nullopt : grabStop_;
  snapshot->throwCapped = throwCapped_;
  std::vector<CollisionRecord> fresh = simulation_->takeCollisions();
  if (fresh.size() > kMaxPendingCollisions)
    fresh.erase(fresh.begin(), fresh.end() - kMaxPendingCollisions);
  snapshot->collisions = std::move(fresh);
  snapshot->kineticEnergy = kineticEnergy(sim.bodies(), snapshot->velocities) +
                            rotationalEnergy(sim.bodies(), snapshot->angularVelocities);
  snapshot->potentialEnergy =
      potentialEnergy(sim.bodies(), sim.world().gravity, snapshot->positions);
  snapshot->initialEnergy = initialEnergy_;
  snapshot->stats = sim.stats();
  snapshot->world = sim.world();
  snapshot->running = running_;
  snapshot->realTimeFactor = running_ ? lastRealTimeFactor_ : 0.0;
  snapshot->fallingBehind = running_ && sinceBacklogDropped_ < kFallingBehindHoldSeconds;
  snapshot->watchEvent = watchEvent_;
  snapshot->watchEvents = watchEvents_;
  if (exchange_.publish(std::move(snapshot))) emit snapshotPublished();
}

}  // namespace carom::ui
