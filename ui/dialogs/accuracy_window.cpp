#include "ui/dialogs/accuracy_window.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineSeries>
#include <QLocale>
#include <QLogValueAxis>
#include <QProgressBar>
#include <QPushButton>
#include <QScatterSeries>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace carom::ui {
namespace {

// Errors of exactly zero cannot sit on a log axis: they are drawn at this floor.
constexpr double kErrorFloor = 1e-16;
// No escape is the tolerance, and zero sits at the floor: the line runs between none and one.
constexpr double kEscapedLine = 0.5;

QString caseName(const StudyCase& c) {
  if (c.method == Method::Exact) return QString::fromUtf8(methodName(c.method));
  return QString("%1, %2, dt %3 s")
      .arg(QString::fromUtf8(methodName(c.method)), QString::fromUtf8(integratorName(c.integrator)),
           QLocale().toString(c.timeStep, 'g', 4));
}

QString number(double value) {
  return QLocale().toString(value, 'g', 3);
}

}  // namespace

AccuracyWindow::AccuracyWindow(const carom::Scene& scene, QWidget* parent)
    : QDialog(parent), scene_(scene), runner_(std::make_unique<AccuracyStudyRunner>()) {
  connect(runner_.get(), &AccuracyStudyRunner::referenceReady, this,
          [this](std::optional<double> horizon) {
            horizon_ = horizon;
            horizonKnown_ = true;
            progress_->setValue(progress_->value() + 1);
            showDuration();
          });
  connect(runner_.get(), &AccuracyStudyRunner::resultReady, this, &AccuracyWindow::addResult);
  connect(runner_.get(), &AccuracyStudyRunner::finished, this, &AccuracyWindow::finish);
  metricLabel_ = new QLabel;
  metric_ = new QComboBox;
  metric_->addItems(QStringList(kStudyMeasures));  // named by retranslate()
  connect(metric_, &QComboBox::currentIndexChanged, this, &AccuracyWindow::replot);

  toleranceLabel_ = new QLabel;
  toleranceLabel_->setObjectName("toleranceLabel");
  toleranceLabel_->setWordWrap(true);

  chart_ = new QChart;
  chart_->legend()->setAlignment(Qt::AlignBottom);
  chart_->setLocalizeNumbers(true);
  timeAxis_ = new QLogValueAxis;
  timeAxis_->setLabelFormat("%.0e");
  errorAxis_ = new QLogValueAxis;
  errorAxis_->setLabelFormat("%.0e");
  chart_->addAxis(timeAxis_, Qt::AlignBottom);
  chart_->addAxis(errorAxis_, Qt::AlignLeft);
  for (Method method : {Method::Exact, Method::Swept, Method::Discrete}) {
    auto* series = new QScatterSeries;
    series->setName(QString::fromUtf8(methodName(method)));
    series->setMarkerSize(9);
    chart_->addSeries(series);
    series->attachAxis(timeAxis_);
    series->attachAxis(errorAxis_);
    // Clicking a point selects its run in the table.
    connect(series, &QScatterSeries::clicked, this,
            [this, method](const QPointF& point) { selectNearest(method, point); });
    series_.push_back(series);
  }
  toleranceLine_ = new QLineSeries;
  toleranceLine_->setObjectName("toleranceLine");
  toleranceLine_->setPen(QPen(Qt::darkRed, 1.5, Qt::DashLine));
  chart_->addSeries(toleranceLine_);
  toleranceLine_->attachAxis(timeAxis_);
  toleranceLine_->attachAxis(errorAxis_);
  cheapestMarker_ = new QScatterSeries;
  cheapestMarker_->setObjectName("cheapestRun");
  cheapestMarker_->setMarkerSize(20);
  cheapestMarker_->setBrush(Qt::NoBrush);
  cheapestMarker_->setPen(QPen(Qt::darkRed, 2.0));
  chart_->addSeries(cheapestMarker_);
  cheapestMarker_->attachAxis(timeAxis_);
  cheapestMarker_->attachAxis(errorAxis_);
  // The run chosen in the table: a square around its point, unlike the cheapest run's ring.
  chosenMarker_ = new QScatterSeries;
  chosenMarker_->setObjectName("chosenRun");
  chosenMarker_->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
  chosenMarker_->setMarkerSize(18);
  chosenMarker_->setBrush(Qt::NoBrush);
  chosenMarker_->setPen(QPen(Qt::black, 2.0));
  chart_->addSeries(chosenMarker_);
  chosenMarker_->attachAxis(timeAxis_);
  chosenMarker_->attachAxis(errorAxis_);
  auto* chartView = new QChartView(chart_);
  chartView->setRenderHint(QPainter::Antialiasing);
  chartView->setMinimumSize(520, 360);

  table_ = new QTableWidget(0, 8);
  // Every column as wide as its header and cells (the run's name too), the last taking what is
  // left; a narrow window scrolls rather than cut a header or a name short.
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);

  progress_ = new QProgressBar;
  cancelButton_ = new QPushButton;
  connect(cancelButton_, &QPushButton::clicked, this, &AccuracyWindow::cancel);
  applyButton_ = new QPushButton;
  applyButton_->setEnabled(false);
  connect(applyButton_, &QPushButton::clicked, this, &AccuracyWindow::applySelected);
  connect(table_, &QTableWidget::itemSelectionChanged, this, [this] {
    applyButton_->setEnabled(!table_->selectedItems().isEmpty());
    showChosen();
  });
  connect(table_, &QTableWidget::cellDoubleClicked, this, [this] { applySelected(); });
  note_ = new QLabel;
  note_->setWordWrap(true);
  summaryLabel_ = new QLabel;
  summaryLabel_->setWordWrap(true);
  retranslate();
  resize(900, 760);

  auto* top = new QHBoxLayout;
  top->addWidget(metricLabel_);
  top->addWidget(metric_, 1);
  auto* bottom = new QHBoxLayout;
  bottom->addWidget(progress_, 1);
  bottom->addWidget(cancelButton_);
  bottom->addWidget(applyButton_);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(top);
  layout->addWidget(toleranceLabel_);
  layout->addWidget(chartView, 3);
  layout->addWidget(table_, 1);
  layout->addWidget(note_);
  layout->addWidget(summaryLabel_);
  layout->addLayout(bottom);
}

