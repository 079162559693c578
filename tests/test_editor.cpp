// The scene editor as a new user meets it: tools, picking, dragging, undo, files and prompts,
// driven with real mouse and key events under a real X server (Xvfb) with Mesa's OpenGL.

#include "sim/io/scene_file.h"
#include "tests/editor_fixture.h"
#include "ui/editor/editor_tools.h"
#include "ui/run/run_session.h"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>
#include <QUrl>

#include <functional>
#include <memory>

using carom::Vec3;
using carom::editor::EditorTools;
using carom::editor::ObjectKind;
using carom::editor::ObjectRef;
using carom::editor::SceneDocument;
using carom::ui::MainWindow;

using carom::testing::DialogAnswerer;
using carom::testing::floorScene;

class TestEditor : public carom::testing::EditorFixture {
  Q_OBJECT

 private slots:
  void init();
  void cleanup() { window_.reset(); }

  void addsEachKindByClicking();
  void refusesAPlacementWithNoRoom();
  void addsBoxesRestingOnWhatIsClicked();
  void addsCappedCylindersAfterACappedOne();
  void selectsByClicking();
  void dragMovesAsOneCommand();
  void dragConstrainedToAnAxis();
  void undoAndRedoEveryStep();
  void duplicateDeleteCopyPaste();
  void saveAndReopenGiveTheSameScene();
  void brokenFileLeavesTheSceneAlone();
  void unsavedChangesPrompt_data();
  void unsavedChangesPrompt();
  void titleShowsModified();
  void dragSnapsToTheGrid();
  void handleDragsSnapToTheGrid();
  void velocityArrowTipDrags();
  void altDragGivesABallAtRestAVelocity();
  void newAsksAboutUnsavedChanges();
  void openRecentReopensAFile();
  void dropOpensAFile();
  void saveAsAsksForAName();
  void saveAsCancelledWritesNothing();
  void aFailedSaveSaysWhyAndKeepsTheEdits();
  void anEditRestartsTheRun();
  void editsCanApplyToTheRunningState();
  void runningStateSurvivesAddingAndDeleting();
  void useCurrentStateAsInitial();

 private:
  QTemporaryDir folder_;
};

void TestEditor::init() {
  openWindow();
}

void TestEditor::addsEachKindByClicking() {
  chooseTool("toolAddBall");
  click(Vec3(2, 0, 1));
  QCOMPARE(document().scene().balls.size(), std::size_t{2});
  const carom::Ball& added = document().scene().balls[1];
  // Resting on the floor where it was clicked, with the last ball's size.
  QCOMPARE(added.radius, 0.5);
  QVERIFY2((added.position - Vec3(2, 0.5, 1)).norm() < 0.1,
           qPrintable(QString("%1 %2 %3")
                          .arg(added.position.x())
                          .arg(added.position.y())
                          .arg(added.position.z())));
  QCOMPARE(document().selection(), (carom::editor::Selection{{ObjectKind::Ball, 1}}));

  chooseTool("toolAddCylinder");
  click(Vec3(-2, 0, -1));
  QCOMPARE(document().scene().cylinders.size(), std::size_t{1});
  QVERIFY((document().scene().cylinders[0].point - Vec3(-2, 0, -1)).norm() < 0.1);
  QVERIFY(document().scene().cylinders[0].axis.normalized().isApprox(Vec3::UnitY()));

  chooseTool("toolAddPlane");
  click(Vec3(-3, 0, -2));  // behind the balls: the wall faces the camera, and so them
  QCOMPARE(document().scene().planes.size(), std::size_t{4});
  const carom::Plane& wall = document().scene().planes[3];
  QVERIFY(std::abs(wall.normal.y()) < 1e-9);  // standing up, facing the camera
  QCOMPARE(document().undoStack()->count(), 3);
}

void TestEditor::refusesAPlacementWithNoRoom() {
  // A cylinder right through the ball is refused by the scene validation, with a message.
  chooseTool("toolAddCylinder");
  click(Vec3(0, 1.0, 0));  // on top of the ball: the post would stand in it
  QCOMPARE(document().scene().cylinders.size(), std::size_t{0});
  QCOMPARE(document().undoStack()->count(), 0);
  QVERIFY2(statusMessage(*window_).contains("overlap"), qPrintable(statusMessage(*window_)));
}

