// The editor's scene surgery: removing, extracting and appending objects must leave every other
// object exactly as it was, names and colours included, wherever the removed ones stood.

#include "ui/editor/object_ref.h"
#include "ui/editor/running_state.h"

#include <QTest>

#include <algorithm>
#include <string>

using carom::Ball;
using carom::Box;
using carom::Cylinder;
using carom::Plane;
using carom::Scene;
using carom::Vec3;
using carom::editor::ObjectKind;
using carom::editor::ObjectRef;
using carom::editor::Selection;

namespace {

constexpr int kPerKind = 5;

// Every object named and coloured after its kind and index, so that any mix-up shows.
Scene namedScene() {
  Scene scene;
  for (int i = 0; i < kPerKind; ++i) {
    const std::string tag = std::to_string(i);
    Ball ball;
    ball.position = Vec3(3.0 * i, 1, 0);
    ball.name = "ball " + tag;
    ball.color = "#1000" + tag + "0";
    ball.restitution = 0.1 * i;
    ball.extra = "{\"tag\":" + tag + "}";
    scene.balls.push_back(ball);
    Plane plane;
    plane.point = Vec3(0, -1.0 - i, 0);
    plane.name = "plane " + tag;
    plane.color = "#2000" + tag + "0";
    scene.planes.push_back(plane);
    Cylinder cylinder;
    cylinder.point = Vec3(-10.0 - 3 * i, 0, 0);
    cylinder.name = "cylinder " + tag;
    cylinder.color = "#3000" + tag + "0";
    scene.cylinders.push_back(cylinder);
    Box box;
    box.center = Vec3(0, 20.0 + 3 * i, 0);
    box.halfExtents = Vec3(0.5 + i, 0.25, 1.0);
    box.name = "box " + tag;
    box.color = "#4000" + tag + "0";
    box.restitution = 0.2 + 0.1 * i;
    if (i % 2 == 1) box.rotation = carom::Rotation{Vec3(1, 1, 0), 15.0 * i};
    box.extra = "{\"box\":" + tag + "}";
    scene.boxes.push_back(box);
  }
  return scene;
}

template <typename T>
std::vector<T> without(const std::vector<T>& items, const std::vector<int>& removed) {
  std::vector<T> kept;
  for (int i = 0; i < static_cast<int>(items.size()); ++i)
    if (std::find(removed.begin(), removed.end(), i) == removed.end()) kept.push_back(items[i]);
  return kept;
}

}  // namespace

class TestObjectRef : public QObject {
  Q_OBJECT
 private slots:
  void removeKeepsEveryOtherObject_data();
  void removeKeepsEveryOtherObject();
  void removeIgnoresReferencesToNothing();
  void extractThenAppendCopiesEveryField();
  void untouchedBallsKeepTheirRunningState();
  void insertUndoesRemove_data();
  void insertUndoesRemove();
  void assignWritesBackWhatExtractTook();
  void boxPositionAndLabel();
};

void TestObjectRef::removeKeepsEveryOtherObject_data() {
  QTest::addColumn<int>("kind");
  QTest::addColumn<std::vector<int>>("removed");
  const char* kinds[] = {"ball", "plane", "cylinder", "box"};
  for (int kind = 0; kind < carom::editor::kObjectKindCount; ++kind) {
    const auto row = [&](const char* where, std::vector<int> removed) {
      QTest::addRow("%s %s", kinds[kind], where) << kind << removed;
    };
    row("first", {0});
    row("middle", {2});
    row("last", {kPerKind - 1});
    row("first and last", {0, kPerKind - 1});
    row("two in the middle", {1, 3});
    row("all", {0, 1, 2, 3, 4});
  }
}

