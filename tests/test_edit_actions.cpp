// The Edit menu's work without a window: copy and paste through the clipboard, duplicate,
// delete and select all, on a document alone.

#include "sim/io/scene_file.h"
#include "tests/scene_helpers.h"
#include "ui/edit_actions.h"
#include "ui/editor/scene_document.h"

#include <QApplication>
#include <QClipboard>
#include <QMimeData>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

using carom::Scene;
using carom::Vec3;
using carom::editor::ObjectKind;
using carom::editor::SceneDocument;
using carom::editor::Selection;
using carom::ui::EditActions;

namespace {

// A floor, and two balls resting on it whose gap is too narrow for a third.
Scene twoBalls() {
  Scene scene;
  carom::Plane floor = carom::testing::makePlane(Vec3::Zero(), Vec3::UnitY());
  floor.name = "floor";
  scene.planes.push_back(floor);
  for (auto [name, x] : {std::pair{"first", 0.0}, std::pair{"second", 1.3}}) {
    carom::Ball ball = carom::testing::makeBall(Vec3(x, 0.5, 0), Vec3::Zero(), 0.5);
    ball.name = name;
    scene.balls.push_back(ball);
  }
  return scene;
}

std::vector<std::string> ballNames(const Scene& scene) {
  std::vector<std::string> names;
  for (const carom::Ball& ball : scene.balls) names.push_back(ball.name);
  return names;
}

}  // namespace

class TestEditActions : public QObject {
  Q_OBJECT

 private slots:
  void init();
  void cleanup();

  void copyThenPasteMovesAside();
  void pasteRefusesText();
  void duplicateGoesAcrossAndKeepsNames();
  void deleteKeepsTheOthersNames();
  void selectAllSelectsEverything();
  void boxesGoThroughTheClipboardWhole();
  void insertedBoxesMoveAsideOffBalls();

 private:
  std::unique_ptr<SceneDocument> document_;
  std::unique_ptr<EditActions> actions_;
  Vec3 across_ = Vec3::UnitX();
};

void TestEditActions::init() {
  document_ = std::make_unique<SceneDocument>();
  document_->reset(twoBalls(), {}, "two balls");
  across_ = Vec3::UnitX();
  actions_ = std::make_unique<EditActions>(document_.get(), [this] { return across_; });
}

void TestEditActions::cleanup() {
  actions_.reset();
  document_.reset();
}

void TestEditActions::copyThenPasteMovesAside() {
  document_->setSelection({{ObjectKind::Ball, 0}});
  actions_->copy();
  const QMimeData* mime = QApplication::clipboard()->mimeData();
  QVERIFY(mime && mime->hasFormat(EditActions::kSceneMimeType));
  const carom::io::SceneLoadResult copied =
      carom::io::parseScene(mime->data(EditActions::kSceneMimeType), "copy");
  QVERIFY2(copied.scene, qPrintable(copied.error));
  QCOMPARE(copied.scene->balls.size(), std::size_t{1});
  QCOMPARE(copied.scene->balls[0].name, std::string("first"));
  QVERIFY(mime->text().contains("\"balls\""));  // for other programs

  actions_->paste();
  QCOMPARE(document_->scene().balls.size(), std::size_t{3});
  QCOMPARE(document_->undoStack()->count(), 1);
  QCOMPARE(document_->selection(), (Selection{{ObjectKind::Ball, 2}}));
  // 1.1 m across would still overlap the second ball, and so would 2.2 m: 3.3 m fits.
  const carom::Ball& pasted = document_->scene().balls[2];
  QVERIFY((pasted.position - Vec3(3.3, 0.5, 0)).norm() < 1e-9);
  QCOMPARE(pasted.name, std::string("first"));
}

void TestEditActions::pasteRefusesText() {
  QApplication::clipboard()->setText("not a scene");
  QSignalSpy messages(actions_.get(), &EditActions::message);
  actions_->paste();
  QCOMPARE(messages.size(), 1);
  QVERIFY2(messages.first().first().toString().startsWith("Nothing to paste: "),
           qPrintable(messages.first().first().toString()));
  QVERIFY(document_->scene() == twoBalls());
  QCOMPARE(document_->undoStack()->count(), 0);
}