// A box lands with its bottom face on the surface under the cursor: the floor, or the top of a
// box already there, turned as that box is. One command each; a box that would overlap a ball
// is refused with the validation's message.
void TestEditor::addsBoxesRestingOnWhatIsClicked() {
  chooseTool("toolAddBox");
  QVERIFY(window_->findChild<QAction*>("toolAddBox")->isChecked());
  click(Vec3(2, 0, 1));
  QCOMPARE(document().scene().boxes.size(), std::size_t{1});
  const carom::Box first = document().scene().boxes[0];
  QCOMPARE(first.halfExtents, Vec3::Constant(0.5));
  QCOMPARE(first.center.y(), 0.5);  // resting on the floor exactly
  QVERIFY((first.center - Vec3(2, 0.5, 1)).norm() < 0.1);
  QVERIFY(!first.rotation);
  QCOMPARE(document().selection(), (carom::editor::Selection{{ObjectKind::Box, 0}}));
  QCOMPARE(document().undoStack()->undoText(), QString("Add Box"));

  // Turned by 25 degrees, then a second box clicked onto its top stands on it,
  // turned the same way.
  carom::Scene turned = document().scene();
  turned.boxes[0].rotation = carom::Rotation{Vec3::UnitY(), 25};
  QVERIFY(carom::testing::applyEdit(document(), turned, "Turn").isEmpty());
  click(first.center + Vec3(0, 0.5, 0));
  QCOMPARE(document().scene().boxes.size(), std::size_t{2});
  const carom::Box& stacked = document().scene().boxes[1];
  QVERIFY2(std::abs(stacked.center.y() - 1.5) < 1e-9,
           qPrintable(QString::number(stacked.center.y())));
  QVERIFY((stacked.center - Vec3(first.center.x(), 1.5, first.center.z())).norm() < 0.1);
  QVERIFY(stacked.rotation == turned.boxes[0].rotation);

  // Right beside the ball, the box would stand in it.
  const int commands = document().undoStack()->count();
  click(Vec3(0.7, 0, 0));
  QCOMPARE(document().scene().boxes.size(), std::size_t{2});
  QCOMPARE(document().undoStack()->count(), commands);
  QVERIFY2(
      statusMessage(*window_).startsWith("Cannot place it there: first would overlap Box 2 by"),
      qPrintable(statusMessage(*window_)));

  // Undo takes the stacked box away, redo puts it back as it was.
  const carom::Scene withBoth = document().scene();
  document().undoStack()->undo();
  QCOMPARE(document().scene().boxes.size(), std::size_t{1});
  document().undoStack()->redo();
  QVERIFY(document().scene() == withBoth);
}