void TestObjectRef::removeKeepsEveryOtherObject() {
  QFETCH(int, kind);
  QFETCH(std::vector<int>, removed);
  const Scene before = namedScene();
  Selection selection;
  for (int index : removed) selection.push_back({ObjectKind(kind), index});
  Scene after = before;
  carom::editor::remove(after, selection);

  // The kind removed from lost exactly those; the other kinds are untouched, field by field.
  const auto expect = [&](ObjectKind k, const auto& items) {
    return ObjectKind(kind) == k ? without(items, removed) : items;
  };
  QCOMPARE(after.balls.size(), expect(ObjectKind::Ball, before.balls).size());
  QVERIFY(after.balls == expect(ObjectKind::Ball, before.balls));
  QVERIFY(after.planes == expect(ObjectKind::Plane, before.planes));
  QVERIFY(after.cylinders == expect(ObjectKind::Cylinder, before.cylinders));
  QVERIFY(after.boxes == expect(ObjectKind::Box, before.boxes));
  // Spelled out for the fields the old bug emptied, so a failure names them.
  for (const Ball& ball : after.balls) {
    QVERIFY(!ball.name.empty());
    QVERIFY(!ball.color.empty());
    QVERIFY(!ball.extra.empty());
  }
  for (const Plane& plane : after.planes) QVERIFY(!plane.name.empty() && !plane.color.empty());
  for (const Cylinder& c : after.cylinders) QVERIFY(!c.name.empty() && !c.color.empty());
  for (const Box& box : after.boxes) {
    QVERIFY(!box.name.empty() && !box.color.empty() && !box.extra.empty());
    QVERIFY(box.restitution.has_value());
  }
}

void TestObjectRef::removeIgnoresReferencesToNothing() {
  Scene scene = namedScene();
  carom::editor::remove(scene, {{ObjectKind::Ball, -1}, {ObjectKind::Plane, kPerKind}});
  QVERIFY(scene == namedScene());
}

void TestObjectRef::extractThenAppendCopiesEveryField() {
  const Scene source = namedScene();
  const Selection picked = {{ObjectKind::Ball, 4},
                            {ObjectKind::Plane, 0},
                            {ObjectKind::Cylinder, 2},
                            {ObjectKind::Box, 3}};
  const Scene part = carom::editor::extract(source, picked);
  Scene target = namedScene();
  const Selection added = carom::editor::append(target, part);
  QCOMPARE(added, (Selection{{ObjectKind::Ball, kPerKind},
                             {ObjectKind::Plane, kPerKind},
                             {ObjectKind::Cylinder, kPerKind},
                             {ObjectKind::Box, kPerKind}}));
  QVERIFY(target.balls.back() == source.balls[4]);
  QVERIFY(target.planes.back() == source.planes[0]);
  QVERIFY(target.cylinders.back() == source.cylinders[2]);
  // Every field of the box, its rotation included.
  QVERIFY(target.boxes.back() == source.boxes[3]);
  QVERIFY(target.boxes.back().rotation.has_value());
  // Then removing the copies gives back the original, as Duplicate followed by Delete does.
  carom::editor::remove(target, added);
  QVERIFY(target == namedScene());
}

// Edits applied to a running simulation: a ball the edit left alone takes the run's state; a
// ball it changed or added keeps the edit's.
void TestObjectRef::untouchedBallsKeepTheirRunningState() {
  const Scene shown = namedScene();
  std::vector<Vec3> positions, velocities;
  for (int i = 0; i < kPerKind; ++i) {
    positions.push_back(Vec3(100.0 + i, 0, 0));
    velocities.push_back(Vec3(0, -1.0 - i, 0));
  }
  const auto ranFrom = [&](const Scene& start, int startIndex, int shownIndex) {
    return start.balls[startIndex].position == positions[shownIndex] &&
           start.balls[startIndex].velocity == velocities[shownIndex];
  };
  // An edit removes balls (here ball 1): the others keep their running state.
  Scene edited = shown;
  carom::editor::remove(edited, {{ObjectKind::Ball, 1}});
  carom::editor::SceneChange change;
  change.removed = {{ObjectKind::Ball, 1}};
  Scene start = carom::editor::withRunningBalls(edited, change, positions, velocities);
  QCOMPARE(start.balls.size(), edited.balls.size());
  for (int i = 0; i < kPerKind - 1; ++i) QVERIFY(ranFrom(start, i, i < 1 ? i : i + 1));
  // Or changes balls in place and appends some: the changed and the new ones are as edited.
  edited = shown;
  edited.balls[3].name = "renamed";
  Ball added;
  added.position = Vec3(-50, 1, 0);
  edited.balls.push_back(added);
  change = {};
  change.edited = {{ObjectKind::Ball, 3}};
  change.inserted = {{ObjectKind::Ball, kPerKind}};
  start = carom::editor::withRunningBalls(edited, change, positions, velocities);
  QCOMPARE(start.balls.size(), edited.balls.size());
  for (int i : {0, 1, 2, 4}) QVERIFY(ranFrom(start, i, i));
  QVERIFY(start.balls[3] == edited.balls[3]);
  QVERIFY(start.balls[5] == added);
  QVERIFY(start.planes == edited.planes && start.cylinders == edited.cylinders);
}

