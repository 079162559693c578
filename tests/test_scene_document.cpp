// The document's edits: each says what it changed (kind and indices) so that observers update
// only that; undo and redo restore every field; a refused edit changes nothing; and the
// outline announces only the rows an edit touched.

#include "ui/editor/outline_dock.h"
#include "ui/editor/scene_document.h"

#include <QGuiApplication>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <string>
#include <vector>

using carom::Ball;
using carom::Scene;
using carom::Vec3;
using carom::editor::ObjectKind;
using carom::editor::ObjectRef;
using carom::editor::SceneChange;
using carom::editor::SceneDocument;
using carom::editor::Selection;

namespace {

// A floor, a post and ten named balls in a row.
Scene rowOfBalls() {
  Scene scene = SceneDocument::newScene();
  carom::Cylinder post;
  post.point = Vec3(0, 0, -5);
  post.radius = 0.5;
  post.name = "post";
  scene.cylinders.push_back(post);
  for (int i = 0; i < 10; ++i) {
    Ball ball;
    ball.position = Vec3(3.0 * i, 1, 0);
    ball.name = "ball " + std::to_string(i);
    ball.color = "#0000" + std::to_string(10 + i);
    scene.balls.push_back(ball);
  }
  return scene;
}

// Records every change the document reports.
struct ChangeLog {
  explicit ChangeLog(SceneDocument& document) {
    QObject::connect(&document, &SceneDocument::sceneChanged, &receiver,
                     [this](const SceneChange& change) { changes.push_back(change); });
  }
  QObject receiver;  // disconnects when the log goes
  std::vector<SceneChange> changes;
};

}  // namespace

class TestSceneDocument : public QObject {
  Q_OBJECT
 private slots:
  void init() { document_.reset(rowOfBalls(), {}); }

  void editReportsTheObjectsItChanged() {
    ChangeLog log(document_);
    const Selection refs{{ObjectKind::Ball, 3}, {ObjectKind::Ball, 7}};
    Scene values = carom::editor::extract(document_.scene(), refs);
    values.balls[0].radius = 0.75;
    values.balls[1].mass = 5.0;
    QCOMPARE(document_.editObjects(refs, values, "edit"), QString());
    QCOMPARE(document_.scene().balls[3].radius, 0.75);
    QCOMPARE(document_.scene().balls[7].mass, 5.0);
    QCOMPARE(int(log.changes.size()), 1);
    QCOMPARE(log.changes[0].edited, refs);
    QVERIFY(!log.changes[0].world && !log.changes[0].replaced);
    QVERIFY(log.changes[0].removed.empty() && log.changes[0].inserted.empty());
    document_.undoStack()->undo();
    QVERIFY(document_.scene() == rowOfBalls());
    QCOMPARE(log.changes.back().edited, refs);
    document_.undoStack()->redo();
    QCOMPARE(document_.scene().balls[3].radius, 0.75);
    // The same values again: no command, no change.
    QCOMPARE(document_.editObjects(refs, values, "again"), QString());
    QCOMPARE(document_.undoStack()->count(), 1);
    QCOMPARE(int(log.changes.size()), 3);
  }

  void refusedEditChangesNothing() {
    ChangeLog log(document_);
    const Selection refs{{ObjectKind::Ball, 2}};
    Scene values = carom::editor::extract(document_.scene(), refs);
    values.balls[0].position = document_.scene().balls[3].position;  // onto ball 3
    // The validation's first problem, in the window's words: objects by their names.
    QCOMPARE(document_.editObjects(refs, values, "overlap"),
             QString("ball 3 would overlap ball 2 by 2 m"));
    QVERIFY(document_.scene() == rowOfBalls());
    QCOMPARE(document_.undoStack()->count(), 0);
    QVERIFY(log.changes.empty());
    // A world edit is checked too.
    carom::World world = document_.scene().world;
    world.timeStep = -1;
    QCOMPARE(document_.editWorld(world, "bad step"),
             QString("Time step must be above zero (got -1 s)"));
    QVERIFY(log.changes.empty());
    // And added objects.
    Scene added;
    added.balls.push_back(document_.scene().balls[0]);
    added.balls[0].name.clear();
    // Named as it would be once added.
    QCOMPARE(document_.addObjects(added, "onto ball 0"),
             QString("Ball 10 would overlap ball 0 by 2 m"));
    QVERIFY(document_.scene() == rowOfBalls());
  }