void AccuracyWindow::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QDialog::changeEvent(event);
}

void AccuracyWindow::retranslate() {
  setWindowTitle(tr("Speed vs accuracy"));
  metricLabel_->setText(tr("Error:"));
  const QStringList metrics{tr("Position error against exact at the horizon (m)"),
                            tr("Relative energy drift"),
                            tr("Deepest penetration (m)"),
                            tr("Escaped balls"),
                            tr("Speed distribution against exact (KS distance)"),
                            tr("Position distribution against exact (KS distance)"),
                            tr("Energy error per simulated second (auto's measure)")};
  for (int i = 0; i < metrics.size(); ++i) metric_->setItemText(i, metrics[i]);
  chart_->setLocale(QLocale());
  timeAxis_->setTitleText(tr("Computing time (s)"));
  toleranceLine_->setName(tr("Tolerance"));
  cheapestMarker_->setName(tr("Cheapest within the tolerance"));
  chosenMarker_->setName(tr("Chosen run"));
  table_->setHorizontalHeaderLabels(
      {tr("Run"), tr("Computing time (s)"), tr("Position error at horizon (m)"), tr("Energy drift"),
       tr("Penetration (m)"), tr("Escaped"), tr("Speeds (KS)"), tr("Positions (KS)")});
  cancelButton_->setText(tr("Cancel"));
  applyButton_->setText(tr("Apply Selected Settings"));
  note_->setText(
      tr("Each point is one run of the current scene; lower and further left is better. Choose "
         "a run to use its settings. Paths part from exact ones with time, whatever the method: "
         "position error is taken at the horizon up to which the finest setting agrees with "
         "exact, and whole runs are judged by energy, penetration, escapes and distributions."));
  showDuration();
  showSummary();
  for (int row = 0; row < table_->rowCount(); ++row) showRow(row);  // numbers in the locale's form
  replot();  // the error axis is named after the metric
}