void TestObjectRef::insertUndoesRemove_data() {
  removeKeepsEveryOtherObject_data();
}

// Undoing a Delete puts the removed objects back where they stood, every field as it was.
void TestObjectRef::insertUndoesRemove() {
  QFETCH(int, kind);
  QFETCH(std::vector<int>, removed);
  Selection refs;
  for (int index : removed) refs.push_back({ObjectKind(kind), index});
  // And a ball among the other kinds, and a box among balls, so that kinds mix.
  if (kind != 0) refs.push_back({ObjectKind::Ball, 2});
  if (kind == 0) refs.push_back({ObjectKind::Box, 1});
  const Scene before = namedScene();
  Scene scene = before;
  const Scene taken = carom::editor::extract(scene, carom::editor::normalized(refs));
  carom::editor::remove(scene, refs);
  QVERIFY(!(scene == before));
  carom::editor::insert(scene, refs, taken);
  QVERIFY(scene == before);
}

// An edit of a few objects works on their copies: the copies go back to the same places, and
// every other object stays as it was.
void TestObjectRef::assignWritesBackWhatExtractTook() {
  const Scene before = namedScene();
  const Selection refs{{ObjectKind::Ball, 1},
                       {ObjectKind::Ball, 4},
                       {ObjectKind::Cylinder, 2},
                       {ObjectKind::Box, 0},
                       {ObjectKind::Box, 3}};
  Scene values = carom::editor::extract(before, refs);
  const Selection local = carom::editor::extractedRefs(refs);
  QCOMPARE(local, (Selection{{ObjectKind::Ball, 0},
                             {ObjectKind::Ball, 1},
                             {ObjectKind::Cylinder, 0},
                             {ObjectKind::Box, 0},
                             {ObjectKind::Box, 1}}));
  for (const ObjectRef& ref : local) carom::editor::objectInfo(values, ref).name += " edited";
  Scene scene = before;
  carom::editor::assign(scene, refs, values);
  for (ObjectKind kind : carom::editor::kObjectKinds) {
    for (int i = 0; i < kPerKind; ++i) {
      const ObjectRef ref{kind, i};
      const bool edited = std::find(refs.begin(), refs.end(), ref) != refs.end();
      const std::string expected =
          carom::editor::objectInfo(before, ref).name + (edited ? " edited" : "");
      QCOMPARE(carom::editor::objectInfo(scene, ref).name, expected);
    }
  }
  QVERIFY(scene.balls[1].position == before.balls[1].position);
  QVERIFY(scene.boxes[3].rotation == before.boxes[3].rotation);
  QVERIFY(scene.boxes[3].extra == before.boxes[3].extra);
}

// A box's centre is what moves it, and it is named as the other kinds are.
void TestObjectRef::boxPositionAndLabel() {
  Scene scene = namedScene();
  const ObjectRef ref{ObjectKind::Box, 2};
  QCOMPARE(carom::editor::objectCount(scene, ObjectKind::Box), kPerKind);
  QVERIFY(carom::editor::objectPosition(scene, ref) == scene.boxes[2].center);
  carom::editor::setObjectPosition(scene, ref, Vec3(7, 8, 9));
  QVERIFY(scene.boxes[2].center == Vec3(7, 8, 9));
  QVERIFY(scene.boxes[2].halfExtents == namedScene().boxes[2].halfExtents);
  QCOMPARE(carom::editor::objectLabel(scene, ref), QString("box 2"));
  scene.boxes[2].name.clear();
  QCOMPARE(carom::editor::objectLabel(scene, ref), QString("Box 2"));
  QCOMPARE(carom::editor::kindPluralName(ObjectKind::Box), QString("Boxes"));
}

QTEST_APPLESS_MAIN(TestObjectRef)
#include "test_object_ref.moc"