// After a capped cylinder, the Add Cylinder tool adds capped ones of its length and radius,
// standing with the lower cap on the surface clicked; the dock's length field, emptied, makes
// the new one infinite, and the next one added is infinite too.
void TestEditor::addsCappedCylindersAfterACappedOne() {
  carom::Scene edited = document().scene();
  carom::Cylinder post;
  post.point = Vec3(2, 0.75, -2);
  post.radius = 0.4;
  post.length = 1.5;
  edited.cylinders.push_back(post);
  QVERIFY(carom::testing::applyEdit(document(), edited, "add").isEmpty());

  chooseTool("toolAddCylinder");
  click(Vec3(-2, 0, -1));
  QCOMPARE(document().scene().cylinders.size(), std::size_t{2});
  const carom::Cylinder added = document().scene().cylinders[1];
  QCOMPARE(added.length, std::optional(1.5));
  QCOMPARE(added.radius, 0.4);
  QVERIFY(added.axis.normalized().isApprox(Vec3::UnitY()));
  QVERIFY2(std::abs(added.point.y() - 0.75) < 1e-9, qPrintable(QString::number(added.point.y())));
  QVERIFY((added.point - Vec3(-2, 0.75, -1)).norm() < 0.1);
  QCOMPARE(document().selection(), (carom::editor::Selection{{ObjectKind::Cylinder, 1}}));
  QCOMPARE(document().undoStack()->undoText(), QString("Add Cylinder"));

  auto* length = window_->findChild<QLineEdit*>("cylinderLength");
  QVERIFY(length && length->isVisible());
  QCOMPARE(length->text(), QString("1.5"));
  QTest::mouseClick(length, Qt::LeftButton);
  QTest::keyClick(length, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClick(length, Qt::Key_Backspace);
  QTest::keyClick(length, Qt::Key_Return);
  QCOMPARE(document().scene().cylinders[1].length, std::nullopt);
  click(Vec3(-2, 0, 1));
  QCOMPARE(document().scene().cylinders.size(), std::size_t{3});
  QCOMPARE(document().scene().cylinders[2].length, std::nullopt);
  QVERIFY(std::abs(document().scene().cylinders[2].point.y()) < 1e-9);

  document().undoStack()->undo();
  document().undoStack()->undo();
  QVERIFY(document().scene().cylinders[1] == added);
  document().undoStack()->undo();
  QCOMPARE(document().scene().cylinders.size(), std::size_t{1});
}

void TestEditor::selectsByClicking() {
  chooseTool("toolSelect");
  click(Vec3(0, 0.5, 0));
  QCOMPARE(document().selection(), (carom::editor::Selection{{ObjectKind::Ball, 0}}));
  click(Vec3(1.5, 0, 1.5), Qt::ControlModifier);  // the floor joins
  QCOMPARE(document().selection(),
           (carom::editor::Selection{{ObjectKind::Ball, 0}, {ObjectKind::Plane, 0}}));
  click(Vec3(0, 0.5, 0), Qt::ShiftModifier);  // the ball leaves
  QCOMPARE(document().selection(), (carom::editor::Selection{{ObjectKind::Plane, 0}}));
  // Empty sky above the room clears it.
  QTest::mouseClick(&view(), Qt::LeftButton, Qt::NoModifier, QPoint(view().width() / 2, 3));
  QVERIFY(document().selection().empty());
}

void TestEditor::dragMovesAsOneCommand() {
  chooseTool("toolSelect");
  const QPoint from = at(Vec3(0, 0.5, 0));
  const QPoint to = from + QPoint(100, 0);  // across the screen: along the floor
  QTest::mousePress(&view(), Qt::LeftButton, Qt::NoModifier, from);
  for (int i = 1; i <= 10; ++i) QTest::mouseMove(&view(), from + (to - from) * i / 10);
  // Moves reach the window asynchronously on xcb.
  QTRY_VERIFY(document().scene().balls[0].position.x() > 0.5);
  QTest::mouseRelease(&view(), Qt::LeftButton, Qt::NoModifier, to);
  const Vec3 moved = document().scene().balls[0].position;
  QVERIFY2(moved.x() > 0.5 && std::abs(moved.y() - 0.5) < 1e-6,
           qPrintable(QString("%1 %2 %3, %4 commands")
                          .arg(moved.x())
                          .arg(moved.y())
                          .arg(moved.z())
                          .arg(document().undoStack()->count())));
  QCOMPARE(document().undoStack()->count(), 1);  // ten moves, one command
  document().undoStack()->undo();
  QCOMPARE(document().scene().balls[0].position, Vec3(0, 0.5, 0));
}

void TestEditor::dragConstrainedToAnAxis() {
  chooseTool("toolSelect");
  const QPoint from = at(Vec3(0, 0.5, 0));
  const QPoint to = from + QPoint(60, -60);  // up and to the right on screen
  QTest::mousePress(&view(), Qt::LeftButton, Qt::NoModifier, from);
  QTest::keyPress(&view(), Qt::Key_Y);
  for (int i = 1; i <= 6; ++i) QTest::mouseMove(&view(), from + (to - from) * i / 6);
  QTRY_VERIFY(document().scene().balls[0].position.y() > 0.7);
  QTest::mouseRelease(&view(), Qt::LeftButton, Qt::NoModifier, to);
  QTest::keyRelease(&view(), Qt::Key_Y);
  const Vec3 moved = document().scene().balls[0].position;
  QCOMPARE(moved.x(), 0.0);
  QCOMPARE(moved.z(), 0.0);
  QVERIFY2(moved.y() > 0.7, qPrintable(QString::number(moved.y())));
}

void TestEditor::undoAndRedoEveryStep() {
  std::vector<carom::Scene> states = {document().scene()};
  chooseTool("toolAddBall");
  click(Vec3(2, 0, 0));
  states.push_back(document().scene());
  chooseTool("toolSelect");
  click(Vec3(2, 0.5, 0));
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  states.push_back(document().scene());
  QCOMPARE(states[2].balls.size(), std::size_t{1});
  for (int i = 2; i > 0; --i) {
    QTest::keyClick(window_.get(), Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(document().scene() == states[i - 1]);
  }
  for (int i = 1; i <= 2; ++i) {
    QTest::keyClick(window_.get(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(document().scene() == states[i]);
  }
  QTest::keyClick(window_.get(), Qt::Key_Z, Qt::ControlModifier);
  QTest::keyClick(window_.get(), Qt::Key_Y, Qt::ControlModifier);  // the other redo key
  QVERIFY(document().scene() == states[2]);
}

void TestEditor::duplicateDeleteCopyPaste() {
  document().setSelection({{ObjectKind::Ball, 0}});
  QTest::keyClick(window_.get(), Qt::Key_D, Qt::ControlModifier);
  QCOMPARE(document().scene().balls.size(), std::size_t{2});
  const carom::Ball& copy = document().scene().balls[1];
  QCOMPARE(copy.name, std::string("first"));
  QCOMPARE(copy.color, std::string("#ff0000"));
  QVERIFY((copy.position - Vec3(0, 0.5, 0)).norm() >= 1.0 - 1e-9);  // beside, not inside
  QCOMPARE(document().selection(), (carom::editor::Selection{{ObjectKind::Ball, 1}}));

  QTest::keyClick(window_.get(), Qt::Key_C, Qt::ControlModifier);
  QVERIFY(QApplication::clipboard()->text().contains("\"balls\""));
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  QCOMPARE(document().scene().balls.size(), std::size_t{1});
  QTest::keyClick(window_.get(), Qt::Key_V, Qt::ControlModifier);
  QCOMPARE(document().scene().balls.size(), std::size_t{2});
  QCOMPARE(document().undoStack()->count(), 3);

  // Text that is not a scene is refused with a message.
  QApplication::clipboard()->setText("not a scene");
  QTest::keyClick(window_.get(), Qt::Key_V, Qt::ControlModifier);
  QCOMPARE(document().scene().balls.size(), std::size_t{2});
  QVERIFY(statusMessage(*window_).startsWith("Nothing to paste"));

  // Select All, then Delete, leaves an empty scene in one step.
  QTest::keyClick(window_.get(), Qt::Key_A, Qt::ControlModifier);
  QCOMPARE(document().selection().size(), std::size_t{5});
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  QVERIFY(document().scene().balls.empty() && document().scene().planes.empty());
}

void TestEditor::saveAndReopenGiveTheSameScene() {
  const QString file = folder_.filePath("round-trip.carom");
  {
    QFile out(file);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(carom::io::serializeScene(floorScene()));
  }
  QVERIFY(window_->openFile(file, false));
  chooseTool("toolAddBall");
  click(Vec3(2, 0, 1));
  QVERIFY(document().isModified());
  QVERIFY(window_->save());
  QVERIFY(!document().isModified());
  const carom::Scene saved = document().scene();
  window_->openScene(floorScene(), {}, "other");
  QVERIFY(window_->openFile(file, false));
  QVERIFY(document().scene() == saved);
  QCOMPARE(document().fileName(), QFileInfo(file).absoluteFilePath());
}

void TestEditor::brokenFileLeavesTheSceneAlone() {
  const QString file = folder_.filePath("broken.carom");
  {
    QFile out(file);
    QVERIFY(out.open(QIODevice::WriteOnly));
    QByteArray json = carom::io::serializeScene(floorScene());
    const qsizetype radius = json.indexOf("\"radius\"");
    QVERIFY(radius > 0);
    json.insert(json.indexOf(':', radius) + 1, " -2, \"unused\":");  // radius: -2
    out.write(json);
  }
  const carom::Scene before = document().scene();
  DialogAnswerer answer(QMessageBox::Ok);
  QVERIFY(!window_->openFile(file, false));
  QVERIFY(answer.answered());
  QVERIFY2(answer.text().contains("balls[0].radius"), qPrintable(answer.text()));
  QVERIFY(document().scene() == before);
  QVERIFY(document().fileName().isEmpty());
}

void TestEditor::unsavedChangesPrompt_data() {
  QTest::addColumn<int>("answer");
  QTest::addColumn<bool>("closes");
  QTest::addColumn<bool>("written");
  QTest::newRow("save") << int(QMessageBox::Save) << true << true;
  QTest::newRow("discard") << int(QMessageBox::Discard) << true << false;
  QTest::newRow("cancel") << int(QMessageBox::Cancel) << false << false;
}

void TestEditor::unsavedChangesPrompt() {
  QFETCH(int, answer);
  QFETCH(bool, closes);
  QFETCH(bool, written);
  const QString file = folder_.filePath("prompt.carom");
  {
    QFile out(file);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(carom::io::serializeScene(floorScene()));
  }
  QVERIFY(window_->openFile(file, false));
  document().setSelection({{ObjectKind::Ball, 0}});
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  QVERIFY(document().isModified());

  DialogAnswerer answerer(static_cast<QMessageBox::StandardButton>(answer));
  const bool closed = window_->close();
  QVERIFY(answerer.answered());
  QVERIFY(answerer.text().contains("prompt.carom"));
  QCOMPARE(closed, closes);
  const carom::io::SceneLoadResult onDisk = carom::io::loadSceneFile(file);
  QVERIFY(onDisk.scene);
  QCOMPARE(onDisk.scene->balls.empty(), written);
  if (!closes) QCOMPARE(document().scene().balls.size(), std::size_t{0});  // still the edit
}

void TestEditor::titleShowsModified() {
  QVERIFY(!window_->isWindowModified());
  document().setSelection({{ObjectKind::Ball, 0}});
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  QVERIFY(window_->isWindowModified());
  QVERIFY(window_->windowTitle().contains("floor"));
  QTest::keyClick(window_.get(), Qt::Key_Z, Qt::ControlModifier);
  QVERIFY(!window_->isWindowModified());  // back at the saved state
}

void TestEditor::dragSnapsToTheGrid() {
  chooseTool("toolSelect");
  window_->findChild<QAction*>("snapToGrid")->trigger();
  QVERIFY(editorTools(*window_)->snapToGrid());
  const QPoint from = at(Vec3(0, 0.5, 0));
  drag(from, from + QPoint(77, 9), [&] { return document().scene().balls[0].position.x() > 0.2; });
  const Vec3 moved = document().scene().balls[0].position;
  for (int a = 0; a < 3; ++a) {
    const double steps = moved[a] / EditorTools::gridStep();
    QVERIFY2(std::abs(steps - std::round(steps)) < 1e-9, qPrintable(QString::number(moved[a])));
  }
  QVERIFY(moved.x() >= 0.25);
}

// With snapping on, a box's face and a capped cylinder's end dragged by their handles make the
// size and the length whole grid steps; the other face and end stay, so that a box whose faces
// were on the grid keeps them there.
void TestEditor::handleDragsSnapToTheGrid() {
  carom::Scene edited = document().scene();
  carom::Box crate;
  crate.center = Vec3(2, 0.5, 0);
  edited.boxes.push_back(crate);
  carom::Cylinder post;
  post.point = Vec3(-2, 0.5, -2);
  post.radius = 0.3;
  post.length = 1.0;
  edited.cylinders.push_back(post);
  QVERIFY(carom::testing::applyEdit(document(), edited, "add").isEmpty());
  chooseTool("toolSelect");
  window_->findChild<QAction*>("snapToGrid")->trigger();
  QVERIFY(editorTools(*window_)->snapToGrid());
  const double step = EditorTools::gridStep();
  const auto onGrid = [&](double value) {
    return std::abs(value / step - std::round(value / step)) < 1e-9;
  };

  document().setSelection({{ObjectKind::Box, 0}});
  EditorTools::Handle face;
  for (const EditorTools::Handle& handle : editorTools(*window_)->handles())
    if (handle.role == EditorTools::HandleRole::BoxFace && handle.axis == 0 && handle.side == 1)
      face = handle;
  QCOMPARE(face.base, Vec3(2.5, 0.5, 0));
  // 0.6 m out, between the grid's 0.5 and 0.75.
  drag(at(face.tip), at(face.tip + Vec3(0.6, 0, 0)),
       [&] { return document().scene().boxes[0].halfExtents.x() > 0.74; });
  const carom::Box wider = document().scene().boxes[0];
  const double size = 2 * wider.halfExtents.x();
  QVERIFY2(onGrid(size) && size > 1.4 && size < 1.8, qPrintable(QString::number(size)));
  QVERIFY2(onGrid(wider.center.x() + wider.halfExtents.x()),
           qPrintable(QString::number(wider.center.x() + wider.halfExtents.x())));
  QCOMPARE(wider.center.x() - wider.halfExtents.x(), 1.5);

  document().setSelection({{ObjectKind::Cylinder, 0}});
  EditorTools::Handle end;
  for (const EditorTools::Handle& handle : editorTools(*window_)->handles())
    if (handle.role == EditorTools::HandleRole::CylinderEnd && handle.side == 1) end = handle;
  QCOMPARE(end.base, Vec3(-2, 1, -2));
  drag(at(end.tip), at(end.tip + Vec3(0, 0.35, 0)),
       [&] { return document().scene().cylinders[0].length.value_or(0) > 1.2; });
  const carom::Cylinder longer = document().scene().cylinders[0];
  QVERIFY2(onGrid(*longer.length) && *longer.length > 1.2 && *longer.length < 1.6,
           qPrintable(QString::number(*longer.length)));
  QCOMPARE(longer.point.y() - 0.5 * *longer.length, 0.0);
  QVERIFY(onGrid(longer.point.y() + 0.5 * *longer.length));
  QCOMPARE(document().undoStack()->count(), 3);
}

void TestEditor::velocityArrowTipDrags() {
  carom::Scene moving = floorScene();
  moving.balls[0].velocity = Vec3(2, 0, 0);
  window_->openScene(moving, {}, "moving");
  chooseTool("toolSelect");
  document().setSelection({{ObjectKind::Ball, 0}});
  const std::vector<EditorTools::Handle> arrows = editorTools(*window_)->handles();
  QCOMPARE(arrows.size(), std::size_t{1});
  const EditorTools::Handle* arrow = &arrows.front();
  QCOMPARE(arrow->tip, Vec3(1, 0.5, 0));  // half a second of flight
  const QPoint tip = at(arrow->tip);
  drag(tip, tip + QPoint(0, -50), [&] { return document().scene().balls[0].velocity.y() > 0.5; });
  const Vec3 velocity = document().scene().balls[0].velocity;
  QVERIFY2(velocity.y() > 0.5 && velocity.x() > 1.0, qPrintable(QString::number(velocity.y())));
  QCOMPARE(document().scene().balls[0].position, Vec3(0, 0.5, 0));  // the ball stays put
  QCOMPARE(document().undoStack()->count(), 1);
  QCOMPARE(document().undoStack()->text(0), QString("Change Velocity"));
}

void TestEditor::altDragGivesABallAtRestAVelocity() {
  chooseTool("toolSelect");
  QVERIFY(editorTools(*window_)->handles().empty());  // at rest: no arrow to grab
  const QPoint from = at(Vec3(0, 0.5, 0));
  const QPoint to = from + QPoint(60, 0);
  QTest::mousePress(&view(), Qt::LeftButton, Qt::AltModifier, from);
  for (int i = 1; i <= 6; ++i) QTest::mouseMove(&view(), from + (to - from) * i / 6);
  QTRY_VERIFY(document().scene().balls[0].velocity.norm() > 0.5);
  QTest::mouseRelease(&view(), Qt::LeftButton, Qt::AltModifier, to);
  QCOMPARE(document().scene().balls[0].position, Vec3(0, 0.5, 0));
  QCOMPARE(editorTools(*window_)->handles().size(), std::size_t{1});
}

void TestEditor::newAsksAboutUnsavedChanges() {
  document().setSelection({{ObjectKind::Ball, 0}});
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  const carom::Scene edited = document().scene();
  {
    DialogAnswerer cancel(QMessageBox::Cancel);
    QTest::keyClick(window_.get(), Qt::Key_N, Qt::ControlModifier);
    QVERIFY(cancel.answered());
    QVERIFY(document().scene() == edited);
  }
  DialogAnswerer discard(QMessageBox::Discard);
  QTest::keyClick(window_.get(), Qt::Key_N, Qt::ControlModifier);
  QVERIFY(discard.answered());
  QVERIFY(document().scene() == SceneDocument::newScene());
  QVERIFY(!document().isModified());
  QVERIFY(window_->windowTitle().startsWith("untitled"));
}

void TestEditor::openRecentReopensAFile() {
  const QString file = folder_.filePath("recent.carom");
  QVERIFY(carom::io::saveSceneFile(floorScene(), file, nullptr));
  QVERIFY(window_->openFile(file, false));
  window_->openScene(carom::Scene(), {});
  auto* menu = window_->findChild<QMenu*>("recentMenu");
  QVERIFY(menu);
  emit menu->aboutToShow();
  const QList<QAction*> entries = menu->actions();
  QVERIFY(!entries.isEmpty());
  QCOMPARE(entries.first()->text(), QDir::toNativeSeparators(QFileInfo(file).absoluteFilePath()));
  entries.first()->trigger();
  QCOMPARE(document().fileName(), QFileInfo(file).absoluteFilePath());
  QCOMPARE(document().scene().balls.size(), std::size_t{1});
}

void TestEditor::dropOpensAFile() {
  const QString file = folder_.filePath("dropped.carom");
  carom::Scene scene = floorScene();
  scene.balls[0].name = "dropped";
  QVERIFY(carom::io::saveSceneFile(scene, file, nullptr));
  QMimeData mime;
  mime.setUrls({QUrl::fromLocalFile(file)});
  QDragEnterEvent enter(QPoint(50, 50), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(window_.get(), &enter);
  QVERIFY(enter.isAccepted());
  QDropEvent drop(QPointF(50, 50), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(window_.get(), &drop);
  QTRY_COMPARE(document().fileName(), QFileInfo(file).absoluteFilePath());
  QCOMPARE(document().scene().balls[0].name, std::string("dropped"));
}

void TestEditor::saveAsAsksForAName() {
  document().setSelection({{ObjectKind::Ball, 0}});
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  QStringList suggested;
  const QString typed = folder_.filePath("chosen");  // no suffix: .carom is added
  carom::testing::ModalAnswerer<QFileDialog> answer([&](QFileDialog* dialog) {
    suggested = dialog->selectedFiles();
    dialog->selectFile(typed);
    QMetaObject::invokeMethod(dialog, "accept");  // the Save button's slot
  });
  QTest::keyClick(window_.get(), Qt::Key_S, Qt::ControlModifier | Qt::ShiftModifier);
  QVERIFY(answer.answered());
  // The example's name was offered.
  QCOMPARE(suggested.size(), 1);
  QVERIFY2(suggested.first().endsWith("floor.carom"), qPrintable(suggested.first()));
  const QString file = typed + ".carom";
  const carom::io::SceneLoadResult saved = carom::io::loadSceneFile(file);
  QVERIFY2(saved.scene, qPrintable(saved.error));
  QVERIFY(*saved.scene == document().scene());
  QCOMPARE(document().fileName(), QFileInfo(file).absoluteFilePath());
  QVERIFY(!document().isModified());
  QVERIFY(window_->windowTitle().startsWith("chosen.carom"));
  // Ctrl+S now saves there without asking.
  QTest::keyClick(window_.get(), Qt::Key_Z, Qt::ControlModifier);
  QTest::keyClick(window_.get(), Qt::Key_S, Qt::ControlModifier);
  QCOMPARE(carom::io::loadSceneFile(file).scene->balls.size(), std::size_t{1});
}

void TestEditor::saveAsCancelledWritesNothing() {
  document().setSelection({{ObjectKind::Ball, 0}});
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  const QStringList filesBefore = QDir(folder_.path()).entryList(QDir::Files);
  carom::testing::ModalAnswerer<QFileDialog> answer([](QFileDialog* dialog) { dialog->reject(); });
  QVERIFY(!window_->saveAs());
  QVERIFY(answer.answered());
  QVERIFY(document().isModified());
  QVERIFY(document().fileName().isEmpty());
  QCOMPARE(QDir(folder_.path()).entryList(QDir::Files), filesBefore);
}

void TestEditor::aFailedSaveSaysWhyAndKeepsTheEdits() {
  // A scene file that cannot be replaced: its name has become a folder with a file in it.
  const QString file = folder_.filePath("blocked.carom");
  QVERIFY(carom::io::saveSceneFile(floorScene(), file, nullptr));
  QVERIFY(window_->openFile(file, false));
  QVERIFY(QFile::remove(file));
  QVERIFY(QDir(folder_.path()).mkpath("blocked.carom"));
  {
    QFile inside(file + "/keep.txt");
    QVERIFY(inside.open(QIODevice::WriteOnly));
    inside.write("kept");
  }
  document().setSelection({{ObjectKind::Ball, 0}});
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  DialogAnswerer answer(QMessageBox::Ok);
  QTest::keyClick(window_.get(), Qt::Key_S, Qt::ControlModifier);
  QVERIFY(answer.answered());
  QVERIFY2(answer.text().startsWith(file + ": cannot save"), qPrintable(answer.text()));
  QVERIFY(document().isModified());
  QCOMPARE(document().scene().balls.size(), std::size_t{0});
  QVERIFY(QFileInfo(file).isDir());
  QFile inside(file + "/keep.txt");
  QVERIFY(inside.open(QIODevice::ReadOnly));
  QCOMPARE(inside.readAll(), QByteArray("kept"));
}

namespace {

// Two balls falling from 3 m onto the floor.
carom::Scene fallingScene() {
  carom::Scene scene = floorScene();
  scene.balls[0].position = Vec3(-2, 3, 0);
  carom::Ball second = scene.balls[0];
  second.position = Vec3(2, 3, 0);
  second.name = "second";
  scene.balls.push_back(second);
  return scene;
}

}  // namespace

void TestEditor::anEditRestartsTheRun() {
  window_->openScene(fallingScene(), {}, "falling");
  window_->setRunning(true);
  QTRY_VERIFY(currentSnapshot()->time > 0.5);
  carom::Scene edited = document().scene();
  edited.balls[1].mass = 2.0;
  QVERIFY(carom::testing::applyEdit(document(), edited, "heavier").isEmpty());
  // From the start of the edited scene, still running.
  QTRY_VERIFY(currentSnapshot()->time < 0.4);
  QTRY_VERIFY(currentSnapshot()->time > 0.1);
  window_->setRunning(false);
}

void TestEditor::editsCanApplyToTheRunningState() {
  window_->openScene(fallingScene(), {}, "falling");
  QAction* applyToRunning = window_->findChild<QAction*>("applyToRunningState");
  QVERIFY(applyToRunning);
  applyToRunning->setChecked(true);
  window_->setRunning(true);
  QTRY_VERIFY(currentSnapshot()->time > 0.3);
  window_->setRunning(false);
  QTRY_VERIFY(!currentSnapshot()->running);
  const std::vector<Vec3> running = currentSnapshot()->positions;
  QVERIFY(running[1].y() < 3.0);
  // Ball 0 is edited and starts over; ball 1 is left alone and stays where the run had it.
  carom::Scene edited = document().scene();
  edited.balls[0].color = "#00ff00";
  QVERIFY(carom::testing::applyEdit(document(), edited, "recolour").isEmpty());
  QTRY_COMPARE(currentSnapshot()->time, 0.0);
  QCOMPARE(currentSnapshot()->positions[0], Vec3(-2, 3, 0));
  QCOMPARE(currentSnapshot()->positions[1], running[1]);
  // Off: the next edit starts everything from the scene.
  applyToRunning->setChecked(false);
  edited.balls[0].color = "#0000ff";
  QVERIFY(carom::testing::applyEdit(document(), edited, "recolour").isEmpty());
  QTRY_COMPARE(currentSnapshot()->positions[1], Vec3(2, 3, 0));
}

void TestEditor::runningStateSurvivesAddingAndDeleting() {
  window_->openScene(fallingScene(), {}, "falling");
  window_->findChild<QAction*>("applyToRunningState")->setChecked(true);
  window_->setRunning(true);
  QTRY_VERIFY(currentSnapshot()->time > 0.3);
  window_->setRunning(false);
  QTRY_VERIFY(!currentSnapshot()->running);
  const std::vector<Vec3> running = currentSnapshot()->positions;
  // A ball added beside them: both keep falling from where they were.
  chooseTool("toolAddBall");
  click(Vec3(0, 0, 2));
  QCOMPARE(document().scene().balls.size(), std::size_t{3});
  QTRY_COMPARE(currentSnapshot()->positions.size(), std::size_t{3});
  QCOMPARE(currentSnapshot()->positions[0], running[0]);
  QCOMPARE(currentSnapshot()->positions[1], running[1]);
  // The first one deleted: the second, now first, still keeps its running state.
  document().setSelection({{ObjectKind::Ball, 0}});
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  QTRY_COMPARE(currentSnapshot()->positions.size(), std::size_t{2});
  QCOMPARE(currentSnapshot()->positions[0], running[1]);
  // A ball placed where a running ball now is cannot join the running state: everything
  // restarts from the edited scene, and the status bar says why.
  carom::Scene edited = document().scene();
  carom::Ball inTheWay = edited.balls[0];
  inTheWay.position = running[1] - Vec3(0, 0.6, 0);  // clear of where it started
  inTheWay.name = "in the way";
  edited.balls.push_back(inTheWay);
  QVERIFY(carom::testing::applyEdit(document(), edited, "add").isEmpty());
  QTRY_COMPARE(currentSnapshot()->positions.size(), std::size_t{3});
  QCOMPARE(currentSnapshot()->positions[0], Vec3(2, 3, 0));
  QVERIFY2(statusMessage(*window_).contains("does not fit the running state"),
           qPrintable(statusMessage(*window_)));
  // In words, naming the balls as the Outline does, not by the file's paths.
  QVERIFY2(statusMessage(*window_).contains("(in the way would overlap "),
           qPrintable(statusMessage(*window_)));
  QVERIFY2(!statusMessage(*window_).contains("balls["), qPrintable(statusMessage(*window_)));
}

void TestEditor::useCurrentStateAsInitial() {
  window_->openScene(fallingScene(), {}, "falling");
  window_->setRunning(true);
  QTRY_VERIFY(currentSnapshot()->time > 0.3);
  window_->setRunning(false);
  QTRY_VERIFY(!currentSnapshot()->running);
  const std::shared_ptr<const carom::ui::SimulationSnapshot> state = window_->simulation().latest();
  window_->findChild<QAction*>("useCurrentState")->trigger();
  QCOMPARE(document().undoStack()->count(), 1);
  for (std::size_t i = 0; i < 2; ++i) {
    QCOMPARE(document().scene().balls[i].position, state->positions[i]);
    QCOMPARE(document().scene().balls[i].velocity, state->velocities[i]);
  }
  QTest::keyClick(window_.get(), Qt::Key_Z, Qt::ControlModifier);
  QCOMPARE(document().scene().balls[1].position, Vec3(2, 3, 0));
}

QTEST_MAIN(TestEditor)
#include "test_editor.moc"