AccuracyWindow::~AccuracyWindow() {
  // Before the widgets go: stops the runs under way and waits for them.
  runner_.reset();
}

void AccuracyWindow::start() {
  if (isRunning()) return;
  cases_ = studyCases(scene_.world, kStudyStepFactors);
  results_.clear();
  table_->setRowCount(0);
  progress_->setRange(0, static_cast<int>(cases_.size()) + 1);
  progress_->setValue(0);
  summary_.reset();
  horizon_.reset();
  horizonKnown_ = false;
  showDuration();
  showSummary();
  cancelButton_->setEnabled(true);
  runner_->start(scene_, cases_, duration_);
}

void AccuracyWindow::cancel() {
  runner_->cancel();
  cancelButton_->setEnabled(false);
}

void AccuracyWindow::addResult(const StudyResult& result) {
  // Results come in the order the runs finish; rows and results_ stay in the order of cases_.
  const auto caseIndex = [this](const StudyResult& r) {
    const StudyCase& s = r.settings;
    const auto found = std::find_if(cases_.begin(), cases_.end(), [&s](const StudyCase& c) {
      return c.method == s.method && c.integrator == s.integrator && c.timeStep == s.timeStep;
    });
    return found - cases_.begin();
  };
  const auto at = std::upper_bound(
      results_.begin(), results_.end(), result,
      [&](const StudyResult& a, const StudyResult& b) { return caseIndex(a) < caseIndex(b); });
  const int row = static_cast<int>(at - results_.begin());
  results_.insert(at, result);
  table_->insertRow(row);
  showRow(row);
  progress_->setValue(progress_->value() + 1);
  replot();
}

void AccuracyWindow::showRow(int row) {
  const StudyResult& result = results_[static_cast<std::size_t>(row)];
  const QStringList cells{caseName(result.settings),
                          number(result.computeSeconds),
                          std::isnan(result.positionError)
                              ? QStringLiteral("\u2014")  // no horizon: nothing to measure
                              : number(result.positionError),
                          number(result.energyDrift),
                          number(result.maxPenetration),
                          QLocale().toString(result.escaped),
                          number(result.speedDistribution),
                          number(result.positionDistribution)};
  for (int column = 0; column < cells.size(); ++column) {
    if (QTableWidgetItem* item = table_->item(row, column))
      item->setText(cells[column]);
    else
      table_->setItem(row, column, new QTableWidgetItem(cells[column]));
  }
}

void AccuracyWindow::finish(const StudySummary& summary) {
  summary_ = summary;
  showSummary();
  cancelButton_->setEnabled(false);
  progress_->setValue(progress_->maximum());
  emit studyFinished();
}

void AccuracyWindow::showSummary() {
  if (!summary_) {
    summaryLabel_->clear();
    return;
  }
  const QLocale locale;
  const QString runs = tr("%Ln runs", nullptr, summary_->runs);
  // "3.1", "0.0046", "12": two significant digits, without an exponent.
  const double seconds = summary_->wallSeconds;
  const QString wall =
      seconds >= 10.0 ? locale.toString(seconds, 'f', 0) : locale.toString(seconds, 'g', 2);
  if (summary_->cancelled) {
    summaryLabel_->setText(tr("Cancelled after %1 in %2 s.").arg(runs, wall));
    return;
  }
  const QString threads = tr("%Ln threads", nullptr, summary_->threads);
  // The speed-up sets the reference and the runs one after another against the wall time; a
  // study of a few milliseconds is mostly overhead and may gain nothing.
  const double speedUp = summary_->speedUp();
  if (speedUp < 1.05) {
    summaryLabel_->setText(
        tr("%1 in %2 s on %3, no faster than one after another").arg(runs, wall, threads));
    return;
  }
  summaryLabel_->setText(tr("%1 in %2 s on %3, %4× faster than one after another")
                             .arg(runs, wall, threads, locale.toString(speedUp, 'f', 1)));
}

