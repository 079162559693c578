#pragma once
// Runs the physics on its own thread. The worker lives in a QThread; the GUI talks to it only
// through queued calls (SimulationController) and reads its results from the SnapshotExchange,
// so the GUI never waits on the physics and the worker never touches a widget.

#include "sim/run_watch.h"
#include "sim/scene.h"
#include "ui/simulation_snapshot.h"

#include <QElapsedTimer>
#include <QObject>

#include <cstdint>
#include <limits>
#include <memory>

class QTimer;

namespace carom {
class Simulation;
}

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

 signals:
  // A new snapshot is in the exchange (at most one per batch of steps).
  void snapshotPublished();

 private:
  void tick();
  void publish();
  // After a step: runs the watch; on an event pauses and keeps it for the snapshots. True when
  // the run goes on.
  bool watchStep();

  SnapshotExchange& exchange_;
  Scene scene_;
  std::unique_ptr<Simulation> simulation_;
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
};

}  // namespace carom::ui
