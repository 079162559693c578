#include "ui/status_readout.h"

#include "ui/editor/number_text.h"
#include "ui/run/simulation_snapshot.h"
#include "ui/sound_thread.h"

#include <QEvent>

#include <cmath>

namespace carom::ui {

using editor::formatNumber;

StatusReadout::StatusReadout(const SoundThread* sound, QWidget* parent)
    : QLabel(parent), sound_(sound) {
  fpsClock_.start();
  rateClock_.start();
  refreshTimer_.setSingleShot(true);
  refreshTimer_.setInterval(kRefreshMilliseconds);
  connect(&refreshTimer_, &QTimer::timeout, this, &StatusReadout::refresh);
  // Also while the simulation is paused, when no snapshots come.
  connect(sound_, &SoundThread::availabilityChanged, this, &StatusReadout::refresh);
}

void StatusReadout::showSnapshot(std::shared_ptr<const SimulationSnapshot> snapshot) {
  latest_ = std::move(snapshot);
  if (!refreshTimer_.isActive()) refreshTimer_.start();
}

void StatusReadout::countFrame() {
  ++framesRendered_;
  const double seconds = fpsClock_.nsecsElapsed() * 1e-9;
  if (seconds >= 1.0) {
    framesPerSecond_ = (framesRendered_ - framesAtLastSample_) / seconds;
    framesAtLastSample_ = framesRendered_;
    fpsClock_.restart();
  }
}

void StatusReadout::restart() {
  // The snapshot held is of the run before: the line keeps its text until the new run's first.
  latest_.reset();
  rateClock_.restart();
  lastCollisionCount_ = 0;
  lastCollisionTime_ = 0.0;
  collisionsPerSecond_ = 0.0;
}

void StatusReadout::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) refresh();
  QLabel::changeEvent(event);
}

void StatusReadout::refresh() {
  const std::shared_ptr<const SimulationSnapshot> snapshot = latest_;
  if (!snapshot) return;
  const std::uint64_t collisions = snapshot->stats.collisions.total();
  // Paused time is no run time: counted, one Step after a pause gave one step's collisions
  // divided by it (9,463,731 collisions/s in a settling pile).
  if (!snapshot->running) rateClock_.restart();
  if (snapshot->time < lastCollisionTime_ || collisions < lastCollisionCount_) {
    // After a reset: the old run's rate is not this one's, which is known once it has run.
    lastCollisionTime_ = snapshot->time;
    lastCollisionCount_ = collisions;
    collisionsPerSecond_ = 0.0;
    rateClock_.restart();
  } else if (const double simulated = snapshot->time - lastCollisionTime_;
             simulated >= kRateSeconds ||
             (simulated > 0.0 && rateClock_.elapsed() >= kRateMilliseconds)) {
    collisionsPerSecond_ = double(collisions - lastCollisionCount_) / simulated;
    lastCollisionTime_ = snapshot->time;
    lastCollisionCount_ = collisions;
    rateClock_.restart();
  }
  const double energy = snapshot->kineticEnergy + snapshot->potentialEnergy;
  const double drift = snapshot->initialEnergy != 0.0
                           ? (energy - snapshot->initialEnergy) / std::abs(snapshot->initialEnergy)
                           : 0.0;
  QString line =
      tr("t = %1 s   ×%2 real time   %3 fps   %4 collisions/s   %n balls   "
         "E = %5 J (drift %6)",
         nullptr, static_cast<int>(snapshot->positions.size()))
          .arg(formatNumber(snapshot->time, 'f', 3), formatNumber(snapshot->realTimeFactor, 'f', 2),
               formatNumber(framesPerSecond_, 'f', framesPerSecond_ < 10.0 ? 1 : 0),
               formatNumber(collisionsPerSecond_, 'f', 0), formatNumber(energy, 'g', 6),
               formatNumber(drift, 'e', 1));
  if (!sound_->available())
    line += tr("   sound unavailable");
  else if (sound_->muted())
    line += tr("   muted");
  if (snapshot->fallingBehind) line += tr("   — the physics cannot keep up; running slower");
  setText(line);
}

}  // namespace carom::ui