StudyMeasure AccuracyWindow::measure() const {
  return static_cast<StudyMeasure>(std::clamp(metric_->currentIndex(), 0, kStudyMeasures - 1));
}

double AccuracyWindow::errorOf(const StudyResult& result) const {
  return measureOf(result, measure());
}

double AccuracyWindow::tolerance() const {
  return toleranceOf(measure(), tolerance_, scene_, duration_);
}

QPointF AccuracyWindow::plotted(const StudyResult& result) const {
  return {std::max(result.computeSeconds, 1e-7), std::max(errorOf(result), kErrorFloor)};
}

void AccuracyWindow::showTolerance() {
  const double bound = tolerance();
  const QLocale locale;
  const auto value = [&](double v) { return locale.toString(v, 'g', 3); };
  QString name, within;
  switch (measure()) {
    case StudyMeasure::PositionError:
      name = tr("position error at the horizon");
      within = tr("at most %1 m, a tenth of the mean radius: as close as the finest setting "
                  "stays to exact up to the horizon")
                   .arg(value(bound));
      break;
    case StudyMeasure::EnergyDrift:
      name = tr("relative energy drift");
      within = tr("at most %1: auto's energy error per second times the %2 s of the run")
                   .arg(value(bound), value(duration_));
      break;
    case StudyMeasure::Penetration:
      name = tr("deepest penetration");
      within = tr("at most %1 m: auto's %2 % of the smallest radius")
                   .arg(value(bound), value(100.0 * tolerance_.penetrationFraction));
      break;
    case StudyMeasure::Escaped:
      name = tr("escaped balls");
      within = tr("none, as auto asks");
      break;
    case StudyMeasure::SpeedDistribution:
    case StudyMeasure::PositionDistribution:
      name = measure() == StudyMeasure::SpeedDistribution
                 ? tr("speed distribution against exact")
                 : tr("position distribution against exact");
      within = tr("a KS distance of at most %1: %Ln balls cannot tell it from exact's at 5 % "
                  "significance",
                  nullptr, static_cast<int>(scene_.balls.size()))
                   .arg(value(bound));
      break;
    case StudyMeasure::EnergyErrorPerSecond:
      name = tr("energy error per simulated second");
      within = tr("at most %1 per second, auto's accuracy").arg(value(bound));
      break;
  }
  toleranceLabel_->setText(
      tr("Tolerance on %1: %2. Ringed: the cheapest run within it.").arg(name, within));
}

void AccuracyWindow::showChosen() {
  QList<QPointF> chosen;
  const QList<QTableWidgetItem*> selected = table_->selectedItems();
  if (!selected.isEmpty()) {
    const int row = selected.first()->row();
    if (row >= 0 && row < static_cast<int>(results_.size()) &&
        !std::isnan(errorOf(results_[static_cast<std::size_t>(row)])))
      chosen.append(plotted(results_[static_cast<std::size_t>(row)]));
  }
  chosenMarker_->replace(chosen);
}

