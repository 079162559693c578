#pragma once
// The GUI's handle on the simulation: owns the worker thread and forwards every request to the
// worker as a queued call (CallQueue), so nothing here ever waits on the physics. Starting a run
// and reading its snapshots are its owner's (RunSession), which numbers the starts.

#include "sim/measure/run_watch.h"
#include "sim/model/scene.h"
#include "ui/run/simulation_snapshot.h"

#include <QObject>
#include <QThread>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>

namespace carom::ui {

class CallQueue;
class SimulationWorker;
class VideoFrameQueue;

class SimulationController : public QObject {
  Q_OBJECT
 public:
  explicit SimulationController(QObject* parent = nullptr);
  ~SimulationController() override;

  void setRunning(bool running);
  void stepOnce();
  void reset();
  void setSpeed(double factor);
  // New world settings (valid), applied from the running state on.
  void setWorld(const carom::World& world);
  // The timeline and grabbing: see SimulationWorker.
  void showFrame(std::uint64_t frame);
  void setRecordingBudget(std::size_t bytes);
  void grab(int ball);
  void moveGrab(const carom::Vec3& target);
  void releaseGrab(const carom::Vec3& velocity);
  void setThrowLimit(double speed);
  // The video export's frames, replayed from the recorded run (SimulationWorker::exportVideo).
  void exportVideo(std::shared_ptr<VideoFrameQueue> frames, double from, double to, int fps);
  // The run watch's checks (valid), from the next step on.
  void setWatchSettings(const carom::WatchSettings& settings);

 signals:
  // A new snapshot is in the exchange, for RunSession to take.
  void snapshotPublished();

 private:
  friend class RunSession;
  // Stands at the start of `scene` (valid), paused; snapshots of it carry `number`.
  void loadScene(std::shared_ptr<const carom::Scene> scene, std::uint64_t number);
  // The most recent snapshot, or null before the first; never waits on the physics.
  std::shared_ptr<const SimulationSnapshot> latest() const { return exchange_.latest(); }
  // The same, marking it shown: the worker announces the next one.
  std::shared_ptr<const SimulationSnapshot> take() { return exchange_.take(); }

  // Tests hold the physics thread busy through post(), as a very long batch of steps would.
  friend class SimulationControllerTestAccess;
  void post(std::function<void()> call);

  SnapshotExchange exchange_;
  static constexpr std::uint64_t kNoFrame = ~std::uint64_t(0);
  std::atomic<std::uint64_t> pendingFrame_{kNoFrame};
  QThread* thread_;           // a child named "physics"
  SimulationWorker* worker_;  // on thread_, deleted when it finishes
  CallQueue* calls_;          // the worker's child: runs the posted calls on thread_
};

}  // namespace carom::ui
