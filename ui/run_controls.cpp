#include "ui/run_controls.h"

#include "ui/number_box.h"
#include "ui/run/simulation_controller.h"

#include <QAction>
#include <QEvent>
#include <QLabel>
#include <QSignalBlocker>

namespace carom::ui {

RunControls::RunControls(SimulationController* simulation, QWidget* parent)
    : QToolBar(parent), simulation_(simulation) {
  setObjectName("simulation");
  playAction_ = new QAction(this);
  playAction_->setObjectName("run");
  playAction_->setCheckable(true);
  playAction_->setShortcut(Qt::Key_Space);
  connect(playAction_, &QAction::toggled, this, [this](bool on) {
    playAction_->setText(on ? tr("&Pause") : tr("&Run"));
    simulation_->setRunning(on);
  });

  stepAction_ = new QAction(this);
  stepAction_->setShortcut(Qt::Key_S);
  connect(stepAction_, &QAction::triggered, this, [this] {
    playAction_->setChecked(false);
    simulation_->stepOnce();
  });

  resetAction_ = new QAction(this);
  resetAction_->setShortcut(Qt::Key_R);
  connect(resetAction_, &QAction::triggered, this, [this] {
    playAction_->setChecked(false);
    simulation_->reset();
  });

  addAction(playAction_);
  addAction(stepAction_);
  addAction(resetAction_);
  addSeparator();

  speedLabel_ = new QLabel;
  addWidget(speedLabel_);
  speed_ = new NumberBox(QString(), 0.01, 100.0, 0.25);  // named in retranslate()
  speed_->setObjectName("speed");
  speed_->setValue(1.0);
  connect(speed_, &NumberBox::refused, this, &RunControls::message);
  connect(speed_, &QDoubleSpinBox::valueChanged, this,
          [this](double value) { simulation_->setSpeed(value); });
  addWidget(speed_);
  simulation_->setSpeed(speed_->value());
  retranslate();
}

QList<QAction*> RunControls::runActions() const {
  return {playAction_, stepAction_, resetAction_};
}

void RunControls::setRunning(bool running) {
  playAction_->setChecked(running);
}

void RunControls::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QToolBar::changeEvent(event);
}

void RunControls::retranslate() {
  setWindowTitle(tr("Simulation"));
  playAction_->setText(playAction_->isChecked() ? tr("&Pause") : tr("&Run"));
  playAction_->setToolTip(tr("Run or pause the simulation (Space)"));
  stepAction_->setText(tr("&Step"));
  stepAction_->setToolTip(tr("Advance one time step (S)"));
  resetAction_->setText(tr("R&eset"));
  resetAction_->setToolTip(tr("Back to the scene's initial state (R)"));
  speedLabel_->setText(tr("Speed"));
  speed_->setName(tr("Speed"));
  speed_->setToolTip(tr("Simulated seconds per real second"));
  {
    const QSignalBlocker blocker(speed_);  // shown in the language's number format
    speed_->setValue(speed_->value());
  }
}

}  // namespace carom::ui
