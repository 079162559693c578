// Drags in the real window that must not leave a mess (issue 34): Escape during any drag (a
// move, a handle, a velocity arrow, a grab) puts everything back as it was before the press and
// the release then applies nothing; a move does not take a box through the floor it stands on;
// capped cylinders stand on what they are placed on or stand on when given a length, and the
// Add Cylinder tool offers them.

#include "tests/editor_fixture.h"
#include "ui/editor/editor_tools.h"
#include "ui/run/run_session.h"
#include "ui/run/simulation_snapshot.h"

#include <QLineEdit>
#include <QTest>
#include <QToolBar>
#include <QUndoStack>

#include <cmath>
#include <memory>

using namespace carom;
using namespace carom::testing;
using carom::editor::EditorTools;
using carom::editor::ObjectKind;
using carom::editor::Selection;
using carom::ui::SimulationSnapshot;

namespace {

// floorScene() with a box resting on the floor, as Add Box puts it there.
Scene sceneWithABox() {
  Scene scene = floorScene();
  Box box;
  box.center = Vec3(2, 0.5, 1);
  scene.boxes.push_back(box);
  return scene;
}

// Three balls flying across the room above the floor, with nothing above them.
Scene flyingBalls() {
  Scene scene = floorScene();
  scene.balls.clear();
  for (int k = 0; k < 3; ++k) {
    Ball ball;
    ball.radius = 0.3;
    ball.position = Vec3(-2 + 2 * k, 2.0, 0);
    // Across as well as up, so that each keeps a speed of 0.6 m/s or more at the top of its
    // flight: a run paused late (a slow machine, the sanitizers) still finds it moving.
    ball.velocity = Vec3(0.5 - 0.5 * k, 3.0, 0.6);
    scene.balls.push_back(ball);
  }
  return scene;
}

QString text(const Vec3& v) {
  return QString("(%1, %2, %3)")
      .arg(v.x(), 0, 'g', 17)
      .arg(v.y(), 0, 'g', 17)
      .arg(v.z(), 0, 'g', 17);
}

}  // namespace

class DragsTest : public EditorFixture {
  Q_OBJECT

 public:
  static void initMain() { EditorFixture::initMain(); }

 private slots:
  void init() { openWindow(); }
  void cleanup() { window_.reset(); }

  void escapeCancelsAMove();
  void escapeCancelsAHandleDrag();
  void escapeCancelsAVelocityArrowDrag();
  void escapeUndoesAGrabInAPausedRun();
  void escapeLetsARunningGrabGoWithoutAThrow();
  void aMoveStopsAtTheFloor();
  void cappedCylinderPlacedStandsOnItsSurface();
  void lengthTypedKeepsTheFootOnTheFloor();
  void addCylinderOffersCappedCylinders();

