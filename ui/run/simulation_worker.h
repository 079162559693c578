#pragma once
// Runs the physics on its own thread. The worker lives in a QThread; the GUI talks to it only
// through queued calls (SimulationController) and reads its results from the SnapshotExchange,
// so the GUI never waits on the physics and the worker never touches a widget.

#include "sim/dynamics/grab.h"
#include "sim/measure/run_recording.h"
#include "sim/measure/run_watch.h"
#include "sim/model/scene.h"
#include "ui/run/simulation_snapshot.h"
#include "ui/run/video_frames.h"

#include <QElapsedTimer>
#include <QObject>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>

class QTimer;

namespace carom {
class RunRecording;
class Simulation;
}  // namespace carom

namespace carom::ui {

class SimulationWorker : public QObject {
  Q_OBJECT
 public:
  explicit SimulationWorker(SnapshotExchange& exchange, QObject* parent = nullptr);
  ~SimulationWorker() override;

  // Replaces the scene (already validated) and stands at its start, paused; its snapshots carry
  // `number`.
  void loadScene(const carom::Scene& scene, std::uint64_t number);
  void setRunning(bool running);
  void stepOnce();
  void reset();
  void setSpeed(double factor);  // simulated seconds per real second
  void setWorld(const carom::World& world);
  // The run watch's checks (valid settings), from the next step on; all off: no watch.
  void setWatchSettings(const carom::WatchSettings& settings);

  // The timeline (sim/run_recording.h): shows frame `frame` of the recorded run, paused. Play,
  // a step, a grab or a new setting goes on from the frame shown, and the recorded frames
  // after it are forgotten.
  void showFrame(std::uint64_t frame);
  void setRecordingBudget(std::size_t bytes);
  // The video export (ui/video_export.h): replays the recorded run from `from` to `to`
  // (simulated seconds) on a copy of its own, leaving the live run and the frame shown alone,
  // and pushes into `frames` the ball positions of the latest recorded frame at or before each
  // video frame's moment, a batch at each tick as far as the queue has room, until all are made,
  // the queue is cancelled, or the run is reset or goes on from an earlier frame (abandoned).
  void exportVideo(std::shared_ptr<VideoFrameQueue> frames, double from, double to, int fps);

  // Grabbing (sim/grab.h). While running, the held ball is steered to reach the latest target
  // by the end of each batch of steps; paused, it moves there at once as far as it is clear.
  void grab(int ball);
  void moveGrab(const carom::Vec3& target);
  // Lets go at `velocity` (simulated m/s), no faster than the throw limit.
  void releaseGrab(const carom::Vec3& velocity);
  void setThrowLimit(double speed);

 signals:
  // A new snapshot is in the exchange (at most one per batch of steps).
  void snapshotPublished();

 private:
  void tick();
  void publish();
  // Makes the frame shown, when it is an earlier one, the live run's present.
  void goOnFromShownFrame();
  void intervene(const carom::Intervention& what);
  void noteGrabStop();
  // After a step: runs the watch; on an event pauses and keeps it for the snapshots. True when
  // the run goes on.
  bool watchStep();
  // Makes the video frames due, as far as the queue has room and the tick's budget lasts.
  void makeVideoFrames();
  void abandonVideo();

  SnapshotExchange& exchange_;
  Scene scene_;
  std::unique_ptr<Simulation> simulation_;
  std::unique_ptr<RunRecording> recording_;
  std::size_t recordingBudget_;
  // An earlier frame being shown (the timeline scrubbed back), or null for the live run's
  // present.
  std::unique_ptr<Simulation> shown_;
  std::uint64_t shownFrame_ = 0;
  double lastScrubMilliseconds_ = 0.0;
  std::optional<carom::Vec3> grabTarget_;
  double throwLimit_;
  std::optional<GrabStop> grabStop_;  // the last stop, until the grab ends
  bool throwCapped_ = false;          // the last throw was cut to the limit
  QTimer* timer_ = nullptr;
  QElapsedTimer clock_;
  bool running_ = false;
  double speed_ = 1.0;
  double owed_ = 0.0;  // simulated time the physics is behind real time
  double initialEnergy_ = 0.0;
  double lastRealTimeFactor_ = 0.0;
  double factorSimulated_ = 0.0;  // simulated and real time since the factor was last taken
  double factorReal_ = 0.0;
  // Real seconds since a backlog was last dropped; the warning is held a while so it does not
  // blink on and off with every batch.
  double sinceBacklogDropped_ = std::numeric_limits<double>::infinity();
  std::uint64_t startNumber_ = 0;
  RunWatch watch_;
  std::optional<WatchEvent> watchEvent_;
  std::uint64_t watchEvents_ = 0;
  struct VideoJob {
    std::shared_ptr<VideoFrameQueue> frames;
    std::unique_ptr<Simulation> replay;  // at recorded frame `frame`
    std::uint64_t frame = 0;
    std::uint64_t lastFrame = 0;  // the newest recorded when the export began
    double from = 0.0;
    int fps = 1;
    int next = 0;  // the next video frame to make
    // The latest recorded frame not after the next video frame's moment, as far as known.
    std::vector<Vec3> held;
    double heldTime = 0.0;
    bool haveHeld = false;
    std::vector<CollisionRecord> stepCollisions;  // of the step that reached `replay`'s state
    std::vector<CollisionRecord> heldCollisions;  // not yet handed to a video frame
  };
  std::unique_ptr<VideoJob> video_;
};

}  // namespace carom::ui
