#pragma once
// The Speed vs accuracy window: runs the current scene under each method, integrator and a range
// of time steps on all cores (AccuracyStudyRunner), and plots each run's error against its
// computing time. Choosing a run applies its settings to the sandbox.

#include "sim/measure/accuracy_study.h"
#include "sim/measure/method_choice.h"
#include "ui/run/accuracy_study_runner.h"

#include <QDialog>

#include <memory>
#include <optional>
#include <vector>

class QChart;
class QLineSeries;
class QLogValueAxis;
class QScatterSeries;
class QComboBox;
class QPointF;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace carom::ui {

class AccuracyWindow : public QDialog {
  Q_OBJECT
 public:
  AccuracyWindow(const carom::Scene& scene, QWidget* parent = nullptr);
  ~AccuracyWindow() override;

  // Simulated time each run covers (default 5 s); set before start().
  void setDuration(double seconds) {
    duration_ = seconds;
    showDuration();
  }
  // Auto's accuracy, which sets the tolerance of the measures it bounds and of the energy drift
  // (toleranceOf); auto's default unless set.
  void setTolerance(const AccuracyTolerance& tolerance);
  // The cheapest finished run whose plotted measure is within its tolerance (the ringed one), an
  // index into results().
  std::optional<std::size_t> cheapestWithinTolerance() const;
  void start();
  void cancel();
  bool isRunning() const { return runner_->isRunning(); }
  // In the order of the cases (exact first), whatever order the runs finish in.
  const std::vector<StudyResult>& results() const { return results_; }

 signals:
  void settingsChosen(carom::Method method, carom::Integrator integrator, double timeStep);
  void studyFinished();

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  // The measure plotted, chosen in the window.
  carom::StudyMeasure measure() const;
  // Its tolerance: the line drawn on the plot.
  double tolerance() const;
  void addResult(const StudyResult& result);
  // The table's row of results_[row], its numbers in the language's format.
  void showRow(int row);
  // What the tolerance of the measure shown is, and why, above the chart.
  void showTolerance();
  // The run chosen in the table, marked in the chart.
  void showChosen();
  // Where a run's point is drawn: zeros at the floor of the log axis.
  QPointF plotted(const StudyResult& result) const;
  void finish(const StudySummary& summary);
  void showSummary();
  // The simulated duration, and the agreement horizon once known, in the chart's title.
  void showDuration();
  void replot();
  void selectNearest(carom::Method method, const QPointF& point);
  void applySelected();
  double errorOf(const StudyResult& result) const;

  carom::Scene scene_;
  double duration_ = 5.0;
  std::vector<StudyCase> cases_;
  std::vector<StudyResult> results_;
  std::unique_ptr<AccuracyStudyRunner> runner_;
  std::optional<StudySummary> summary_;  // of the last study, once finished
  std::optional<double> horizon_;
  bool horizonKnown_ = false;
  QLabel* metricLabel_;
  QComboBox* metric_;
  QChart* chart_;
  QLogValueAxis* timeAxis_;
  QLogValueAxis* errorAxis_;
  std::vector<QScatterSeries*> series_;  // one per method, in Method order
  StudyTolerance tolerance_;
  QLabel* toleranceLabel_;
  QLineSeries* toleranceLine_;      // the tolerance of the measure shown
  QScatterSeries* cheapestMarker_;  // ringing the cheapest run within it
  QScatterSeries* chosenMarker_;    // the run chosen in the table
  QTableWidget* table_;
  QProgressBar* progress_;
  QPushButton* cancelButton_;
  QPushButton* applyButton_;
  QLabel* note_;
  QLabel* summaryLabel_;
};

}  // namespace carom::ui
