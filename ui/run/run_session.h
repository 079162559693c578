#pragma once
// The live run's owner: the only one that starts a run, it numbers the starts and hands on only
// the current start's snapshots. After a restart the worker may still publish snapshots of the
// run before until it has answered; a consumer given one would draw the old run's positions
// against the new scene (for about a second with a million balls). Here they are dropped, so
// the window and the docks need no filter of their own.
//
// Reset is not a start: it takes the same run back to its beginning, and the snapshots before
// it are of the same scene (the consumers follow the time going back, as for the timeline).

#include "sim/model/scene.h"
#include "ui/run/simulation_controller.h"

#include <QObject>

#include <cstdint>
#include <memory>

namespace carom::ui {

struct SimulationSnapshot;

class RunSession : public QObject {
  Q_OBJECT
 public:
  explicit RunSession(QObject* parent = nullptr);
  ~RunSession() override;

  // Starts the run anew from `scene` (valid), paused: restarted() follows at once, and from
  // then on only snapshots of this start.
  void start(std::shared_ptr<const carom::Scene> scene);
  // The current start's number: 0 before the first, counting up.
  std::uint64_t currentStart() const { return currentStart_; }
  // The current start's newest snapshot, or null while it has none; never waits on the physics.
  std::shared_ptr<const SimulationSnapshot> latest() const;
  // The run's controls (run, step, reset, speed, world, timeline, grab, video, watch).
  SimulationController& controls() { return controller_; }

 signals:
  // The run started anew from `scene` as start `start`: the snapshots that follow are of it.
  void restarted(std::uint64_t start, std::shared_ptr<const carom::Scene> scene);
  // A new snapshot of the current start, for the window to show (at most one per batch of
  // steps; one replaced before it was taken is never handed on).
  void snapshotReady(std::shared_ptr<const SimulationSnapshot> snapshot);

 private:
  void takeSnapshot();

  SimulationController controller_;
  std::uint64_t currentStart_ = 0;
};

}  // namespace carom::ui
