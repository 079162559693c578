// The live run's owner without a window, on real threads: a run restarted hundreds of times
// while the worker runs and this thread's event loop takes its snapshots. A consumer is handed
// only snapshots of the current start, each after that start's restarted(); latest() is of the
// current start or null; and the run goes on after the last restart. Before RunSession, a
// snapshot published just before a restart reached the consumers after it (the view drew the
// old run's positions against the new scene). Run under ThreadSanitizer by scripts/tsan.sh.

#include "sim/model/scene.h"
#include "ui/run/run_session.h"
#include "ui/run/simulation_snapshot.h"

#include <QEventLoop>
#include <QTimer>
#include <QtTest>

#include <cstdint>
#include <memory>
#include <random>

using carom::Ball;
using carom::Scene;
using carom::Vec3;
using carom::ui::RunSession;
using carom::ui::SimulationSnapshot;

namespace {

constexpr int kRestarts = 400;

// Balls far apart, falling: nothing collides, so every start steps fast. The count differs from
// one start to the next, so that a snapshot of another start would not even fit the scene.
std::shared_ptr<const Scene> fallingBalls(int count) {
  auto scene = std::make_shared<Scene>();
  scene->world.gravity = Vec3(0, -9.81, 0);
  for (int i = 0; i < count; ++i) {
    Ball ball;
    ball.position = Vec3(2.0 * i, 0.0, 0.0);
    ball.velocity = Vec3(0.0, 0.1 * i, 0.0);
    ball.radius = 0.2;
    scene->balls.push_back(ball);
  }
  return scene;
}

// This thread's event loop for `milliseconds`, taking the snapshots as they come. (QTest::qWait
// sleeps 10 ms between its rounds of events: shorter waits would take at most one notice.)
void runEventsFor(int milliseconds) {
  QEventLoop loop;
  QTimer::singleShot(milliseconds, &loop, &QEventLoop::quit);
  loop.exec();
}

}  // namespace

class TestRunSession : public QObject {
  Q_OBJECT

 private slots:
  void consumersSeeOnlyTheCurrentStart();
};

void TestRunSession::consumersSeeOnlyTheCurrentStart() {
  RunSession run;
  // What a consumer (the view, a dock) would hold: the start announced last and its scene.
  std::uint64_t announced = 0;
  std::size_t announcedBalls = 0;
  int outOfOrderRestarts = 0;
  double lastTime = 0.0;  // of the newest snapshot handed on
  connect(&run, &RunSession::restarted, this,
          [&](std::uint64_t start, std::shared_ptr<const Scene> scene) {
            if (start != announced + 1) ++outOfOrderRestarts;
            announced = start;
            announcedBalls = scene->balls.size();
            lastTime = 0.0;
          });
  int received = 0;
  int ofAnotherStart = 0;  // older, or not yet announced
  int notFitting = 0;      // positions of another scene
  connect(&run, &RunSession::snapshotReady, this,
          [&](std::shared_ptr<const SimulationSnapshot> snapshot) {
            ++received;
            if (snapshot->startNumber != announced || announced != run.currentStart())
              ++ofAnotherStart;
            if (snapshot->positions.size() != announcedBalls) ++notFitting;
            lastTime = snapshot->time;
          });
  int staleLatest = 0;
  const auto checkLatest = [&] {
    const std::shared_ptr<const SimulationSnapshot> latest = run.latest();
    if (latest && latest->startNumber != run.currentStart()) ++staleLatest;
  };

  std::mt19937 random(35);
  std::uniform_int_distribution<int> pause(0, 9);  // milliseconds, about a tick of the worker
  for (int k = 0; k < kRestarts; ++k) {
    run.start(fallingBalls(3 + k % 5));
    run.controls().setRunning(true);
    checkLatest();
    // Now and then twice in a row, the first start's snapshots never taken.
    if (k % 7 == 0) continue;
    runEventsFor(pause(random));
    checkLatest();
  }

  // The run goes on from the last start.
  const std::uint64_t last = run.currentStart();
  QCOMPARE(last, std::uint64_t(kRestarts));
  QTRY_VERIFY_WITH_TIMEOUT(lastTime > 0.1, 30000);
  QVERIFY(run.latest());
  QCOMPARE(run.latest()->startNumber, last);
  QVERIFY(run.latest()->time > 0.1);

  QCOMPARE(outOfOrderRestarts, 0);
  QVERIFY2(ofAnotherStart == 0 && notFitting == 0 && staleLatest == 0,
           qPrintable(QString("%1 of %2 snapshots handed on were of another start, %3 did not "
                              "fit the scene; latest() was of an older start %4 times")
                          .arg(ofAnotherStart)
                          .arg(received)
                          .arg(notFitting)
                          .arg(staleLatest)));
}

QTEST_GUILESS_MAIN(TestRunSession)
#include "test_run_session.moc"
