#include "ui/accuracy_window.h"

#include "ui/call_queue.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
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
const std::vector<double> kStepFactors{0.25, 0.5, 1.0, 2.0, 4.0};

QString caseName(const StudyCase& c) {
  if (c.method == Method::Exact) return QString::fromUtf8(methodName(c.method));
  return QString("%1, %2, dt %3 s")
      .arg(QString::fromUtf8(methodName(c.method)), QString::fromUtf8(integratorName(c.integrator)))
      .arg(c.timeStep, 0, 'g', 4);
}

}  // namespace

AccuracyWindow::AccuracyWindow(const carom::Scene& scene, QWidget* parent)
    : QDialog(parent), scene_(scene), calls_(new CallQueue(this)) {
  metricLabel_ = new QLabel;
  metric_ = new QComboBox;
  metric_->addItems(QStringList(4));  // named by retranslate()
  connect(metric_, &QComboBox::currentIndexChanged, this, &AccuracyWindow::replot);

  chart_ = new QChart;
  chart_->legend()->setAlignment(Qt::AlignBottom);
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
  auto* chartView = new QChartView(chart_);
  chartView->setRenderHint(QPainter::Antialiasing);
  chartView->setMinimumSize(520, 360);

  table_ = new QTableWidget(0, 6);
  table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);

  progress_ = new QProgressBar;
  cancelButton_ = new QPushButton;
  connect(cancelButton_, &QPushButton::clicked, this, &AccuracyWindow::cancel);
  applyButton_ = new QPushButton;
  applyButton_->setEnabled(false);
  connect(applyButton_, &QPushButton::clicked, this, &AccuracyWindow::applySelected);
  connect(table_, &QTableWidget::itemSelectionChanged, this,
          [this] { applyButton_->setEnabled(!table_->selectedItems().isEmpty()); });
  connect(table_, &QTableWidget::cellDoubleClicked, this, [this] { applySelected(); });
  note_ = new QLabel;
  note_->setWordWrap(true);
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
  layout->addWidget(chartView, 2);
  layout->addWidget(table_, 1);
  layout->addWidget(note_);
  layout->addLayout(bottom);
}

void AccuracyWindow::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QDialog::changeEvent(event);
}

void AccuracyWindow::retranslate() {
  setWindowTitle(tr("Speed vs accuracy"));
  metricLabel_->setText(tr("Error:"));
  const QStringList metrics{tr("Position error against exact (m)"), tr("Relative energy drift"),
                            tr("Deepest penetration (m)"), tr("Escaped balls")};
  for (int i = 0; i < metrics.size(); ++i) metric_->setItemText(i, metrics[i]);
  timeAxis_->setTitleText(tr("Computing time (s)"));
  table_->setHorizontalHeaderLabels({tr("Run"), tr("Computing time (s)"), tr("Position error"),
                                     tr("Energy drift"), tr("Penetration"), tr("Escaped")});
  cancelButton_->setText(tr("Cancel"));
  applyButton_->setText(tr("Apply Selected Settings"));
  note_->setText(
      tr("Each point is one run of the current scene; lower and further left is better. Choose "
         "a run to use its settings."));
  replot();  // the error axis is named after the metric
}

AccuracyWindow::~AccuracyWindow() {
  cancel_ = true;
  if (thread_.joinable()) thread_.join();
}

void AccuracyWindow::start() {
  if (running_) return;
  cases_ = studyCases(scene_.world, kStepFactors);
  results_.clear();
  table_->setRowCount(0);
  progress_->setRange(0, static_cast<int>(cases_.size()) + 1);
  progress_->setValue(0);
  cancel_ = false;
  running_ = true;
  cancelButton_->setEnabled(true);
  // The runs happen on their own thread; each result comes back as a queued call (calls_, on
  // the GUI thread).
  thread_ = std::thread([this, scene = scene_, cases = cases_, duration = duration_] {
    const std::vector<Vec3> reference = exactFinalPositions(scene, duration);
    calls_->post([this] { progress_->setValue(1); });
    for (const StudyCase& c : cases) {
      if (cancel_) break;
      const StudyResult result = runStudyCase(scene, c, duration, reference, &cancel_);
      if (cancel_) break;
      calls_->post([this, result] { addResult(result); });
    }
    calls_->post([this] { finish(); });
  });
}

void AccuracyWindow::cancel() {
  cancel_ = true;
  cancelButton_->setEnabled(false);
}

void AccuracyWindow::addResult(const StudyResult& result) {
  results_.push_back(result);
  const int row = table_->rowCount();
  table_->insertRow(row);
  const QStringList cells{caseName(result.settings),
                          QString::number(result.computeSeconds, 'g', 3),
                          QString::number(result.positionError, 'g', 3),
                          QString::number(result.energyDrift, 'g', 3),
                          QString::number(result.maxPenetration, 'g', 3),
                          QString::number(result.escaped)};
  for (int column = 0; column < cells.size(); ++column)
    table_->setItem(row, column, new QTableWidgetItem(cells[column]));
  progress_->setValue(progress_->value() + 1);
  replot();
}

void AccuracyWindow::finish() {
  if (thread_.joinable()) thread_.join();
  running_ = false;
  cancelButton_->setEnabled(false);
  progress_->setValue(progress_->maximum());
  emit studyFinished();
}

double AccuracyWindow::errorOf(const StudyResult& result) const {
  switch (metric_->currentIndex()) {
    case 1:
      return result.energyDrift;
    case 2:
      return result.maxPenetration;
    case 3:
      return result.escaped;
    default:
      return result.positionError;
  }
}

void AccuracyWindow::replot() {
  double lowTime = 1e300, highTime = 0, lowError = 1e300, highError = 0;
  for (std::size_t m = 0; m < series_.size(); ++m) {
    QList<QPointF> points;
    for (const StudyResult& r : results_) {
      if (r.settings.method != Method(m)) continue;
      const double x = std::max(r.computeSeconds, 1e-7);
      const double y = std::max(errorOf(r), kErrorFloor);
      points.append({x, y});
      lowTime = std::min(lowTime, x);
      highTime = std::max(highTime, x);
      lowError = std::min(lowError, y);
      highError = std::max(highError, y);
    }
    series_[m]->replace(points);
  }
  errorAxis_->setTitleText(metric_->currentText());
  if (highTime > 0) {
    timeAxis_->setRange(lowTime / 2, highTime * 2);
    errorAxis_->setRange(lowError / 10, highError * 10);
    // About six labelled ticks whatever the span, so the labels stay readable.
    const double decades = std::log10(highError * 10 / (lowError / 10));
    errorAxis_->setBase(std::pow(10.0, std::max(1.0, std::ceil(decades / 6.0))));
  }
}

void AccuracyWindow::selectNearest(Method method, const QPointF& point) {
  int best = -1;
  double bestDistance = 1e300;
  for (std::size_t i = 0; i < results_.size(); ++i) {
    if (results_[i].settings.method != method) continue;
    const double dx = std::log10(std::max(results_[i].computeSeconds, 1e-7) / point.x());
    const double dy = std::log10(std::max(errorOf(results_[i]), kErrorFloor) / point.y());
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
