#include "energy_plot.h"

#include "simulation_snapshot.h"

#include <QChart>
#include <QChartView>
#include <QLineSeries>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>

namespace carom::ui {
namespace {

// Points closer together than this in simulated time are skipped, and only this much of the
// recent past is kept, so a long run costs the plot nothing more.
constexpr double kMinSpacingSeconds = 0.02;
constexpr double kWindowSeconds = 30.0;

}  // namespace

EnergyPlot::EnergyPlot(QWidget* parent)
    : QWidget(parent),
      chart_(new QChart),
      kinetic_(new QLineSeries),
      potential_(new QLineSeries),
      total_(new QLineSeries),
      timeAxis_(new QValueAxis),
      energyAxis_(new QValueAxis) {
  kinetic_->setName(tr("Kinetic"));
  potential_->setName(tr("Potential"));
  total_->setName(tr("Total"));
  timeAxis_->setTitleText(tr("Simulated time (s)"));
  energyAxis_->setTitleText(tr("Energy (J)"));
  chart_->addAxis(timeAxis_, Qt::AlignBottom);
  chart_->addAxis(energyAxis_, Qt::AlignLeft);
  for (QLineSeries* series : {kinetic_, potential_, total_}) {
    chart_->addSeries(series);
    series->attachAxis(timeAxis_);
    series->attachAxis(energyAxis_);
  }
  chart_->legend()->setAlignment(Qt::AlignRight);
  timeAxis_->setLabelFormat("%.1f");
  energyAxis_->setLabelFormat("%.4g");
  auto* view = new QChartView(chart_);
  view->setRenderHint(QPainter::Antialiasing);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(view);
  clear();
}

void EnergyPlot::clear() {
  for (QLineSeries* series : {kinetic_, potential_, total_}) series->clear();
  lastTime_ = -1.0;
  low_ = high_ = 0.0;
  timeAxis_->setRange(0.0, 1.0);
  energyAxis_->setRange(-1.0, 1.0);
}

int EnergyPlot::pointCount() const {
  return static_cast<int>(total_->count());
}

void EnergyPlot::add(const SimulationSnapshot& snapshot) {
  const double t = snapshot.time;
  if (t < lastTime_) clear();
  if (lastTime_ >= 0.0 && t - lastTime_ < kMinSpacingSeconds) return;
  const double kinetic = snapshot.kineticEnergy, potential = snapshot.potentialEnergy;
  const double total = kinetic + potential;
  if (pointCount() == 0) low_ = high_ = total;
  low_ = std::min({low_, kinetic, potential, total});
  high_ = std::max({high_, kinetic, potential, total});
  kinetic_->append(t, kinetic);
  potential_->append(t, potential);
  total_->append(t, total);
  lastTime_ = t;
  while (total_->count() > 0 && total_->at(0).x() < t - kWindowSeconds)
    for (QLineSeries* series : {kinetic_, potential_, total_}) series->remove(0);
  const double first = total_->count() > 0 ? total_->at(0).x() : 0.0;
  timeAxis_->setRange(first, std::max(first + 1.0, t));
  const double margin = 0.05 * std::max(high_ - low_, 1e-9);
  energyAxis_->setRange(low_ - margin, high_ + margin);
}

}  // namespace carom::ui
