// The Speed vs accuracy study on its thread pool, without a window: one result per case, the same
// results whatever the number of threads, a prompt cancel, and a runner destroyed mid-study.
// Times are not checked: they depend on the machine and on what else it runs.

#include "scene_helpers.h"
#include "sim/model/scene_builders.h"
#include "ui/run/accuracy_study_runner.h"

#include <QSignalSpy>
#include <QThread>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <tuple>
#include <vector>

using carom::Integrator;
using carom::Method;
using carom::StudyCase;
using carom::StudyResult;
using carom::ui::AccuracyStudyRunner;
using carom::ui::StudySummary;

namespace {

// A few balls bouncing under gravity in a closed box: a study of it takes a fraction of a second
// for a second of simulated time.
carom::Scene smallScene() {
  return carom::makeGasInBox(27, 0.2, carom::Vec3(0.0, -9.81, 0.0), 7);
}

// A study that takes long enough to cancel or destroy mid-way: a cheap reference, and runs of
// tiny time steps (some 5 s of computing each here) between cheap ones of coarse steps. A tenth
// of it under the sanitizers, whose instrumented runs are ten times slower: the reference alone
// took 40 s there.
double longStudySeconds() {
  return carom::testing::sanitizerRun() ? 10.0 : 100.0;
}

std::vector<StudyCase> longCasesOf(const carom::Scene& scene) {
  return carom::studyCases(scene.world, {0.02, 4.0});
}

std::vector<StudyCase> casesOf(const carom::Scene& scene) {
  return carom::studyCases(scene.world, {0.5, 1.0, 2.0});
}

using CaseKey = std::tuple<Method, Integrator, double>;

CaseKey keyOf(const StudyCase& c) {
  return {c.method, c.integrator, c.timeStep};
}

struct StudyRun {
  std::vector<StudyResult> results;  // in the order they came
  int referenceSignals = 0;
  std::optional<double> horizon;  // as referenceReady gave it
  bool referenceBeforeResults = true;
  std::optional<StudySummary> summary;
};

// Runs a whole study on `threads` threads and waits for it.
StudyRun runStudy(const carom::Scene& scene, const std::vector<StudyCase>& cases, double duration,
                  int threads) {
  StudyRun run;
  AccuracyStudyRunner runner;
  runner.setMaxThreadCount(threads);
  QObject::connect(&runner, &AccuracyStudyRunner::referenceReady,
                   [&run](std::optional<double> horizon) {
                     ++run.referenceSignals;
                     run.horizon = horizon;
                     run.referenceBeforeResults = run.referenceBeforeResults && run.results.empty();
                   });
  QObject::connect(&runner, &AccuracyStudyRunner::resultReady, [&run](const StudyResult& r) {
    if (run.referenceSignals == 0) run.referenceBeforeResults = false;
    run.results.push_back(r);
  });
  QObject::connect(&runner, &AccuracyStudyRunner::finished,
                   [&run](const StudySummary& summary) { run.summary = summary; });
  runner.start(scene, cases, duration);
  if (!QTest::qWaitFor([&] { return run.summary.has_value(); }, 120000)) run.summary.reset();
  return run;
}

}  // namespace

class TestAccuracyRunner : public QObject {
  Q_OBJECT

 private slots:
  void everyCaseGivesOneResult_data() {
    QTest::addColumn<int>("threads");
    QTest::newRow("1 thread") << 1;
    QTest::newRow("2 threads") << 2;
  }

  void everyCaseGivesOneResult() {
    QFETCH(int, threads);
    const carom::Scene scene = smallScene();
    const std::vector<StudyCase> cases = casesOf(scene);
    const StudyRun run = runStudy(scene, cases, 1.0, threads);
    QVERIFY(run.summary);
    QCOMPARE(run.referenceSignals, 1);
    QVERIFY(run.referenceBeforeResults);
    QCOMPARE(run.results.size(), cases.size());
    std::map<CaseKey, int> seen;
    for (const StudyResult& r : run.results) ++seen[keyOf(r.settings)];
    for (const StudyCase& c : cases) QCOMPARE(seen[keyOf(c)], 1);
    QCOMPARE(run.summary->runs, int(cases.size()));
    QCOMPARE(run.summary->threads, threads);
    QVERIFY(!run.summary->cancelled);
    double sum = 0.0;
    for (const StudyResult& r : run.results) {
      QVERIFY(r.computeSeconds >= 0.0);
      sum += r.computeSeconds;
    }
    QCOMPARE(run.summary->computeSeconds, sum);
    QVERIFY(run.summary->referenceSeconds >= 0.0);
    QVERIFY(run.summary->wallSeconds > 0.0);
    QVERIFY(run.summary->speedUp() > 0.0);
    // The finest case agrees with exact for a while in a gas of 27 balls, not for a whole
    // second; the summary keeps the horizon the signal gave, and position errors are taken there.
    QVERIFY(run.horizon);
    QCOMPARE(run.summary->horizon, run.horizon);
    QVERIFY(*run.horizon > 0.0);
    for (const StudyResult& r : run.results) {
      QCOMPARE(r.deviation.size(), carom::studySampleTimes(1.0, scene.balls.size()).size());
      QVERIFY(!std::isnan(r.positionError));
      QVERIFY(r.positionError <= *std::max_element(r.deviation.begin(), r.deviation.end()));
      if (r.settings.method == Method::Exact) QCOMPARE(r.positionError, 0.0);
    }
  }

