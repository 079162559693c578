#include "ui/docks/energy_plot.h"

#include "ui/docks/plot_axis.h"
#include "ui/run/simulation_snapshot.h"

#include <QChart>
#include <QChartView>
#include <QLineSeries>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <array>

namespace carom::ui {
namespace {

// Points closer together than this in simulated time are skipped, and only this much of the
// recent past is kept, so a long run costs the plot nothing more.
constexpr double kMinSpacingSeconds = 0.02;
constexpr double kWindowSeconds = 30.0;
// Redrawing the chart for every point would cost the GUI thread several milliseconds a frame;
// points gathered in between are drawn together at this pace.
constexpr int kRedrawMilliseconds = 100;
// At most this many ticks an axis: their labels stay whole at the dock's opening size.
constexpr int kTimeTicks = 6;
constexpr int kEnergyTicks = 5;

}  // namespace

EnergyPlot::EnergyPlot(QWidget* parent)
    : QWidget(parent),
      chart_(new QChart),
      kinetic_(new QLineSeries),
      potential_(new QLineSeries),
      total_(new QLineSeries),
      timeAxis_(new QValueAxis),
      energyAxis_(new QValueAxis) {
  retranslate();
  chart_->addAxis(timeAxis_, Qt::AlignBottom);
  chart_->addAxis(energyAxis_, Qt::AlignLeft);
  for (QLineSeries* series : {kinetic_, potential_, total_}) {
    chart_->addSeries(series);
    series->attachAxis(timeAxis_);
    series->attachAxis(energyAxis_);
  }
  chart_->legend()->setAlignment(Qt::AlignRight);
  fitToDock(chart_);
  auto* view = new QChartView(chart_);
  view->setRenderHint(QPainter::Antialiasing);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(view);
  redrawTimer_.setSingleShot(true);
  redrawTimer_.setInterval(kRedrawMilliseconds);
  connect(&redrawTimer_, &QTimer::timeout, this, &EnergyPlot::drawPending);
  clear();
}

void EnergyPlot::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void EnergyPlot::retranslate() {
  localizeNumbers(chart_);
  kinetic_->setName(tr("Kinetic"));
  potential_->setName(tr("Potential"));
  total_->setName(tr("Total"));
  timeAxis_->setTitleText(tr("Simulated time (s)"));
  energyAxis_->setTitleText(tr("Energy (J)"));
}

void EnergyPlot::clear() {
  for (QLineSeries* series : {kinetic_, potential_, total_}) series->clear();
  for (QList<QPointF>& points : pending_) points.clear();
  redrawTimer_.stop();
  lastTime_ = -1.0;
  low_ = high_ = 0.0;
  setRoundRange(timeAxis_, 0.0, 1.0, kTimeTicks);
  setRoundRange(energyAxis_, -1.0, 1.0, kEnergyTicks);
}

int EnergyPlot::pointCount() const {
  return static_cast<int>(total_->count());
}

void EnergyPlot::add(const SimulationSnapshot& snapshot) {
  const double t = snapshot.time;
  if (t < lastTime_) truncateAfter(t);
  if (lastTime_ >= 0.0 && t - lastTime_ < kMinSpacingSeconds) return;
  const double kinetic = snapshot.kineticEnergy, potential = snapshot.potentialEnergy;
  const double total = kinetic + potential;
  if (lastTime_ < 0.0) low_ = high_ = total;
  low_ = std::min({low_, kinetic, potential, total});
  high_ = std::max({high_, kinetic, potential, total});
  pending_[0].append(QPointF(t, kinetic));
  pending_[1].append(QPointF(t, potential));
  pending_[2].append(QPointF(t, total));
  lastTime_ = t;
  if (!redrawTimer_.isActive()) redrawTimer_.start();
}

// The timeline went back to `t` (or the run restarted): the plot shows the run up to there, as
// it was, and goes on from there.
void EnergyPlot::truncateAfter(double t) {
  drawPending();
  if (total_->count() == 0 || total_->at(0).x() >= t) {
    clear();
    return;
  }
  qsizetype keep = total_->count();
  while (keep > 0 && total_->at(keep - 1).x() > t) --keep;
  for (QLineSeries* s : {kinetic_, potential_, total_})
    s->removePoints(static_cast<int>(keep), static_cast<int>(s->count() - keep));
  lastTime_ = total_->at(keep - 1).x();
  setRoundRange(timeAxis_, total_->at(0).x(), std::max(total_->at(0).x() + 1.0, lastTime_),
                kTimeTicks);
}

void EnergyPlot::drawPending() {
  if (pending_[2].isEmpty()) return;
  const std::array<QLineSeries*, 3> series = {kinetic_, potential_, total_};
  for (std::size_t i = 0; i < series.size(); ++i) {
    series[i]->append(pending_[i]);
    pending_[i].clear();
  }
  const double t = lastTime_;
  qsizetype old = 0;
  while (old < total_->count() && total_->at(old).x() < t - kWindowSeconds) ++old;
  if (old > 0)
    for (QLineSeries* s : series) s->removePoints(0, static_cast<int>(old));
  const double first = total_->count() > 0 ? total_->at(0).x() : 0.0;
  setRoundRange(timeAxis_, first, std::max(first + 1.0, t), kTimeTicks);
  const double margin = 0.05 * std::max(high_ - low_, 1e-9);
  setRoundRange(energyAxis_, low_ - margin, high_ + margin, kEnergyTicks);
}

}  // namespace carom::ui
