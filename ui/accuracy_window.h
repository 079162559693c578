#pragma once
// The Speed vs accuracy window: runs the current scene under each method, integrator and a range
// of time steps on a background thread, and plots each run's error against its computing time.
// Choosing a run applies its settings to the sandbox.

#include "sim/accuracy_study.h"

#include <QDialog>

#include <atomic>
#include <thread>
#include <vector>

class QChart;
class QLogValueAxis;
class QScatterSeries;
class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace carom::ui {

class CallQueue;

class AccuracyWindow : public QDialog {
  Q_OBJECT
 public:
  AccuracyWindow(const carom::Scene& scene, QWidget* parent = nullptr);
  ~AccuracyWindow() override;

  // Simulated time each run covers (default 5 s); set before start().
  void setDuration(double seconds) { duration_ = seconds; }
  void start();
  void cancel();
  bool isRunning() const { return running_; }
  const std::vector<StudyResult>& results() const { return results_; }

 signals:
  void settingsChosen(carom::Method method, carom::Integrator integrator, double timeStep);
  void studyFinished();

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void addResult(const StudyResult& result);
  void finish();
  void replot();
  void selectNearest(carom::Method method, const QPointF& point);
  void applySelected();
  double errorOf(const StudyResult& result) const;

  carom::Scene scene_;
  double duration_ = 5.0;
  std::vector<StudyCase> cases_;
  std::vector<StudyResult> results_;
  std::atomic<bool> cancel_{false};
  std::thread thread_;
  CallQueue* calls_;  // the study thread's results, run on the GUI thread
  bool running_ = false;
  QLabel* metricLabel_;
  QComboBox* metric_;
  QChart* chart_;
  QLogValueAxis* timeAxis_;
  QLogValueAxis* errorAxis_;
  std::vector<QScatterSeries*> series_;  // one per method, in Method order
  QTableWidget* table_;
  QProgressBar* progress_;
  QPushButton* cancelButton_;
  QPushButton* applyButton_;
  QLabel* note_;
};

}  // namespace carom::ui