  // Boxes ride along with edits of other objects: deleting and moving balls leaves them as they
  // were, undo gives back the scene whole, and a ball moved into a box
  // is refused with the validation's message.
  void boxesSurviveEditsAndStopOverlaps() {
    Scene withBox = rowOfBalls();
    carom::Box box;
    box.center = Vec3(0, 1, 4);
    box.halfExtents = Vec3(1, 1, 1);
    box.rotation = carom::Rotation{Vec3(0, 1, 0), 15};
    box.name = "crate";
    withBox.boxes.push_back(box);
    document_.reset(withBox, {});
    QCOMPARE(document_.removeObjects({{ObjectKind::Ball, 1}}, "Delete"), QString());
    const Selection moved{{ObjectKind::Ball, 0}};
    Scene values = carom::editor::extract(document_.scene(), moved);
    values.balls[0].position = Vec3(0, 1, 1.5);
    QCOMPARE(document_.editObjects(moved, values, "Move"), QString());
    QVERIFY(document_.scene().boxes == withBox.boxes);
    values.balls[0].position = Vec3(0.2, 1, 3.4);
    QVERIFY(document_.editObjects(moved, values, "Into the box")
                .contains("ball 0 would overlap crate by"));
    document_.undoStack()->undo();
    document_.undoStack()->undo();
    QVERIFY(document_.scene() == withBox);
  }

  // Deleting boxes, in the middle and at the end, changes no other object, name or field; undo
  // and redo give back each state exactly.
  void deletingABoxKeepsEveryOtherObject() {
    Scene scene = rowOfBalls();
    for (int i = 0; i < 4; ++i) {
      carom::Box box;
      box.center = Vec3(3.0 * i, 4, -8);
      box.halfExtents = Vec3(0.5, 0.25 + 0.1 * i, 1);
      box.name = "box " + std::to_string(i);
      box.color = "#00ff0" + std::to_string(i);
      box.restitution = 0.5;
      if (i != 2) box.rotation = carom::Rotation{Vec3(0, 1, 1), 20.0 * i};
      box.extra = R"({"tag":)" + std::to_string(i) + "}";
      scene.boxes.push_back(box);
    }
    document_.reset(scene, {});
    ChangeLog log(document_);
    const Selection doomed{{ObjectKind::Box, 1}, {ObjectKind::Box, 3}};
    document_.setSelection(doomed);
    QCOMPARE(document_.removeObjects(doomed, "Delete"), QString());
    Scene expected = scene;
    expected.boxes = {scene.boxes[0], scene.boxes[2]};
    QVERIFY(document_.scene() == expected);
    QCOMPARE(document_.scene().boxes[1].name, std::string("box 2"));
    QVERIFY(!document_.scene().boxes[1].rotation);
    QCOMPARE(log.changes.back().removed, doomed);
    document_.undoStack()->undo();
    QVERIFY(document_.scene() == scene);
    QCOMPARE(document_.selection(), doomed);
    document_.undoStack()->redo();
    QVERIFY(document_.scene() == expected);
  }

  // A box's edit is checked by the scene validation: sizes must be positive, the axis not zero,
  // and no ball may end up inside; a refused edit changes nothing.
  void boxEditsAreValidated() {
    Scene scene = rowOfBalls();
    carom::Box box;
    box.center = Vec3(1.5, 1, 0);  // between balls 0 and 1, which stand 3 apart
    box.halfExtents = Vec3(0.25, 0.25, 0.25);
    scene.boxes.push_back(box);
    document_.reset(scene, {});
    const Selection ref{{ObjectKind::Box, 0}};
    Scene values = carom::editor::extract(document_.scene(), ref);
    values.boxes[0].halfExtents.y() = 0;
    QCOMPARE(document_.editObjects(ref, values, "Resize"),
             QString("Half extents y of Box 0 must be above zero (got 0 m)"));
    values.boxes[0].halfExtents = Vec3(1, 0.25, 0.25);  // reaches into both balls
    QVERIFY(document_.editObjects(ref, values, "Resize").contains("would overlap Box 0 by"));
    values.boxes[0].halfExtents = Vec3(0.25, 0.25, 0.25);
    values.boxes[0].rotation = carom::Rotation{Vec3::Zero(), 10};
    QCOMPARE(document_.editObjects(ref, values, "Turn"),
             QString("Rotation axis of Box 0 must not be zero: it gives a direction"));
    QVERIFY(document_.scene() == scene);
    QCOMPARE(document_.undoStack()->count(), 0);
    values.boxes[0].rotation = carom::Rotation{Vec3(0, 2, 0), 10};
    QCOMPARE(document_.editObjects(ref, values, "Turn"), QString());
    QCOMPARE(document_.undoStack()->count(), 1);
    QVERIFY(document_.scene().boxes[0] == values.boxes[0]);
    document_.undoStack()->undo();
    QVERIFY(document_.scene() == scene);
  }

