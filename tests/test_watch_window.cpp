// The run watch in the window (Simulation > Watch): a run that goes wrong pauses, the status bar
// and a dialog say what happened to which ball and when, the ball is selected and framed; the
// checks and tolerances are set from the menu and remembered.

#include "tests/editor_fixture.h"
#include "ui/dialogs/watch_tolerance_dialog.h"
#include "ui/number_box.h"
#include "ui/run/run_session.h"
#include "ui/run/simulation_snapshot.h"
#include "ui/watch_menu.h"

#include <QMessageBox>
#include <QPushButton>
#include <QSettings>

using carom::Vec3;
using carom::editor::ObjectKind;
using carom::ui::SimulationSnapshot;

namespace {

// A heavy ball crushes a light one ("nut") against a thick box at a step far too long for it:
// after the first step the nut's centre is inside the box (as in test_watch).
carom::Scene crushScene() {
  carom::Scene s;
  s.world.gravity = Vec3::Zero();
  s.world.method = carom::Method::Discrete;
  s.world.timeStep = 0.1;
  carom::Box box;
  box.center = Vec3(1, 0, 0);
  box.halfExtents = Vec3(0.5, 1, 1);
  s.boxes.push_back(box);
  carom::Ball heavy;
  heavy.position = Vec3(-0.5, 0, 0);
  heavy.velocity = Vec3(8, 0, 0);
  heavy.radius = 0.3;
  heavy.mass = 1000;
  carom::Ball nut;
  nut.position = Vec3(0.39, 0, 0);
  nut.radius = 0.1;
  nut.mass = 0.001;
  nut.name = "nut";
  s.balls = {heavy, nut};
  return s;
}

}  // namespace

class TestWatchWindow : public carom::testing::EditorFixture {
  Q_OBJECT

 private slots:
  void init() {
    openWindow();
    window_->openScene(crushScene(), {}, "crush");
    QTRY_VERIFY(latest() && latest()->positions.size() == 2);
  }
  void cleanup() { window_.reset(); }

  void stopsShowsSelectsAndFrames() {
    carom::testing::DialogAnswerer answer(QMessageBox::Ok);
    QAction* run = window_->findChild<QAction*>("run");
    window_->setRunning(true);
    QTRY_VERIFY(answer.answered());
    QVERIFY2(answer.text().contains("ball 1 (nut)"), qPrintable(answer.text()));
    QVERIFY2(answer.text().contains("box 0"), qPrintable(answer.text()));
    QVERIFY2(answer.text().contains("0.1 s"), qPrintable(answer.text()));
    // Paused at the event, the control showing it.
    const auto snapshot = latest();
    QVERIFY(!snapshot->running);
    QCOMPARE(snapshot->time, 0.1);
    QVERIFY(snapshot->watchEvent);
    QCOMPARE(snapshot->watchEvent->lastGoodTime, 0.0);
    QVERIFY(!run->isChecked());
    QVERIFY2(statusMessage(*window_).contains("ball 1 (nut)"), qPrintable(statusMessage(*window_)));
    // The ball is selected and the camera looks at it.
    QCOMPARE(document().selection(), (carom::editor::Selection{{ObjectKind::Ball, 1}}));
    const QVector3D target = view().camera().target();
    const Vec3& nut = snapshot->positions[1];
    QVERIFY((Vec3(target.x(), target.y(), target.z()) - nut).norm() < 1e-4);
    QTRY_VERIFY(!watchDialog(*window_));
    // Resumed, the run goes on: the same problem is not reported again while it lasts.
    window_->setRunning(true);
    QTRY_VERIFY_WITH_TIMEOUT(latest()->time > 0.5, 10000);
    QVERIFY(!watchDialog(*window_));
  }

  // A name as long as the format allows is elided in the dialog and the status bar, which then
  // keep to a sentence's length.
  void longNamesAreElided() {
    carom::Scene scene = crushScene();
    scene.balls[1].name = "nut " + std::string(252, 'N');
    scene.boxes[0].name = std::string(256, 'B');
    window_->openScene(scene, {}, "crush");
    QTRY_VERIFY(latest() && latest()->positions.size() == 2);
    carom::testing::DialogAnswerer answer(QMessageBox::Ok);
    window_->setRunning(true);
    QTRY_VERIFY(answer.answered());
    for (const QString& text : {answer.text(), statusMessage(*window_)}) {
      QVERIFY2(text.contains("ball 1 (nut NNN") && text.contains("box 0 (BBB"), qPrintable(text));
      QCOMPARE(text.count("\u2026"), 2);
      QVERIFY2(text.size() < 200, qPrintable(text));
    }
  }

