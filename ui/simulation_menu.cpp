#include "ui/simulation_menu.h"

#include "ui/grab_control.h"
#include "ui/run/simulation_controller.h"
#include "ui/run_controls.h"
#include "ui/simulation_sync.h"
#include "ui/timeline_bar.h"
#include "ui/watch_menu.h"

#include <QAction>
#include <QEvent>
#include <QSettings>

namespace carom::ui {

SimulationMenu::SimulationMenu(RunControls* runControls, SimulationController* simulation,
                               SimulationSync* sync, GrabControl* grab, TimelineBar* timeline,
                               QWidget* window, QWidget* parent)
    : QMenu(parent) {
  addActions(runControls->runActions());
  addSeparator();
  accuracyAction_ = addAction(QString(), this, &SimulationMenu::accuracyWindowRequested);
  auto* watchMenu = new WatchMenu(this);
  addMenu(watchMenu);
  connect(watchMenu, &WatchMenu::settingsChanged, simulation,
          &SimulationController::setWatchSettings);
  simulation->setWatchSettings(watchMenu->settings());
  addSeparator();
  useStateAction_ = addAction(QString(), this, &SimulationMenu::useCurrentStateRequested);
  useStateAction_->setObjectName("useCurrentState");
  applyToRunningAction_ = addAction(QString());
  applyToRunningAction_->setObjectName("applyToRunningState");
  applyToRunningAction_->setCheckable(true);
  applyToRunningAction_->setChecked(QSettings().value(kApplyToRunningKey, false).toBool());
  sync->setApplyToRunningState(applyToRunningAction_->isChecked());
  connect(applyToRunningAction_, &QAction::toggled, this, [sync](bool on) {
    sync->setApplyToRunningState(on);
    QSettings().setValue(kApplyToRunningKey, on);
  });
  addSeparator();
  throwLimitAction_ = addAction(QString(), this, [grab, window] { grab->askThrowLimit(window); });
  throwLimitAction_->setObjectName("throwLimit");
  timelineMemoryAction_ = addAction(QString(), timeline, &TimelineBar::askMemoryBudget);
  timelineMemoryAction_->setObjectName("timelineMemory");
  retranslate();
}

void SimulationMenu::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QMenu::changeEvent(event);
}

void SimulationMenu::retranslate() {
  setTitle(tr("&Simulation"));
  accuracyAction_->setText(tr("Speed vs &Accuracy…"));
  throwLimitAction_->setText(tr("&Throw Speed Limit…"));
  timelineMemoryAction_->setText(tr("Timeline &Memory…"));
  useStateAction_->setText(tr("&Use Current State as Initial"));
  applyToRunningAction_->setText(tr("Edits Apply to the &Running State"));
  applyToRunningAction_->setToolTip(
      tr("Off: an edit restarts the simulation from the edited scene. On: balls the edit leaves "
         "alone keep their running state."));
}

}  // namespace carom::ui