void TestEditActions::duplicateGoesAcrossAndKeepsNames() {
  across_ = Vec3::UnitZ();  // the window's "across" decides where copies go
  document_->setSelection({{ObjectKind::Ball, 1}});
  actions_->duplicate();
  QCOMPARE(ballNames(document_->scene()), (std::vector<std::string>{"first", "second", "second"}));
  QVERIFY((document_->scene().balls[2].position - Vec3(1.3, 0.5, 1.1)).norm() < 1e-9);
  QCOMPARE(document_->selection(), (Selection{{ObjectKind::Ball, 2}}));
  QCOMPARE(document_->undoStack()->undoText(), QString("Duplicate"));
  // Nothing selected: nothing to duplicate.
  document_->setSelection({});
  actions_->duplicate();
  QCOMPARE(document_->undoStack()->count(), 1);
}

void TestEditActions::deleteKeepsTheOthersNames() {
  document_->setSelection({{ObjectKind::Ball, 0}, {ObjectKind::Plane, 0}});
  actions_->deleteSelection();
  QCOMPARE(ballNames(document_->scene()), (std::vector<std::string>{"second"}));
  QVERIFY(document_->scene().planes.empty());
  QVERIFY(document_->selection().empty());
  QCOMPARE(document_->undoStack()->count(), 1);
  actions_->deleteSelection();  // nothing selected: no command
  QCOMPARE(document_->undoStack()->count(), 1);
}

void TestEditActions::selectAllSelectsEverything() {
  actions_->selectAll();
  QCOMPARE(document_->selection().size(), std::size_t{3});
  QVERIFY(std::count(document_->selection().begin(), document_->selection().end(),
                     carom::editor::ObjectRef{ObjectKind::Plane, 0}) == 1);
  actions_->deleteSelection();
  QVERIFY(document_->scene().balls.empty() && document_->scene().planes.empty());
  QCOMPARE(document_->undoStack()->count(), 1);
}

namespace {

carom::Box crate() {
  carom::Box box;
  box.center = Vec3(0, 0.5, 3);
  box.halfExtents = Vec3(0.5, 0.5, 0.5);
  box.rotation = carom::Rotation{Vec3(0, 1, 0), 30};
  box.name = "crate";
  box.color = "#806040";
  box.restitution = 0.25;
  return box;
}

}  // namespace

void TestEditActions::boxesGoThroughTheClipboardWhole() {
  Scene scene = twoBalls();
  scene.boxes.push_back(crate());
  document_->reset(scene, {}, "with a box");
  document_->setSelection({{ObjectKind::Box, 0}});
  actions_->copy();
  actions_->paste();
  QCOMPARE(document_->scene().boxes.size(), std::size_t{2});
  QCOMPARE(document_->selection(), (Selection{{ObjectKind::Box, 1}}));
  // Every field, the turn included, read back from the clipboard's scene file.
  QVERIFY(document_->scene().boxes[1] == crate());
  QVERIFY(document_->scene().balls == scene.balls);
  actions_->selectAll();
  QCOMPARE(document_->selection().size(), std::size_t{5});
  document_->setSelection({{ObjectKind::Box, 0}});
  actions_->duplicate();
  QCOMPARE(document_->scene().boxes.size(), std::size_t{3});
  QCOMPARE(document_->undoStack()->undoText(), QString("Duplicate"));
  actions_->deleteSelection();
  actions_->deleteSelection();  // the duplicate was selected, then nothing
  QCOMPARE(document_->scene().boxes.size(), std::size_t{2});
  document_->undoStack()->undo();
  document_->undoStack()->undo();
  document_->undoStack()->undo();
  QVERIFY(document_->scene() == scene);
}

// A box inserted where a ball stands moves across in steps of its half diagonal's 2.2 times
// until it overlaps no ball, as balls do.
void TestEditActions::insertedBoxesMoveAsideOffBalls() {
  Scene objects;
  carom::Box box = crate();
  box.rotation.reset();
  box.center = Vec3(0, 0.5, 0);  // on the first ball
  objects.boxes.push_back(box);
  actions_->insertObjects(objects, "Paste");
  QCOMPARE(document_->scene().boxes.size(), std::size_t{1});
  // One step (1.91 m) would still reach the second ball, at 1.3 m: two steps.
  const double step = 2.2 * box.halfExtents.norm();
  QVERIFY((document_->scene().boxes[0].center - Vec3(2 * step, 0.5, 0)).norm() < 1e-9);
  QCOMPARE(document_->scene().boxes[0].name, std::string("crate"));
}

QTEST_MAIN(TestEditActions)
#include "test_edit_actions.moc"
