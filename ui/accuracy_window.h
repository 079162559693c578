#pragma once
// The Speed vs accuracy window: runs the current scene under each method, integrator and a range
// of time steps on all cores (AccuracyStudyRunner), and plots each run's error against its
// computing time. Choosing a run applies its settings to the sandbox.

#include "sim/accuracy_study.h"
#include "sim/method_choice.h"
#include "ui/accuracy_study_runner.h"

#include <QDialog>

#include <memory>
#include <optional>
#include <vector>

class QChart;
class QLineSeries;
class QLogValueAxis;
class QScatterSeries;
class QComboBox;
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
  // The accuracy the plots draw, and the cheapest run that meets it; auto's default unless set.
  void setTolerance(const AccuracyTolerance& tolerance);
  // The cheapest finished run that meets the tolerance, an index into results().
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
  void addResult(const StudyResult& result);
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
  AccuracyTolerance tolerance_;
  QLineSeries* toleranceLine_;      // on the metrics the tolerance bounds
  QScatterSeries* cheapestMarker_;  // ringing the cheapest run within the tolerance
  QTableWidget* table_;
  QProgressBar* progress_;
  QPushButton* cancelButton_;
  QPushButton* applyButton_;
  QLabel* note_;
  QLabel* summaryLabel_;
};

}  // namespace carom::ui