  void removeAndUndoRestoreEveryField() {
    ChangeLog log(document_);
    const Selection doomed{{ObjectKind::Ball, 0},
                           {ObjectKind::Ball, 4},
                           {ObjectKind::Ball, 5},
                           {ObjectKind::Cylinder, 0}};
    document_.setSelection(doomed);
    QCOMPARE(document_.removeObjects(doomed, "Delete"), QString());
    QCOMPARE(int(document_.scene().balls.size()), 7);
    QVERIFY(document_.scene().cylinders.empty());
    QCOMPARE(document_.scene().balls[3].name, std::string("ball 6"));
    QVERIFY(document_.selection().empty());
    QCOMPARE(log.changes.back().removed, doomed);
    document_.undoStack()->undo();
    QVERIFY(document_.scene() == rowOfBalls());
    QCOMPARE(log.changes.back().inserted, doomed);
    QCOMPARE(document_.selection(), doomed);
  }

  void addSelectsAndReportsTheNewObjects() {
    ChangeLog log(document_);
    Scene added;
    Ball ball;
    ball.position = Vec3(0, 5, 0);
    added.balls.push_back(ball);
    carom::Plane wall;
    wall.point = Vec3(-5, 0, 0);
    wall.normal = Vec3(1, 0, 0);
    added.planes.push_back(wall);
    QCOMPARE(document_.addObjects(added, "Paste"), QString());
    const Selection expected{{ObjectKind::Ball, 10}, {ObjectKind::Plane, 1}};
    QCOMPARE(document_.selection(), expected);
    QCOMPARE(log.changes.back().inserted, expected);
    QVERIFY(document_.scene().balls[10].position == ball.position);
    document_.undoStack()->undo();
    QVERIFY(document_.scene() == rowOfBalls());
  }

  void worldEditReportsTheWorldOnly() {
    ChangeLog log(document_);
    carom::World world = document_.scene().world;
    world.gravity = Vec3(0, -1.62, 0);
    QCOMPARE(document_.editWorld(world, "Moon"), QString());
    QCOMPARE(int(log.changes.size()), 1);
    QVERIFY(log.changes[0].world && !log.changes[0].objectsChanged());
    document_.undoStack()->undo();
    QVERIFY(document_.scene().world == rowOfBalls().world);
  }

  void aDragIsOneCommand() {
    const int gesture = document_.newGesture();
    const Selection refs{{ObjectKind::Ball, 9}};
    for (int step = 1; step <= 5; ++step) {
      Scene values = carom::editor::extract(rowOfBalls(), refs);
      values.balls[0].position.y() += step;
      QCOMPARE(document_.editObjects(refs, values, "Move", gesture), QString());
    }
    QCOMPARE(document_.undoStack()->count(), 1);
    QCOMPARE(document_.scene().balls[9].position.y(), 6.0);
    document_.undoStack()->undo();
    QVERIFY(document_.scene() == rowOfBalls());
  }

  void outlineAnnouncesOnlyTheRowsTouched() {
    carom::editor::OutlineModel model(&document_);
    const QModelIndex balls = model.groupIndex(ObjectKind::Ball);
    QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
    QSignalSpy removed(&model, &QAbstractItemModel::rowsRemoved);
    QSignalSpy inserted(&model, &QAbstractItemModel::rowsInserted);
    // A rename: that row alone.
    const Selection refs{{ObjectKind::Ball, 6}};
    Scene values = carom::editor::extract(document_.scene(), refs);
    values.balls[0].name = "renamed";
    QCOMPARE(document_.editObjects(refs, values, "Rename"), QString());
    QCOMPARE(changed.count(), 1);
    QCOMPARE(changed[0][0].value<QModelIndex>(), model.index(6, 0, balls));
    QCOMPARE(changed[0][1].value<QModelIndex>(), model.index(6, 0, balls));
    // A delete of balls 2 and 3: those rows go, and the rows after them (renumbered) and the
    // group's count are announced; the rows before are not.
    changed.clear();
    QCOMPARE(document_.removeObjects({{ObjectKind::Ball, 2}, {ObjectKind::Ball, 3}}, "Delete"),
             QString());
    QCOMPARE(removed.count(), 1);
    QCOMPARE(removed[0][1].toInt(), 2);
    QCOMPARE(removed[0][2].toInt(), 3);
    QCOMPARE(model.rowCount(balls), 8);
    for (const QList<QVariant>& signal : changed) {
      const QModelIndex first = signal[0].value<QModelIndex>();
      QVERIFY(first == balls || (first.parent() == balls && first.row() >= 2));
    }
    // Undo puts them back in place.
    document_.undoStack()->undo();
    QCOMPARE(inserted.count(), 1);
    QCOMPARE(inserted[0][1].toInt(), 2);
    QCOMPARE(model.rowCount(balls), 10);
    QCOMPARE(model.data(model.index(3, 0, balls), Qt::DisplayRole).toString(), QString("ball 3"));
  }

 private:
  SceneDocument document_;
};

// A refusal names objects elided in the application's font (validation_text.h): a
// QGuiApplication, on the offscreen platform, so that the test needs no display.
int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QGuiApplication app(argc, argv);
  TestSceneDocument test;
  return QTest::qExec(&test, argc, argv);
}
#include "test_scene_document.moc"
