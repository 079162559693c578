#include "ui/run/accuracy_study_runner.h"

#include "ui/run/call_queue.h"
#include "ui/run/thread_handover.h"

#include <QPointer>
#include <QThread>

#include <algorithm>
#include <atomic>

namespace carom::ui {

namespace {

// QThreadPool hands each task (and all its captures) to a thread through Qt's own lock, which
// ThreadSanitizer cannot see (Debian's Qt is not built with it). So every start() says that
// what came before it is handed over, and every task takes it over before it reads a capture:
// on this address, which a task can name without reading one.
char poolHandOver;

}  // namespace

// What the tasks share.
struct AccuracyStudyRunner::Study {
  carom::Scene scene;
  std::vector<StudyCase> cases;
  double duration = 0.0;
  // Written by the reference task before it queues the cases.
  StudyReference reference;
  std::optional<StudyResult> finest;
  std::atomic<bool> cancel{false};
};

AccuracyStudyRunner::AccuracyStudyRunner(QObject* parent)
    : QObject(parent), calls_(new CallQueue(this)) {
  pool_.setMaxThreadCount(QThread::idealThreadCount());
}

AccuracyStudyRunner::~AccuracyStudyRunner() {
  if (study_) study_->cancel = true;
  // The tasks only post calls to this object, never wait for it, so the GUI thread can wait
  // here; calls posted and not yet run die with the queue, a child deleted after this.
  pool_.waitForDone();
}

void AccuracyStudyRunner::setMaxThreadCount(int threads) {
  pool_.setMaxThreadCount(std::max(1, threads));
}

void AccuracyStudyRunner::start(const carom::Scene& scene, const std::vector<StudyCase>& cases,
                                double duration) {
  if (study_) return;
  auto study = std::make_shared<Study>();
  study->scene = scene;
  study->cases = cases;
  study->duration = duration;
  study_ = study;
  summary_ = StudySummary{};
  summary_.threads = std::min(pool_.maxThreadCount(), std::max(1, int(cases.size())));
  referenceDone_ = false;
  casesLeft_ = 0;
  wallClock_.start();

  // The reference first, as a task of its own; it queues the cases once they can use it. Every
  // task keeps `study` alive and reports to `this`, which outlives them (the destructor waits).
  handOver(&poolHandOver);
  pool_.start([this, study] {
    takeOver(&poolHandOver);
    const double start = threadCpuSeconds();
    study->reference = exactReference(study->scene, study->duration, &study->cancel);
    const double seconds = threadCpuSeconds() - start;
    // The finest case sets the horizon the others' position errors are taken at, so it runs
    // before them; its own result is reported like theirs.
    const std::optional<std::size_t> finest = finestCase(study->cases);
    if (finest && !study->cancel) {
      StudyResult result = runStudyCase(study->scene, study->cases[*finest], study->duration,
                                        study->reference, &study->cancel);
      double radii = 0.0;
      for (const Ball& ball : study->scene.balls) radii += ball.radius;
      const double meanRadius =
          study->scene.balls.empty() ? 0.0 : radii / double(study->scene.balls.size());
      setAgreementHorizon(study->reference, result, meanRadius);
      result.positionError = positionErrorAtHorizon(result, study->reference);
      if (!study->cancel) study->finest = result;
    }
    std::vector<std::size_t> queued;
    for (std::size_t i = 0; i < study->cases.size() && !study->cancel; ++i)
      if (i != finest) queued.push_back(i);
    // Posted before the cases are queued, so it arrives before any of their results. The calls
    // cross to the runner's thread under CallQueue's lock, which ThreadSanitizer sees.
    calls_->post(
        [this, study, seconds, count = queued.size()] { referenceDone(study, seconds, count); });
    for (std::size_t i : queued) {
      handOver(&poolHandOver);
      pool_.start([this, study, i] {
        takeOver(&poolHandOver);
        std::optional<StudyResult> result;
        if (!study->cancel) {
          result = runStudyCase(study->scene, study->cases[i], study->duration, study->reference,
                                &study->cancel);
          // A run cut short is no measure of anything.
          if (study->cancel) result.reset();
        }
        calls_->post([this, study, result] { caseDone(study, result); });
      });
    }
  });
}

void AccuracyStudyRunner::cancel() {
  if (!study_) return;
  study_->cancel = true;
  summary_.cancelled = true;
}

void AccuracyStudyRunner::referenceDone(const std::shared_ptr<Study>& study, double computeSeconds,
                                        std::size_t casesQueued) {
  if (study != study_) return;
  referenceDone_ = true;
  summary_.referenceSeconds = computeSeconds;
  summary_.horizon = study->reference.horizon();
  casesLeft_ = casesQueued;
  if (!summary_.cancelled) {
    const QPointer<AccuracyStudyRunner> alive(this);
    emit referenceReady(summary_.horizon);
    if (!alive) return;  // a receiver deleted the runner
    if (study->finest) {
      ++summary_.runs;
      summary_.computeSeconds += study->finest->computeSeconds;
      emit resultReady(*study->finest);
      if (!alive) return;
    }
  }
  finishIfDone();
}

void AccuracyStudyRunner::caseDone(const std::shared_ptr<Study>& study,
                                   const std::optional<StudyResult>& result) {
  if (study != study_) return;
  --casesLeft_;
  if (result && !summary_.cancelled) {
    ++summary_.runs;
    summary_.computeSeconds += result->computeSeconds;
    const QPointer<AccuracyStudyRunner> alive(this);
    emit resultReady(*result);
    if (!alive) return;  // a receiver deleted the runner
  }
  finishIfDone();
}

void AccuracyStudyRunner::finishIfDone() {
  if (!study_ || !referenceDone_ || casesLeft_ > 0) return;
  summary_.wallSeconds = wallClock_.nsecsElapsed() * 1e-9;
  study_.reset();
  emit finished(summary_);
}

}  // namespace carom::ui
