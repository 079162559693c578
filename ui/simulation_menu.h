#pragma once
// The Simulation menu: the run's controls, Speed vs Accuracy, the watch, the run's state as the
// scene's, whether edits apply to the running state, the throw speed limit and the timeline's
// memory.

#include <QMenu>

class QAction;

namespace carom::ui {

class GrabControl;
class RunControls;
class SimulationController;
class SimulationSync;
class TimelineBar;
class WatchMenu;

class SimulationMenu : public QMenu {
  Q_OBJECT
 public:
  // Dialogs open over `window`.
  SimulationMenu(RunControls* runControls, SimulationController* simulation, SimulationSync* sync,
                 GrabControl* grab, TimelineBar* timeline, QWidget* window,
                 QWidget* parent = nullptr);

 signals:
  void accuracyWindowRequested();
  void useCurrentStateRequested();

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();

  static constexpr const char* kApplyToRunningKey = "editing/applyToRunningState";
  QAction* accuracyAction_ = nullptr;
  QAction* useStateAction_ = nullptr;
  QAction* applyToRunningAction_ = nullptr;
  QAction* throwLimitAction_ = nullptr;
  QAction* timelineMemoryAction_ = nullptr;
};

}  // namespace carom::ui
