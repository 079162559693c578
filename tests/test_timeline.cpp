// The running world in the user's hands: the timeline under the view scrubs back to any frame
// and shows exactly what a fresh run reaches there; Play goes on from the frame shown; a ball
// dragged with the Select tool in a run in progress is grabbed, pushed and thrown, which is no
// edit of the scene and replays identically.

#include "sim/simulation.h"
#include "tests/dialog_answerer.h"
#include "tests/editor_fixture.h"
#include "ui/run/run_session.h"
#include "ui/run/simulation_snapshot.h"
#include "ui/timeline_bar.h"

#include <QInputDialog>
#include <QLabel>
#include <QSettings>
#include <QSlider>
#include <QUndoStack>

using namespace carom;
using namespace carom::testing;
using carom::ui::SimulationSnapshot;

namespace {

// Balls bouncing and colliding in a box: a floor, four walls, eight balls.
Scene bouncingScene() {
  Scene scene = floorScene();
  scene.world.restitution = 0.9;
  for (double z : {-4.0, 4.0}) {
    Plane wall;
    wall.point = Vec3(0, 0, z);
    wall.normal = Vec3(0, 0, z < 0 ? 1 : -1);
    scene.planes.push_back(wall);
  }
  for (int k = 0; k < 7; ++k) {
    Ball ball;
    ball.radius = 0.3;
    ball.position = Vec3(-3 + k, 1.5 + 0.4 * k, 0.3 * (k % 3));
    ball.velocity = Vec3(1.5 - 0.5 * k, 0, 0.7 * (k % 2 ? 1 : -1));
    scene.balls.push_back(ball);
  }
  return scene;
}

bool sameBalls(const SimulationSnapshot& snapshot, const Simulation& sim) {
  const std::vector<BallState> state = sim.state();
  if (snapshot.time != sim.time() || state.size() != snapshot.positions.size()) return false;
  for (std::size_t i = 0; i < state.size(); ++i)
    if (snapshot.positions[i] != state[i].position || snapshot.velocities[i] != state[i].velocity)
      return false;
  return true;
}

}  // namespace

class TimelineTest : public EditorFixture {
  Q_OBJECT

 public:
  static void initMain() { EditorFixture::initMain(); }

 private slots:
  void init() {
    openWindow();
    window_->openScene(bouncingScene(), {}, "bouncing");
    QVERIFY(waitFor([](const SimulationSnapshot& s) { return s.positions.size() == 8; }));
    slider_ = window_->findChild<QSlider*>("timelineSlider");
    QVERIFY(slider_);
  }
  void cleanup() { window_.reset(); }

  void scrubbingShowsWhatAFreshRunReaches() {
    runUntil(1.0);
    const auto paused = pause();
    QVERIFY(paused->frameCount >= 60);
    QCOMPARE(paused->frame, paused->frameCount);
    QTRY_COMPARE(std::uint64_t(slider_->maximum()), paused->frameCount);
    // Back with the slider, to frames before and after keyframes alike.
    for (const std::uint64_t frame :
         {paused->frameCount / 3, std::uint64_t(7), paused->frameCount - 1, std::uint64_t(0)}) {
      slider_->setValue(int(frame));
      const auto shown =
          waitFor([frame](const SimulationSnapshot& s) { return s.frame == frame && !s.running; });
      QVERIFY2(shown, qPrintable(QString::number(frame)));
      Simulation fresh(document().scene());
      for (std::uint64_t k = 0; k < frame; ++k) fresh.step();
      QVERIFY2(sameBalls(*shown, fresh), qPrintable(QString::number(frame)));
      QCOMPARE(shown->frameCount, paused->frameCount);  // the future is still there
      // The line under the slider says where it stands.
      QTRY_VERIFY(window_->findChild<QLabel*>("timelineLabel")
                      ->text()
                      .contains(QLocale().toString(qulonglong(frame))));
    }
    // The keyboard moves along it too: End is the present again.
    slider_->setFocus();
    QTest::keyClick(slider_, Qt::Key_End);
    QVERIFY(waitFor([&](const SimulationSnapshot& s) { return s.frame == paused->frameCount; }));
  }