  // The dialog offers the last frame that passed the watch, from the timeline.
  void offersTheMomentBefore() {
    window_->setRunning(true);
    QTRY_VERIFY(watchDialog(*window_));
    const auto stopped = latest();
    QVERIFY(stopped->watchEvent);
    auto* before = watchDialog(*window_)->findChild<QPushButton*>("showMomentBefore");
    QVERIFY(before);
    before->click();
    QTRY_VERIFY(latest()->frame + 1 == stopped->frameCount);
    QCOMPARE(latest()->time, stopped->watchEvent->lastGoodTime);
    QVERIFY(latest()->positions != stopped->positions);
    QTRY_VERIFY(!watchDialog(*window_));
  }

  void checksTurnedOffLetTheRunGoOn() {
    for (const char* name : {"watch:escape", "watch:penetration"}) {
      QAction* action = window_->findChild<QAction*>(name);
      QVERIFY2(action && action->isChecked(), name);
      action->trigger();
      QVERIFY(!action->isChecked());
    }
    QVERIFY(!watchMenu(*window_)->settings().escape);
    QCOMPARE(QSettings().value("watch/on/escape").toBool(), false);
    window_->setRunning(true);
    QTRY_VERIFY_WITH_TIMEOUT(latest()->time > 1.0, 10000);
    QVERIFY(latest()->running);
    QVERIFY(!watchDialog(*window_));
    QCOMPARE(latest()->watchEvents, std::uint64_t(0));
    // Remembered for the next window.
    carom::ui::WatchMenu again;
    QVERIFY(!again.settings().escape && !again.settings().penetration);
    QVERIFY(again.settings().nonFinite && again.settings().energyRise);
  }

  void tolerancesFromTheDialog() {
    // A refused value says why and changes nothing.
    QString refusal;
    carom::testing::ModalAnswerer<carom::ui::WatchToleranceDialog> refuse(
        [&](carom::ui::WatchToleranceDialog* dialog) {
          carom::ui::NumberBox* box = dialog->penetrationBox();
          // No window manager under Xvfb: make the dialog active ourselves so the box has focus.
          QApplication::setActiveWindow(dialog);
          box->setFocus();
          QTest::keyClick(box, Qt::Key_A, Qt::ControlModifier);
          QTest::keyClick(box, Qt::Key_Backspace);
          QTest::keyClicks(box, "-1");
          QTest::keyClick(box, Qt::Key_Tab);  // leaves the box: editing finishes
          refusal = dialog->problem();
          dialog->reject();
        });
    window_->findChild<QAction*>("watchTolerances")->trigger();
    QVERIFY(refuse.answered());
    QVERIFY2(refusal.contains("-1"), qPrintable(refusal));
    QCOMPARE(watchMenu(*window_)->settings(), carom::WatchSettings{});
    // A tolerance wider than the nut's overlap (two radii) with escape off: the run goes on.
    carom::testing::ModalAnswerer<carom::ui::WatchToleranceDialog> widen(
        [](carom::ui::WatchToleranceDialog* dialog) {
          dialog->penetrationBox()->setValue(2.5);
          dialog->accept();
        });
    window_->findChild<QAction*>("watchTolerances")->trigger();
    QVERIFY(widen.answered());
    QCOMPARE(watchMenu(*window_)->settings().penetrationTolerance, 2.5);
    QCOMPARE(QSettings().value("watch/penetration").toDouble(), 2.5);
    window_->findChild<QAction*>("watch:escape")->trigger();
    window_->setRunning(true);
    QTRY_VERIFY_WITH_TIMEOUT(latest()->time > 1.0, 10000);
    QVERIFY(!watchDialog(*window_));
  }

 private:
  std::shared_ptr<const SimulationSnapshot> latest() { return window_->simulation().latest(); }
};

QTEST_MAIN(TestWatchWindow)
#include "test_watch_window.moc"
