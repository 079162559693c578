#include "ui/grab_control.h"

#include "ui/editor/editor_tools.h"
#include "ui/editor/number_text.h"
#include "ui/run/run_session.h"
#include "ui/run/simulation_snapshot.h"

#include <QInputDialog>
#include <QSettings>

#include <algorithm>

namespace carom::ui {
namespace {

constexpr char kThrowLimitKey[] = "simulation/throwLimit";
constexpr double kDefaultThrowLimit = 50.0;

}  // namespace

GrabControl::GrabControl(editor::EditorTools* tools, RunSession* run, QObject* parent)
    : QObject(parent), tools_(tools), run_(run) {
  bool ok = false;
  const double stored = QSettings().value(kThrowLimitKey, kDefaultThrowLimit).toDouble(&ok);
  throwLimit_ =
      ok && stored >= kMinThrowLimit && stored <= kMaxThrowLimit ? stored : kDefaultThrowLimit;
  run_->controls().setThrowLimit(throwLimit_);
  connect(tools_, &editor::EditorTools::grabStarted, this, [this](int ball) {
    lastStopTime_.reset();
    heldFrom_.reset();
    const std::shared_ptr<const SimulationSnapshot> shown = run_->latest();
    if (shown && !shown->running && ball < int(shown->positions.size()))
      heldFrom_ = Held{shown->positions[ball], shown->velocities[ball]};
    run_->controls().grab(ball);
  });
  connect(tools_, &editor::EditorTools::grabCancelled, this, &GrabControl::cancelGrab);
  connect(tools_, &editor::EditorTools::grabMoved, &run_->controls(),
          &SimulationController::moveGrab);
  connect(tools_, &editor::EditorTools::grabReleased, &run_->controls(),
          &SimulationController::releaseGrab);
}

void GrabControl::cancelGrab() {
  const std::shared_ptr<const SimulationSnapshot> shown = run_->latest();
  if (heldFrom_ && shown && !shown->running) {
    // Paused, nothing else moved: the ball goes back and is let go as it was.
    run_->controls().moveGrab(heldFrom_->position);
    run_->controls().releaseGrab(heldFrom_->velocity);
  } else {
    // Running, the run went on under the grab; the ball is let go where it is, without a throw.
    run_->controls().releaseGrab(Vec3::Zero());
  }
  heldFrom_.reset();
}

void GrabControl::setThrowLimit(double speed) {
  if (!(speed >= kMinThrowLimit && speed <= kMaxThrowLimit)) return;
  throwLimit_ = speed;
  QSettings().setValue(kThrowLimitKey, speed);
  run_->controls().setThrowLimit(speed);
}

void GrabControl::askThrowLimit(QWidget* parent) {
  bool ok = false;
  const double limit = QInputDialog::getDouble(parent, tr("Throw Speed Limit"),
                                               tr("Fastest throw of a grabbed ball (m/s):"),
                                               throwLimit_, kMinThrowLimit, kMaxThrowLimit, 6, &ok);
  if (ok) setThrowLimit(limit);
}

void GrabControl::showSnapshot(const SimulationSnapshot& snapshot) {
  // At the scene's start the Select tool edits the scene; once the run has begun it grabs.
  const bool inProgress = snapshot.running || snapshot.time > 0.0;
  tools_->setRunningBalls(inProgress ? snapshot.positions : std::vector<Vec3>{});
  if (snapshot.grabStop && lastStopTime_ != snapshot.grabStop->time) {
    lastStopTime_ = snapshot.grabStop->time;
    const GrabStop& stop = *snapshot.grabStop;
    const QString time = editor::formatNumber(stop.time, 'f', 4);
    if (stop.kind == GrabStopKind::Crush)
      emit message(tr("The grab stopped at t = %1 s: ball %2 would have been crushed against "
                      "what is behind it.")
                       .arg(time)
                       .arg(stop.other + 1));
    else
      emit message(tr("The grab stopped at t = %1 s: the balls in front are jammed.").arg(time));
  }
  if (snapshot.throwCapped && !throwCapped_)
    emit message(tr("Thrown at the throw limit, %1 m/s (Simulation > Throw Speed Limit).")
                     .arg(editor::formatNumber(throwLimit_)));
  throwCapped_ = snapshot.throwCapped;
}

}  // namespace carom::ui
