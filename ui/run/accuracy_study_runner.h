#pragma once
// Runs the Speed vs accuracy study off the GUI thread: first the exact reference and the finest
// case, which set the agreement horizon (accuracy_study.h), then every other case at once on a
// thread pool of its own, each case's result signalled on the runner's thread
// as soon as it is done (so in the order they finish, not the order of the cases).

#include "sim/measure/accuracy_study.h"

#include <QElapsedTimer>
#include <QObject>
#include <QThreadPool>

#include <memory>
#include <optional>
#include <vector>

namespace carom::ui {

class CallQueue;

// How a study went, for telling whether running the cases side by side paid.
struct StudySummary {
  int runs = 0;     // results signalled
  int threads = 0;  // threads the runs had: the pool's, at most one per case
  bool cancelled = false;
  double wallSeconds = 0.0;       // start() to finished(), the reference included
  double referenceSeconds = 0.0;  // computing time of the exact reference
  // Up to when the finest case agrees with exact; none when it parts at once.
  std::optional<double> horizon;
  double computeSeconds = 0.0;  // the runs' computeSeconds, summed
  // How many times faster than computing the reference and the runs one after another; the
  // reference is counted because the wall time includes it.
  double speedUp() const {
    return wallSeconds > 0.0 ? (referenceSeconds + computeSeconds) / wallSeconds : 0.0;
  }
};

class AccuracyStudyRunner : public QObject {
  Q_OBJECT
 public:
  explicit AccuracyStudyRunner(QObject* parent = nullptr);
  // Cancels and waits for the runs under way (each notices within a fiftieth of its duration).
  ~AccuracyStudyRunner() override;

  // Threads for the next start(); QThread::idealThreadCount() unless set.
  void setMaxThreadCount(int threads);
  int maxThreadCount() const { return pool_.maxThreadCount(); }

  // Ignored while running. `scene` and `cases` are copied.
  void start(const carom::Scene& scene, const std::vector<carom::StudyCase>& cases,
             double duration);
  // No resultReady() after this; finished() follows once the runs under way have stopped.
  void cancel();
  bool isRunning() const { return study_ != nullptr; }

 signals:
  void referenceReady(std::optional<double> horizon);
  void resultReady(carom::StudyResult result);
  void finished(carom::ui::StudySummary summary);

 private:
  struct Study;
  // The queued calls of the pool's tasks, on the runner's thread.
  void referenceDone(const std::shared_ptr<Study>& study, double computeSeconds,
                     std::size_t casesQueued);
  void caseDone(const std::shared_ptr<Study>& study, const std::optional<StudyResult>& result);
  void finishIfDone();

  // What the pool's tasks touch is theirs to share (scene, cases, reference, cancel flag), so a
  // task outlives nothing it needs; what they tell the runner comes as queued calls to it.
  std::shared_ptr<Study> study_;
  QElapsedTimer wallClock_;
  StudySummary summary_;
  bool referenceDone_ = false;
  std::size_t casesLeft_ = 0;  // queued cases yet to report
  CallQueue* calls_;           // a child: the tasks' reports, run on the runner's thread
  QThreadPool pool_;
};

}  // namespace carom::ui

Q_DECLARE_METATYPE(carom::StudyResult)
Q_DECLARE_METATYPE(carom::ui::StudySummary)