 private:
  // A press at `from` and moves towards `to` until `arrived`, then Escape; more moves, which
  // must do nothing, and the release.
  void dragThenEscape(QPoint from, QPoint to, const std::function<bool()>& arrived) {
    QTest::mousePress(&view(), Qt::LeftButton, Qt::NoModifier, from);
    for (int i = 1; i <= 10; ++i) QTest::mouseMove(&view(), from + (to - from) * i / 10);
    QTRY_VERIFY(arrived());
    QTest::keyClick(&view(), Qt::Key_Escape);
    for (int i = 1; i <= 5; ++i) QTest::mouseMove(&view(), to + QPoint(0, -20 * i));
    QTest::mouseRelease(&view(), Qt::LeftButton, Qt::NoModifier, to + QPoint(0, -100));
  }
  // After an edit drag cancelled: the scene, the selection and the camera as before, and no
  // undo step. The moves after Escape reach the window asynchronously: give them time to act.
  void checkNothingChanged(const Scene& before, const Selection& selectionBefore,
                           const QVector3D& eyeBefore) {
    QTest::qWait(200);
    QVERIFY(document().scene() == before);
    QCOMPARE(document().undoStack()->count(), 0);
    QVERIFY(!document().isModified());
    QCOMPARE(document().selection(), selectionBefore);
    QCOMPARE(view().camera().eye(), eyeBefore);  // the moves after Escape did not orbit
  }
  QLineEdit* toolLength() {
    auto* field = window_->findChild<QLineEdit*>("toolCylinderLength");
    return field;
  }
  void type(QLineEdit* field, const QString& typed) {
    QTest::mouseClick(field, Qt::LeftButton);
    QTest::keyClick(field, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClick(field, Qt::Key_Backspace);
    QTest::keyClicks(field, typed);
    QTest::keyClick(field, Qt::Key_Return);
  }
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
};

// A ball dragged across the floor, Escape, the release: the ball where it was, unselected as
// it was, and no undo step.
void DragsTest::escapeCancelsAMove() {
  chooseTool("toolSelect");
  const Scene before = document().scene();
  const QVector3D eye = view().camera().eye();
  QVERIFY(document().selection().empty());
  const QPoint from = at(Vec3(0, 0.5, 0));
  dragThenEscape(from, from + QPoint(120, 0),
                 [&] { return document().scene().balls[0].position.x() > 0.5; });
  checkNothingChanged(before, {}, eye);
}

// A box's +x face dragged out, Escape: the box as it was.
void DragsTest::escapeCancelsAHandleDrag() {
  window_->openScene(sceneWithABox(), {}, "box");
  chooseTool("toolSelect");
  document().setSelection({{ObjectKind::Box, 0}});
  const Scene before = document().scene();
  const QVector3D eye = view().camera().eye();
  EditorTools::Handle face;
  for (const EditorTools::Handle& handle : editorTools(*window_)->handles())
    if (handle.role == EditorTools::HandleRole::BoxFace && handle.axis == 0 && handle.side == 1)
      face = handle;
  QCOMPARE(face.base, Vec3(2.5, 0.5, 1));
  dragThenEscape(at(face.tip), at(face.tip + Vec3(1.0, 0, 0)),
                 [&] { return document().scene().boxes[0].halfExtents.x() > 0.7; });
  checkNothingChanged(before, {{ObjectKind::Box, 0}}, eye);
}

// A ball's velocity arrow dragged up, Escape: the velocity as it was.
void DragsTest::escapeCancelsAVelocityArrowDrag() {
  Scene moving = floorScene();
  moving.balls[0].velocity = Vec3(2, 0, 0);
  window_->openScene(moving, {}, "moving");
  chooseTool("toolSelect");
  document().setSelection({{ObjectKind::Ball, 0}});
  const Scene before = document().scene();
  const QVector3D eye = view().camera().eye();
  const std::vector<EditorTools::Handle> arrows = editorTools(*window_)->handles();
  QCOMPARE(arrows.size(), std::size_t{1});
  const QPoint tip = at(arrows.front().tip);
  dragThenEscape(tip, tip + QPoint(0, -60),
                 [&] { return document().scene().balls[0].velocity.y() > 0.5; });
  checkNothingChanged(before, {{ObjectKind::Ball, 0}}, eye);
}

// Paused, a grab moves the ball at once; Escape puts it back where it was taken, with the
// velocity it had, and lets it go.
void DragsTest::escapeUndoesAGrabInAPausedRun() {
  window_->openScene(flyingBalls(), {}, "flying");
  QTest::keyClick(window_.get(), Qt::Key_Space);
  QVERIFY(waitFor([](const SimulationSnapshot& s) { return s.running && s.time >= 0.2; }));
  QTest::keyClick(window_.get(), Qt::Key_Space);
  QVERIFY(waitFor([](const SimulationSnapshot& s) { return !s.running; }));
  QTest::qWait(100);  // the pause's own snapshot may follow one more batch
  const auto paused = window_->simulation().latest();
  const Vec3 start = paused->positions[1];
  const Vec3 velocity = paused->velocities[1];
  QVERIFY(velocity.norm() > 0.5);
  QTest::mousePress(&view(), Qt::LeftButton, Qt::NoModifier, at(start));
  const QPoint to = at(start + Vec3(0, 1.5, 0));
  for (int i = 1; i <= 10; ++i) QTest::mouseMove(&view(), at(start) + (to - at(start)) * i / 10);
  QVERIFY(waitFor([&](const SimulationSnapshot& s) {
    return s.grabbed == 1 && s.positions[1].y() > start.y() + 1.0;
  }));
  QTest::keyClick(&view(), Qt::Key_Escape);
  QTest::mouseMove(&view(), to + QPoint(0, -40));
  QTest::mouseRelease(&view(), Qt::LeftButton, Qt::NoModifier, to + QPoint(0, -40));
  const auto released = waitFor([&](const SimulationSnapshot& s) {
    return s.grabbed < 0 && (s.positions[1] - start).norm() < 1e-9;
  });
  const auto last = window_->simulation().latest();
  QVERIFY2(released, qPrintable(QString("ball at %1 (taken at %2), grabbed %3")
                                    .arg(text(last->positions[1]), text(start))
                                    .arg(last->grabbed)));
  QVERIFY2((released->velocities[1] - velocity).norm() < 1e-12,
           qPrintable(text(released->velocities[1]) + " against " + text(velocity)));
  QCOMPARE(released->time, paused->time);
  QCOMPARE(document().selection(), Selection{});
}

// Running, Escape lets the ball go where it is, at rest: cursor moves up to the release throw
// nothing.
void DragsTest::escapeLetsARunningGrabGoWithoutAThrow() {
  window_->openScene(flyingBalls(), {}, "flying");
  QTest::keyClick(window_.get(), Qt::Key_Space);
  const auto running =
      waitFor([](const SimulationSnapshot& s) { return s.running && s.time >= 0.1; });
  QVERIFY(running);
  const Vec3 now = running->positions[0];
  const QPoint from = at(now);
  const QPoint to = at(now + Vec3(0, 1.0, 0));
  QTest::mousePress(&view(), Qt::LeftButton, Qt::NoModifier, from);
  for (int i = 1; i <= 10; ++i) QTest::mouseMove(&view(), from + (to - from) * i / 10);
  QVERIFY(waitFor([](const SimulationSnapshot& s) { return s.grabbed == 0; }));
  QTest::keyClick(&view(), Qt::Key_Escape);
  // A fast stroke upwards just before the release: thrown, the ball would fly off with it.
  for (int i = 1; i <= 5; ++i) QTest::mouseMove(&view(), to + QPoint(0, -40 * i));
  QTest::mouseRelease(&view(), Qt::LeftButton, Qt::NoModifier, to + QPoint(0, -200));
  const auto released = waitFor([](const SimulationSnapshot& s) { return s.grabbed < 0; });
  QVERIFY(released);
  // Let go at rest a moment ago, it has fallen for at most that moment since.
  QVERIFY2(released->velocities[0].norm() < 2.0, qPrintable(text(released->velocities[0])));
  QVERIFY(document().undoStack()->count() == 0);
}

// A box standing on the floor dragged down and to the right: it slides along the floor under
// the cursor instead of sinking through it.
void DragsTest::aMoveStopsAtTheFloor() {
  window_->openScene(sceneWithABox(), {}, "box");
  chooseTool("toolSelect");
  const QPoint from = at(Vec3(2, 0.5, 1));
  drag(from, from + QPoint(120, 120), [&] { return document().scene().boxes[0].center.x() > 2.3; });
  const Box moved = document().scene().boxes[0];
  QVERIFY2(std::abs(moved.center.y() - 0.5) < 1e-9, qPrintable(text(moved.center)));
  QVERIFY2(moved.center.x() > 2.3 && moved.center.z() > 1.3, qPrintable(text(moved.center)));
  QCOMPARE(document().undoStack()->count(), 1);
  // Held to Y, down leads nowhere: it stays on the floor.
  QTest::mousePress(&view(), Qt::LeftButton, Qt::NoModifier, at(moved.center));
  QTest::keyPress(&view(), Qt::Key_Y);
  for (int i = 1; i <= 6; ++i) QTest::mouseMove(&view(), at(moved.center) + QPoint(0, 15 * i));
  QTest::qWait(200);
  QTest::mouseRelease(&view(), Qt::LeftButton, Qt::NoModifier, at(moved.center) + QPoint(0, 90));
  QTest::keyRelease(&view(), Qt::Key_Y);
  QVERIFY2(std::abs(document().scene().boxes[0].center.y() - 0.5) < 1e-9,
           qPrintable(text(document().scene().boxes[0].center)));
}

// Add Cylinder with a length: the cylinder stands on the floor, and on a box's top, its lowest
// point on the surface to round-off.
void DragsTest::cappedCylinderPlacedStandsOnItsSurface() {
  window_->openScene(sceneWithABox(), {}, "box");
  chooseTool("toolAddCylinder");
  QLineEdit* length = toolLength();
  QVERIFY(length);
  QTRY_VERIFY(length->isVisible());
  type(length, "2");
  click(Vec3(-2, 0, -1));
  QCOMPARE(document().scene().cylinders.size(), std::size_t{1});
  const Cylinder onFloor = document().scene().cylinders[0];
  QCOMPARE(onFloor.length, std::optional(2.0));
  QVERIFY2(std::abs(onFloor.point.y() - 1.0) < 1e-9, qPrintable(text(onFloor.point)));
  click(Vec3(2, 1, 1));  // the box's top
  QCOMPARE(document().scene().cylinders.size(), std::size_t{2});
  const Cylinder onBox = document().scene().cylinders[1];
  QVERIFY2(std::abs(onBox.point.y() - 0.5 * *onBox.length - 1.0) < 1e-9,
           qPrintable(text(onBox.point)));
}

// A cylinder standing on the floor given a length in the Properties dock rises from the floor:
// an infinite one placed there, then a longer and a shorter length. One lying free keeps its
// middle.
void DragsTest::lengthTypedKeepsTheFootOnTheFloor() {
  chooseTool("toolAddCylinder");
  click(Vec3(-2, 0, -1));
  QCOMPARE(document().scene().cylinders.size(), std::size_t{1});
  QCOMPARE(document().scene().cylinders[0].length, std::nullopt);
  QCOMPARE(document().selection(), (Selection{{ObjectKind::Cylinder, 0}}));
  auto* length = window_->findChild<QLineEdit*>("cylinderLength");
  QVERIFY(length && length->isVisible());
  for (const double typed : {2.0, 3.0, 0.5}) {
    type(length, QString::number(typed));
    const Cylinder& cylinder = document().scene().cylinders[0];
    QCOMPARE(cylinder.length, std::optional(typed));
    QVERIFY2(std::abs(cylinder.point.y() - 0.5 * typed) < 1e-9, qPrintable(text(cylinder.point)));
    QVERIFY((cylinder.point - Vec3(-2, 0.5 * typed, -1)).norm() < 0.1);
  }
  // Emptied, it is infinite again with its point on the floor, where it was placed.
  type(length, "");
  QCOMPARE(document().scene().cylinders[0].length, std::nullopt);
  QVERIFY(std::abs(document().scene().cylinders[0].point.y()) < 1e-9);

  // Lying across the room above the floor, it stands on nothing: its middle stays.
  Scene lying = document().scene();
  lying.cylinders[0].point = Vec3(0, 2, -2);
  lying.cylinders[0].axis = Vec3::UnitX();
  window_->openScene(lying, {}, "lying");
  document().setSelection({{ObjectKind::Cylinder, 0}});
  type(length, "2");
  QCOMPARE(document().scene().cylinders[0].point, Vec3(0, 2, -2));
}

// The tools bar shows Add Cylinder's length while the tool is chosen: empty (infinite) to
// begin with, a typed length for the next cylinders, a bad one refused with the reason.
void DragsTest::addCylinderOffersCappedCylinders() {
  chooseTool("toolSelect");
  QLineEdit* length = toolLength();
  QVERIFY(length);
  QVERIFY(!length->isVisible());
  chooseTool("toolAddCylinder");
  QTRY_VERIFY(length->isVisible());  // the tools bar lays itself out again when it can
  QVERIFY(length->text().isEmpty());
  QCOMPARE(length->placeholderText(), QString("infinite"));

  type(length, "1.5");
  click(Vec3(-2, 0, -1));
  QCOMPARE(document().scene().cylinders.size(), std::size_t{1});
  QCOMPARE(document().scene().cylinders[0].length, std::optional(1.5));

  type(length, "-1");
  QVERIFY2(statusMessage(*window_).contains("positive"), qPrintable(statusMessage(*window_)));
  QCOMPARE(length->text(), QString("1.5"));
  click(Vec3(-2, 0, 1));
  QCOMPARE(document().scene().cylinders[1].length, std::optional(1.5));

  // Emptied: infinite ones again.
  type(length, "");
  click(Vec3(2, 0, -1));
  QCOMPARE(document().scene().cylinders.size(), std::size_t{3});
  QCOMPARE(document().scene().cylinders[2].length, std::nullopt);
  QVERIFY(std::abs(document().scene().cylinders[2].point.y()) < 1e-9);
}

QTEST_MAIN(DragsTest)
#include "test_drags.moc"