void AccuracyWindow::replot() {
  double lowTime = 1e300, highTime = 0, lowError = 1e300, highError = 0;
  for (std::size_t m = 0; m < series_.size(); ++m) {
    QList<QPointF> points;
    for (const StudyResult& r : results_) {
      if (r.settings.method != Method(m) || std::isnan(errorOf(r))) continue;
      const QPointF point = plotted(r);
      const double x = point.x();
      const double y = point.y();
      points.append(point);
      lowTime = std::min(lowTime, x);
      highTime = std::max(highTime, x);
      lowError = std::min(lowError, y);
      highError = std::max(highError, y);
    }
    series_[m]->replace(points);
  }
  // The tolerance of the measure shown, and the cheapest run under it: the ring, the line and
  // the points all speak of the same measure (auto's accuracy bounds only some of them).
  const double bound = tolerance();
  const double lineAt = measure() == StudyMeasure::Escaped ? kEscapedLine : bound;
  QList<QPointF> line;
  if (highTime > 0 && lineAt > 0.0 && std::isfinite(lineAt)) {
    line = {{lowTime / 2, lineAt}, {highTime * 2, lineAt}};
    lowError = std::min(lowError, lineAt);
    highError = std::max(highError, lineAt);
  }
  toleranceLine_->replace(line);
  QList<QPointF> cheapest;
  if (const std::optional<std::size_t> best = cheapestWithinTolerance())
    cheapest.append(plotted(results_[*best]));
  cheapestMarker_->replace(cheapest);
  showChosen();
  showTolerance();
  // Short: the axis is as long as the plot is high, and the box above names the metric in full.
  const QStringList axisTitles{tr("Position error (m)"),     tr("Energy drift"),
                               tr("Penetration (m)"),        tr("Escaped balls"),
                               tr("Speeds (KS distance)"),   tr("Positions (KS distance)"),
                               tr("Energy error per second")};
  errorAxis_->setTitleText(axisTitles[static_cast<int>(measure())]);
  if (highTime > 0) {
    timeAxis_->setRange(lowTime / 2, highTime * 2);
    errorAxis_->setRange(lowError / 10, highError * 10);
    // About six labelled ticks whatever the span, so the labels stay readable.
    const double decades = std::log10(highError * 10 / (lowError / 10));
    errorAxis_->setBase(std::pow(10.0, std::max(1.0, std::ceil(decades / 6.0))));
  }
}

void AccuracyWindow::setTolerance(const AccuracyTolerance& tolerance) {
  if (!validateTolerance(tolerance).empty()) return;
  tolerance_ = {tolerance.energyPerSecond, tolerance.penetrationFraction};
  replot();
}

std::optional<std::size_t> AccuracyWindow::cheapestWithinTolerance() const {
  return cheapestWithin(results_, measure(), tolerance());
}

void AccuracyWindow::showDuration() {
  const QLocale locale;
  const QString duration = tr("Each run: %1 s simulated").arg(locale.toString(duration_, 'g', 3));
  if (!horizonKnown_) {
    chart_->setTitle(duration);
  } else if (horizon_) {
    chart_->setTitle(tr("%1; the finest setting agrees with exact up to %2 s")
                         .arg(duration, locale.toString(*horizon_, 'g', 3)));
  } else {
    chart_->setTitle(tr("%1; even the finest setting parts from exact at once: no position error")
                         .arg(duration));
  }
}

void AccuracyWindow::selectNearest(Method method, const QPointF& point) {
  int best = -1;
  double bestDistance = 1e300;
  for (std::size_t i = 0; i < results_.size(); ++i) {
    if (results_[i].settings.method != method) continue;
    const QPointF at = plotted(results_[i]);
    const double dx = std::log10(at.x() / point.x());
    const double dy = std::log10(at.y() / point.y());
    if (dx * dx + dy * dy < bestDistance) {
      bestDistance = dx * dx + dy * dy;
      best = static_cast<int>(i);
    }
  }
  if (best >= 0) table_->selectRow(best);
}

void AccuracyWindow::applySelected() {
  const QList<QTableWidgetItem*> selected = table_->selectedItems();
  if (selected.isEmpty()) return;
  const int row = selected.first()->row();
  if (row < 0 || row >= static_cast<int>(results_.size())) return;
  const StudyCase& c = results_[row].settings;
  emit settingsChosen(c.method, c.integrator, c.timeStep);
}

}  // namespace carom::ui
