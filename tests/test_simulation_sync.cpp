// The simulation kept in step with the document, on real threads: small scenes restart at once;
// huge ones (SimulationSync::kBackgroundBalls) are copied and checked on a thread of their own,
// the document waiting for that before it changes again, so that every restart starts from the
// scene of its edit, in order. Run under ThreadSanitizer by scripts/tsan.sh.

#include "scene_edits.h"
#include "ui/editor/scene_document.h"
#include "ui/run/run_session.h"
#include "ui/run/simulation_snapshot.h"
#include "ui/simulation_sync.h"

#include <QSignalSpy>
#include <QtTest>

#include <memory>
#include <vector>

using carom::Ball;
using carom::Scene;
using carom::Vec3;
using carom::editor::SceneDocument;
using carom::ui::RunSession;
using carom::ui::SimulationSync;

namespace {

// Balls far apart in a lattice, falling: nothing collides, so a run of any size steps fast.
Scene sparseCrowd(std::size_t count) {
  Scene scene;
  scene.world.gravity = Vec3(0, -9.81, 0);
  const int side = 64;
  for (std::size_t i = 0; i < count; ++i) {
    Ball ball;
    const auto k = static_cast<int>(i);
    ball.position = Vec3(k % side, (k / side) % side, k / (side * side)) * 1.0;
    ball.velocity = Vec3(0.1 * (k % 7), 0.0, -0.1 * (k % 5));
    ball.radius = 0.1;
    ball.color = k % 2 ? "#ff0000" : "#0000ff";
    scene.balls.push_back(ball);
  }
  return scene;
}

using Starts = std::shared_ptr<std::vector<std::shared_ptr<const Scene>>>;

// The scenes `run` restarted from, as SimulationSync restarts it.
Starts recordStarts(RunSession& run) {
  auto starts = std::make_shared<std::vector<std::shared_ptr<const Scene>>>();
  QObject::connect(
      &run, &RunSession::restarted,
      [starts](std::uint64_t, std::shared_ptr<const Scene> start) { starts->push_back(start); });
  return starts;
}

}  // namespace

class TestSimulationSync : public QObject {
  Q_OBJECT

 private slots:
  void smallScenesRestartAtOnce();
  void hugeScenesRestartWhenTheirStartIsMade();
  void anEditWaitsForTheStartBeingMade();
  void hugeEditsKeepTheRunningState();
  void closingWhileAStartIsMade();
};

void TestSimulationSync::smallScenesRestartAtOnce() {
  RunSession run;
  SceneDocument document;
  SimulationSync sync(&document, &run);
  Starts starts = recordStarts(run);
  document.reset(sparseCrowd(10), {});
  QCOMPARE(starts->size(), std::size_t{1});
  QVERIFY(*starts->back() == document.scene());
}

void TestSimulationSync::hugeScenesRestartWhenTheirStartIsMade() {
  RunSession run;
  SceneDocument document;
  SimulationSync sync(&document, &run);
  Starts starts = recordStarts(run);
  document.reset(sparseCrowd(SimulationSync::kBackgroundBalls), {});
  // Only the event loop delivers it: the open returned before the copy was made.
  QCOMPARE(starts->size(), std::size_t{0});
  QTRY_COMPARE_WITH_TIMEOUT(starts->size(), std::size_t{1}, 30000);
  QVERIFY(*starts->back() == document.scene());
  // The simulation stands at that start.
  run.controls().stepOnce();
  QTRY_VERIFY_WITH_TIMEOUT(run.latest() && run.latest()->time > 0.0, 30000);
  QCOMPARE(run.latest()->positions.size(), SimulationSync::kBackgroundBalls);
}

// Edits in quick succession: each restart starts from the scene of its own edit, in order,
// although the document changed again while the one before was being made.
void TestSimulationSync::anEditWaitsForTheStartBeingMade() {
  RunSession run;
  SceneDocument document;
  SimulationSync sync(&document, &run);
  Starts starts = recordStarts(run);
  document.reset(sparseCrowd(SimulationSync::kBackgroundBalls + 10), {});
  std::vector<Scene> expected{document.scene()};
  for (double mass : {2.0, 3.0, 4.0}) {
    Scene edited = document.scene();
    edited.balls.back().mass = mass;
    QCOMPARE(carom::testing::applyEdit(document, edited, "mass"), QString());
    expected.push_back(document.scene());
  }
  // The edits waited for the start before each: all but the last are out.
  QCOMPARE(starts->size(), std::size_t{3});
  QTRY_COMPARE_WITH_TIMEOUT(starts->size(), std::size_t{4}, 30000);
  for (std::size_t k = 0; k < expected.size(); ++k)
    QVERIFY2(*(*starts)[k] == expected[k], qPrintable(QString::number(k)));
  document.undoStack()->undo();
  QCOMPARE(starts->size(), std::size_t{4});
  QTRY_COMPARE_WITH_TIMEOUT(starts->size(), std::size_t{5}, 30000);
  QCOMPARE(starts->back()->balls.back().mass, 3.0);
}

// With edits applying to the running state, the balls the edit left alone start where the run
// has them, as for small scenes.
void TestSimulationSync::hugeEditsKeepTheRunningState() {
  RunSession run;
  SceneDocument document;
  SimulationSync sync(&document, &run);
  sync.setApplyToRunningState(true);
  Starts starts = recordStarts(run);
  document.reset(sparseCrowd(SimulationSync::kBackgroundBalls), {});
  QTRY_COMPARE_WITH_TIMEOUT(starts->size(), std::size_t{1}, 30000);
  run.controls().stepOnce();
  QTRY_VERIFY_WITH_TIMEOUT(run.latest() && run.latest()->time > 0.0, 30000);
  const std::shared_ptr<const carom::ui::SimulationSnapshot> ran = run.latest();
  Scene edited = document.scene();
  edited.balls.front().mass = 5.0;
  QCOMPARE(carom::testing::applyEdit(document, edited, "mass"), QString());
  QTRY_COMPARE_WITH_TIMEOUT(starts->size(), std::size_t{2}, 30000);
  const Scene& start = *starts->back();
  QCOMPARE(start.balls.front().mass, 5.0);
  QCOMPARE(start.balls.front().position, document.scene().balls.front().position);
  for (std::size_t i : {std::size_t{1}, start.balls.size() / 2, start.balls.size() - 1}) {
    QCOMPARE(start.balls[i].position, ran->positions[i]);
    QCOMPARE(start.balls[i].velocity, ran->velocities[i]);
    QVERIFY(start.balls[i].position != document.scene().balls[i].position);
  }
}

// The window closing with a start being made: it is waited for, and nothing restarts after.
void TestSimulationSync::closingWhileAStartIsMade() {
  RunSession run;
  SceneDocument document;
  auto sync = std::make_unique<SimulationSync>(&document, &run);
  Starts starts = recordStarts(run);
  document.reset(sparseCrowd(SimulationSync::kBackgroundBalls), {});
  sync.reset();
  QTest::qWait(200);  // the notice the thread posted must find nobody
  QCOMPARE(starts->size(), std::size_t{0});
  Scene edited = document.scene();
  edited.balls.front().mass = 5.0;
  QCOMPARE(carom::testing::applyEdit(document, edited, "mass"), QString());
}

QTEST_GUILESS_MAIN(TestSimulationSync)
#include "test_simulation_sync.moc"