  void playGoesOnFromTheFrameShown() {
    runUntil(0.8);
    const auto paused = pause();
    const std::uint64_t back = paused->frameCount / 2;
    slider_->setValue(int(back));
    QVERIFY(waitFor([back](const SimulationSnapshot& s) { return s.frame == back; }));
    QTest::keyClick(window_.get(), Qt::Key_Space);
    // The recorded future is forgotten: the run goes on from `back`.
    QVERIFY(waitFor([back](const SimulationSnapshot& s) {
      return s.running && s.frameCount > back + 20 && s.frame == s.frameCount;
    }));
    const auto again = pause();
    const std::uint64_t frame = back + 5;
    QVERIFY(again->frameCount > frame);
    slider_->setValue(int(frame));
    const auto shown = waitFor([frame](const SimulationSnapshot& s) { return s.frame == frame; });
    QVERIFY(shown);
    Simulation fresh(document().scene());
    for (std::uint64_t k = 0; k < frame; ++k) fresh.step();
    QVERIFY(sameBalls(*shown, fresh));
    // Undo has nothing to go back into: the run is no edit.
    QCOMPARE(document().undoStack()->count(), 0);
  }

  void dragInARunGrabsThrowsAndReplays() {
    runUntil(0.5);
    auto paused = pause();
    const int undoSteps = document().undoStack()->count();
    const Scene sceneBefore = document().scene();
    // Paused, the grabbed ball follows the cursor at once, as far as nothing is in the way: a
    // way up or sideways that a fresh run at this frame finds clear.
    const Vec3 start = paused->positions[0];
    Vec3 way = Vec3::Zero();
    for (const Vec3& candidate : {Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 1)}) {
      Simulation fresh(document().scene());
      for (std::uint64_t k = 0; k < paused->frame; ++k) fresh.step();
      fresh.grab(0);
      if ((fresh.moveGrabbed(start + 1.5 * candidate) - start).norm() > 1.49) {
        way = candidate;
        break;
      }
    }
    QVERIFY(!way.isZero());
    const Vec3 target = start + 1.5 * way;
    drag(at(start), at(target), [&] {
      const auto s = window_->simulation().latest();
      return s && s->grabbed == 0 && (s->positions[0] - start).dot(way) > 1.0;
    });
    auto released = waitFor([](const SimulationSnapshot& s) { return s.grabbed < 0; });
    QVERIFY(released);
    QVERIFY((released->positions[0] - start).dot(way) > 1.0);
    QCOMPARE(document().undoStack()->count(), undoSteps);
    QVERIFY(document().scene() == sceneBefore);
    // Running, a drag steers the ball through the run; let go, it falls.
    QTest::keyClick(window_.get(), Qt::Key_Space);
    auto running = waitFor([](const SimulationSnapshot& s) { return s.running; });
    QVERIFY(running);
    const Vec3 now = currentSnapshot()->positions[1];
    const Vec3 aside = now + Vec3(0, 2.0, 0);
    drag(
        at(now), at(aside),
        [&] {
          const auto s = window_->simulation().latest();
          return s && s->grabbed == 1 && s->positions[1].y() > now.y() + 1.0;
        },
        20);
    QVERIFY(waitFor([](const SimulationSnapshot& s) { return s.grabbed < 0; }));
    runUntil(currentSnapshot()->time + 0.3);
    paused = pause();
    // Every frame of it, grabs included, comes back as it was.
    const std::uint64_t frame = paused->frameCount;
    slider_->setValue(int(frame / 4));
    QVERIFY(waitFor([&](const SimulationSnapshot& s) { return s.frame == frame / 4; }));
    slider_->setValue(int(frame));
    const auto again = waitFor([&](const SimulationSnapshot& s) { return s.frame == frame; });
    QVERIFY(again);
    QVERIFY(again->positions == paused->positions && again->velocities == paused->velocities);
    QCOMPARE(again->time, paused->time);
    // Reset goes back to the scene, which the grabs never touched.
    QTest::keyClick(window_.get(), Qt::Key_R);
    const auto reset = waitFor([](const SimulationSnapshot& s) { return s.frameCount == 0; });
    QVERIFY(reset);
    for (std::size_t i = 0; i < sceneBefore.balls.size(); ++i)
      QVERIFY(reset->positions[i] == sceneBefore.balls[i].position);
  }

  // A click on a ball in a run in progress selects it and leaves the run alone.
  void clickInARunSelectsWithoutGrabbing() {
    runUntil(0.4);
    const auto paused = pause();
    document().setSelection({});
    click(paused->positions[2]);
    QTRY_VERIFY(document().selection().size() == 1);
    QCOMPARE(document().selection().front().index, 2);
    QTest::qWait(200);
    const auto after = window_->simulation().latest();
    QCOMPARE(after->frameCount, paused->frameCount);
    QVERIFY(after->positions == paused->positions && after->velocities == paused->velocities);
    QCOMPARE(after->grabbed, -1);
  }

  // At the scene's start, the same drag edits the scene as before: one undo step.
  void dragAtTheStartStillEditsTheScene() {
    const Vec3 start = document().scene().balls[0].position;
    const int undoSteps = document().undoStack()->count();
    drag(at(start), at(start + Vec3(1.0, 0, 0)),
         [&] { return document().scene().balls[0].position.x() > start.x() + 0.5; });
    QCOMPARE(document().undoStack()->count(), undoSteps + 1);
  }

  // Simulation > Timeline Memory and Throw Speed Limit ask over the window and keep the answer;
  // Cancel keeps the value before.
  // Issue 34: the line beside the slider grows with its numbers ("frame 0 of 0" at the start,
  // "frame 31 of 62 · … · replayed in 1.2 ms" scrubbing a run) and took its width from the
  // slider, which shrank under the hand.
  void sliderKeepsItsWidthAsTheLineGrows() {
    auto* label = window_->findChild<QLabel*>("timelineLabel");
    QVERIFY(label);
    QTRY_VERIFY(label->width() >= label->sizeHint().width());
    const int width = slider_->width();
    const QString startLine = label->text();
    runUntil(1.0);
    const auto paused = pause();
    const std::uint64_t back = paused->frameCount / 2;
    slider_->setValue(int(back));
    QVERIFY(waitFor([back](const SimulationSnapshot& s) { return s.frame == back; }));
    QTRY_VERIFY(label->text().contains(" ms"));  // its longest, with the replay's time
    QVERIFY2(label->fontMetrics().horizontalAdvance(label->text()) >
                 label->fontMetrics().horizontalAdvance(startLine),
             qPrintable(label->text()));
    // Once the layout has caught up with the longer line.
    QTRY_VERIFY(label->width() >= label->sizeHint().width());
    QCOMPARE(slider_->width(), width);
  }

  void simulationMenuSettingsAreAskedAndKept() {
    QCOMPARE(ui::TimelineBar::memoryBudget(), std::size_t(256) << 20);
    const auto answer = [](int mebibytes) {
      return ModalAnswerer<QInputDialog>([mebibytes](QInputDialog* dialog) {
        QCOMPARE(dialog->intMinimum(), ui::TimelineBar::kMinMemoryMebibytes);
        dialog->setIntValue(mebibytes);
        mebibytes > 0 ? dialog->accept() : dialog->reject();
      });
    };
    QAction* memory = window_->findChild<QAction*>("timelineMemory");
    QVERIFY(memory);
    {
      auto answerer = answer(64);
      memory->trigger();
      QTRY_VERIFY(answerer.answered());
    }
    QCOMPARE(ui::TimelineBar::memoryBudget(), std::size_t(64) << 20);
    {
      auto answerer = answer(0);  // cancelled
      memory->trigger();
      QTRY_VERIFY(answerer.answered());
    }
    QCOMPARE(ui::TimelineBar::memoryBudget(), std::size_t(64) << 20);
    // A stored value out of range, as from an older or hand-edited file, is not used.
    QSettings().setValue("simulation/timelineMemoryMiB", 3);
    QCOMPARE(ui::TimelineBar::memoryBudget(), std::size_t(256) << 20);

    QAction* throwLimit = window_->findChild<QAction*>("throwLimit");
    QVERIFY(throwLimit);
    ModalAnswerer<QInputDialog> answerer([](QInputDialog* dialog) {
      QCOMPARE(dialog->doubleValue(), 50.0);
      dialog->setDoubleValue(7.5);
      dialog->accept();
    });
    throwLimit->trigger();
    QTRY_VERIFY(answerer.answered());
    QCOMPARE(QSettings().value("simulation/throwLimit").toDouble(), 7.5);
  }

 private:
  template <typename Predicate>
  std::shared_ptr<const SimulationSnapshot> waitFor(Predicate ready) {
    std::shared_ptr<const SimulationSnapshot> snapshot;
    const bool reached = QTest::qWaitFor(
        [&] {
          snapshot = window_->simulation().latest();
          return snapshot && ready(*snapshot);
        },
        15000);
    return reached ? snapshot : nullptr;
  }
  void runUntil(double time) {
    if (!currentSnapshot()->running) QTest::keyClick(window_.get(), Qt::Key_Space);
    QVERIFY(waitFor([time](const SimulationSnapshot& s) { return s.running && s.time >= time; }));
  }
  std::shared_ptr<const SimulationSnapshot> pause() {
    QTest::keyClick(window_.get(), Qt::Key_Space);
    auto paused = waitFor([](const SimulationSnapshot& s) { return !s.running; });
    // The pause's own snapshot may come after one more batch: wait until it settles.
    QTest::qWait(100);
    return window_->simulation().latest();
  }

  QSlider* slider_ = nullptr;
};

QTEST_MAIN(TimelineTest)
#include "test_timeline.moc"