  void resultsDoNotDependOnTheThreadCount() {
    const carom::Scene scene = smallScene();
    const std::vector<StudyCase> cases = casesOf(scene);
    const StudyRun one = runStudy(scene, cases, 1.0, 1);
    const StudyRun two = runStudy(scene, cases, 1.0, 2);
    QCOMPARE(one.results.size(), cases.size());
    QCOMPARE(two.results.size(), cases.size());
    std::map<CaseKey, StudyResult> byCase;
    for (const StudyResult& r : one.results) byCase[keyOf(r.settings)] = r;
    for (const StudyResult& r : two.results) {
      const StudyResult& alone = byCase.at(keyOf(r.settings));
      QCOMPARE(r.positionError, alone.positionError);
      QCOMPARE(r.energyDrift, alone.energyDrift);
      QCOMPARE(r.maxPenetration, alone.maxPenetration);
      QCOMPARE(r.escaped, alone.escaped);
      QCOMPARE(r.deviation, alone.deviation);
      QCOMPARE(r.speedDistribution, alone.speedDistribution);
      QCOMPARE(r.positionDistribution, alone.positionDistribution);
      if (r.settings.method == Method::Exact) QCOMPARE(r.positionError, 0.0);  // the reference
    }
  }

  void cancelStopsPromptly() {
    const carom::Scene scene = smallScene();
    const std::vector<StudyCase> cases = longCasesOf(scene);
    AccuracyStudyRunner runner;
    runner.setMaxThreadCount(2);
    QSignalSpy results(&runner, &AccuracyStudyRunner::resultReady);
    QSignalSpy finished(&runner, &AccuracyStudyRunner::finished);
    // Cancelled on the first result, with the other runs under way or waiting.
    QObject::connect(&runner, &AccuracyStudyRunner::resultReady, &runner,
                     &AccuracyStudyRunner::cancel);
    runner.start(scene, cases, longStudySeconds());
    QVERIFY(runner.isRunning());
    QVERIFY(results.wait(120000));
    // Each run looks at the cancel flag every fiftieth of its duration: a few seconds are ample.
    QVERIFY(finished.count() == 1 || finished.wait(5000));
    QVERIFY(!runner.isRunning());
    QCOMPARE(results.count(), 1);
    const auto summary = finished.first().first().value<StudySummary>();
    QVERIFY(summary.cancelled);
    QCOMPARE(summary.runs, 1);
  }

  void cancelDuringTheReference() {
    const carom::Scene scene = smallScene();
    AccuracyStudyRunner runner;
    QSignalSpy reference(&runner, &AccuracyStudyRunner::referenceReady);
    QSignalSpy results(&runner, &AccuracyStudyRunner::resultReady);
    QSignalSpy finished(&runner, &AccuracyStudyRunner::finished);
    runner.start(scene, casesOf(scene), 1e6);  // a reference that would take hours
    runner.cancel();
    QVERIFY(finished.wait(30000));
    QCOMPARE(reference.count(), 0);
    QCOMPARE(results.count(), 0);
    QVERIFY(finished.first().first().value<StudySummary>().cancelled);
    // And it can run again.
    runner.start(scene, casesOf(scene), 0.2);
    QVERIFY(runner.isRunning());
    QVERIFY(finished.wait(60000));
    QCOMPARE(results.count(), int(casesOf(scene).size()));
  }

  void destroyedMidStudy_data() {
    QTest::addColumn<int>("threads");
    QTest::addColumn<bool>("duringRuns");  // else during the reference
    QTest::newRow("during the reference") << 2 << false;
    QTest::newRow("1 thread, during the runs") << 1 << true;
    QTest::newRow("2 threads, during the runs") << 2 << true;
  }

  void destroyedMidStudy() {
    QFETCH(int, threads);
    QFETCH(bool, duringRuns);
    const carom::Scene scene = smallScene();
    auto runner = std::make_unique<AccuracyStudyRunner>();
    runner->setMaxThreadCount(threads);
    int delivered = 0;
    QObject::connect(runner.get(), &AccuracyStudyRunner::resultReady,
                     [&delivered] { ++delivered; });
    runner->start(scene, longCasesOf(scene), longStudySeconds());
    if (duringRuns) {
      QVERIFY(QTest::qWaitFor([&] { return delivered > 0; }, 120000));
      // Runs finish meanwhile and post their results, which nobody delivers before the runner
      // is gone.
      QThread::msleep(300);
    }
    runner.reset();
    // Whatever was posted went with the runner: nothing reaches freed memory now.
    const int before = delivered;
    QTest::qWait(100);
    QCOMPARE(delivered, before);
  }
};

QTEST_GUILESS_MAIN(TestAccuracyRunner)
#include "test_accuracy_runner.moc"
