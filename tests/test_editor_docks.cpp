// The editor's docks and handles as a user drives them: the outline (grouped objects, selection
// shared with the view, renaming), the properties dock (typed fields, units, the shared
// validation refusing bad values, multi-selection, the world settings, the colour picker, a
// cylinder's length), and the handles that turn a plane's normal and a cylinder's axis, move a
// box's faces and a capped cylinder's ends.

#include "sim/geometry/shapes.h"
#include "sim/io/scene_file.h"
#include "tests/editor_fixture.h"
#include "tests/scene_helpers.h"
#include "ui/docks/ball_story_dock.h"
#include "ui/editor/editor_tools.h"
#include "ui/editor/number_text.h"
#include "ui/editor/outline_dock.h"
#include "ui/editor/properties_dock.h"
#include "ui/run/run_session.h"
#include "ui/run/simulation_snapshot.h"

#include <QChartView>
#include <QClipboard>
#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLegend>
#include <QLegendMarker>
#include <QLineEdit>
#include <QScrollArea>
#include <QScrollBar>
#include <QTemporaryDir>
#include <QToolButton>
#include <QTreeView>
#include <QUndoStack>
#include <QUndoView>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

using carom::Vec3;
using carom::editor::ObjectKind;
using carom::editor::Selection;

class TestEditorDocks : public carom::testing::EditorFixture {
  Q_OBJECT

 private slots:
  void init() { openWindow(); }
  void cleanup() { window_.reset(); }

  void outlineGroupsEveryObject();
  void outlineFollowsEdits();
  void boxesAreGroupedPickedAndHighlighted();
  void selectingInTheOutlineSelectsInTheView();
  void selectingInTheViewSelectsInTheOutline();
  void renamingInTheOutline();
  void viewKeysWorkWhereverTheFocusIs();
  void editsAFieldAsOneCommand();
  void refusesBadValues_data();
  void refusesBadValues();
  void editsEverySelectedObject();
  void editsABox();
  void refusesBadBoxValues_data();
  void refusesBadBoxValues();
  void showsOnlyTheFieldsTheSelectionHas();
  void editsTheWorldWhenNothingIsSelected();
  void picksAColour();
  void turnsAPlaneByItsHandle();
  void turnsACylinderByItsHandle();
  void resizesABoxByItsFaceHandles();
  void resizesABoxFromItsNegativeFaces();
  void editsACylindersLength();
  void refusesBadLengths_data();
  void refusesBadLengths();
  void editsTheLengthOfSeveralCylinders();
  void resizesACappedCylinderByItsEnds();
  void turnsABoxByItsHandle();
  void typesANormal();
  void saveTakesTheValueBeingTyped();
  void toolbarRefusesBadValues_data();
  void toolbarRefusesBadValues();
  void toolbarShowsShortButKeepsExactValues();
  void narrowFieldsShowTheStartOfTheirValues();
  void fieldsShowSixDigitsAndEditAllOfThem();
  void fieldsLeftAsTheyWereKeepExactValues();
  void refusalGoesOnceTheFieldIsValidAgain();
  void aRefusalLeavesTheRowsReadable();
  void refusesNamesOverTheLimit();
  void outlineRefusesNamesOverTheLimit();
  void longNamesAreElided();

 private:
  QTreeView& tree() { return *window_->outlineDock()->tree(); }
  carom::editor::OutlineModel& outline() { return *window_->outlineDock()->model(); }
  carom::editor::PropertiesDock& properties() { return *window_->propertiesDock(); }
  QLineEdit* field(const QString& name) {
    auto* edit = properties().findChild<QLineEdit*>(name);
    if (!edit) qWarning("no field %s", qPrintable(name));
    return edit;
  }
  // Clicks into the field, replaces its text as a user would, and presses Enter.
  void type(const QString& name, const QString& text) {
    QLineEdit* edit = field(name);
    QVERIFY(edit);
    QVERIFY2(edit->isVisible(), qPrintable(name));
    QTest::mouseClick(edit, Qt::LeftButton);
    QTest::keyClick(edit, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClick(edit, Qt::Key_Backspace);
    QTest::keyClicks(edit, text);
    QTest::keyClick(edit, Qt::Key_Return);
  }
  void clickRow(const QModelIndex& index, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    tree().scrollTo(index);
    QTest::mouseClick(tree().viewport(), Qt::LeftButton, modifiers,
                      tree().visualRect(index).center());
  }
  // A double click opens the row's name for editing (F2 follows a ball wherever the focus is).
  void startRenaming(const QModelIndex& index) {
    tree().scrollTo(index);
    QTest::mouseDClick(tree().viewport(), Qt::LeftButton, Qt::NoModifier,
                       tree().visualRect(index).center());
  }
  // Pixels of the view's image, in the square round the ball, that differ from `before`.
  int changedPixelsAroundBall(const QImage& before) {
    const Vec3 centre = document().scene().balls[0].position;
    const double radius = document().scene().balls[0].radius;
    const QPointF middle = view().project(centre);
    double reach = 0.0;
    for (int a = 0; a < 3; ++a) {
      const QPointF side = view().project(centre + radius * Vec3::Unit(a)) - middle;
      reach = std::max(reach, std::hypot(side.x(), side.y()));
    }
    const QImage after = view().grabFramebuffer();
    const double scale = after.width() / double(view().width());
    int changed = 0;
    for (int y = int((middle.y() - reach) * scale); y <= int((middle.y() + reach) * scale); ++y)
      for (int x = int((middle.x() - reach) * scale); x <= int((middle.x() + reach) * scale); ++x)
        if (after.valid(x, y) && after.pixel(x, y) != before.pixel(x, y)) ++changed;
    return changed;
  }
  Selection outlineSelection() {
    Selection selection;
    for (const QModelIndex& index : tree().selectionModel()->selectedIndexes())
      if (auto ref = outline().objectAt(index)) selection.push_back(*ref);
    return carom::editor::normalized(selection);
  }
  // Adds an unturned box of half size 0.5 resting on the floor at (2, 0, 0), as one command.
  void addBox() {
    carom::Scene edited = document().scene();
    carom::Box crate;
    crate.center = Vec3(2, 0.5, 0);
    crate.halfExtents = Vec3(0.5, 0.5, 0.5);
    edited.boxes.push_back(crate);
    QVERIFY(carom::testing::applyEdit(document(), edited, "add").isEmpty());
  }
  bool unitShown(const QString& unit) {
    for (QLabel* label : properties().findChildren<QLabel*>())
      if (label->isVisible() && label->text() == unit) return true;
    return false;
  }
  // Adds a cylinder standing at (2, 0, -2), away from the ball, as one command.
  void addCylinder() {
    carom::Scene edited = document().scene();
    carom::Cylinder post;
    post.point = Vec3(2, 0, -2);
    post.radius = 0.3;
    edited.cylinders.push_back(post);
    QVERIFY(carom::testing::applyEdit(document(), edited, "add").isEmpty());
  }
  // Adds a capped cylinder, as one command.
  void addCappedCylinder(const Vec3& middle, const Vec3& axis, double length) {
    carom::Scene edited = document().scene();
    edited.cylinders.push_back(carom::testing::makeCylinder(middle, axis, 0.3, length));
    QVERIFY(carom::testing::applyEdit(document(), edited, "add").isEmpty());
  }
};

void TestEditorDocks::outlineGroupsEveryObject() {
  const QModelIndex balls = outline().groupIndex(ObjectKind::Ball);
  const QModelIndex planes = outline().groupIndex(ObjectKind::Plane);
  const QModelIndex cylinders = outline().groupIndex(ObjectKind::Cylinder);
  QCOMPARE(balls.data().toString(), QString("Balls (1)"));
  QCOMPARE(planes.data().toString(), QString("Planes (3)"));
  QCOMPARE(cylinders.data().toString(), QString("Cylinders (0)"));
  QCOMPARE(outline().rowCount(planes), 3);
  // Named objects show their names; the others their kind and index, as in messages.
  QCOMPARE(outline().index(0, 0, balls).data().toString(), QString("first"));
  QCOMPARE(outline().index(0, 0, planes).data().toString(), QString("floor"));
  QCOMPARE(outline().index(2, 0, planes).data().toString(), QString("Plane 2"));
  QCOMPARE(outline().index(2, 0, planes).data(Qt::ToolTipRole).toString(), QString("planes[2]"));
  // The ball's colour as its icon; groups cannot be selected.
  QVERIFY(!outline().index(0, 0, balls).data(Qt::DecorationRole).isNull());
  QVERIFY(!(outline().flags(balls) & Qt::ItemIsSelectable));
}

void TestEditorDocks::outlineFollowsEdits() {
  chooseTool("toolAddBall");
  click(Vec3(2, 0, 1));
  const QModelIndex balls = outline().groupIndex(ObjectKind::Ball);
  QCOMPARE(outline().rowCount(balls), 2);
  QCOMPARE(balls.data().toString(), QString("Balls (2)"));
  // The new ball is selected, in the outline too.
  QCOMPARE(outlineSelection(), (Selection{{ObjectKind::Ball, 1}}));
  document().undoStack()->undo();
  QCOMPARE(outline().rowCount(balls), 1);
  QVERIFY(outlineSelection().empty());
  // Deleting the first of several shifts the rest up.
  document().setSelection({{ObjectKind::Plane, 0}});
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  const QModelIndex planes = outline().groupIndex(ObjectKind::Plane);
  QCOMPARE(outline().rowCount(planes), 2);
  QCOMPARE(outline().index(0, 0, planes).data().toString(), QString("Plane 0"));
}

// Boxes in their own group, picked in the view by their true shape (a turned box's corner
// beside it is the floor), and shown in the selection's colour.
void TestEditorDocks::boxesAreGroupedPickedAndHighlighted() {
  carom::Scene edited = document().scene();
  carom::Box crate;
  crate.center = Vec3(2, 0.5, 0);
  crate.halfExtents = Vec3(0.5, 0.5, 0.5);
  crate.rotation = carom::Rotation{Vec3::UnitY(), 45};
  crate.color = "#3060c0";
  edited.boxes.push_back(crate);
  QVERIFY(carom::testing::applyEdit(document(), edited, "add").isEmpty());
  const QModelIndex boxes = outline().groupIndex(ObjectKind::Box);
  QCOMPARE(boxes.data().toString(), QString("Boxes (1)"));
  QCOMPARE(outline().index(0, 0, boxes).data().toString(), QString("Box 0"));
  QCOMPARE(outline().index(0, 0, boxes).data(Qt::ToolTipRole).toString(), QString("boxes[0]"));

  chooseTool("toolSelect");
  document().setSelection({});  // the addition selected it
  const QImage before = view().grabFramebuffer();
  click(Vec3(2, 1.0, 0));  // the middle of its top
  QCOMPARE(document().selection(), (Selection{{ObjectKind::Box, 0}}));
  QCOMPARE(outlineSelection(), (Selection{{ObjectKind::Box, 0}}));
  QVERIFY(properties().heading().contains("Box 0"));
  // The top's middle takes on the selection's orange: more red, less blue.
  const QImage after = view().grabFramebuffer();
  const double scale = after.width() / double(view().width());
  const QPoint top = (view().project(Vec3(2, 1.0, 0)) * scale).toPoint();
  QVERIFY2(QColor(after.pixel(top)).red() > QColor(before.pixel(top)).red() + 40,
           qPrintable(QString("%1 -> %2")
                          .arg(QColor(before.pixel(top)).name(), QColor(after.pixel(top)).name())));
  // Turned by 45 degrees, the box leaves the floor bare at the corner of its unturned outline.
  click(Vec3(2.45, 0, 0.45));
  QCOMPARE(document().selection(), (Selection{{ObjectKind::Plane, 0}}));
  // Deleting it empties the group and leaves the rest alone.
  const carom::Scene withBox = document().scene();
  document().setSelection({{ObjectKind::Box, 0}});
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  QCOMPARE(outline().rowCount(boxes), 0);
  carom::Scene expected = withBox;
  expected.boxes.clear();
  QVERIFY(document().scene() == expected);
}

void TestEditorDocks::selectingInTheOutlineSelectsInTheView() {
  const QModelIndex planes = outline().groupIndex(ObjectKind::Plane);
  clickRow(outline().index(0, 0, outline().groupIndex(ObjectKind::Ball)));
  QCOMPARE(document().selection(), (Selection{{ObjectKind::Ball, 0}}));
  QVERIFY(properties().heading().contains("first"));
  clickRow(outline().index(2, 0, planes), Qt::ControlModifier);
  QCOMPARE(document().selection(), (Selection{{ObjectKind::Ball, 0}, {ObjectKind::Plane, 2}}));
  clickRow(outline().index(0, 0, planes));
  QCOMPARE(document().selection(), (Selection{{ObjectKind::Plane, 0}}));
  // A click on a group's row selects nothing.
  clickRow(planes);
  QVERIFY(document().selection().empty());
  // The view draws the selection: a ring round the ball when the outline picks it.
  const QImage before = view().grabFramebuffer();
  clickRow(outline().index(0, 0, outline().groupIndex(ObjectKind::Ball)));
  QTRY_VERIFY(changedPixelsAroundBall(before) > 20);
}

void TestEditorDocks::selectingInTheViewSelectsInTheOutline() {
  chooseTool("toolSelect");
  click(Vec3(0, 0.5, 0));
  QCOMPARE(outlineSelection(), (Selection{{ObjectKind::Ball, 0}}));
  click(Vec3(1.5, 0, 1.5), Qt::ControlModifier);
  QCOMPARE(outlineSelection(), (Selection{{ObjectKind::Ball, 0}, {ObjectKind::Plane, 0}}));
  QTest::keyClick(window_.get(), Qt::Key_A, Qt::ControlModifier);
  QCOMPARE(outlineSelection().size(), std::size_t{4});
  QTest::mouseClick(&view(), Qt::LeftButton, Qt::NoModifier, QPoint(view().width() / 2, 3));
  QVERIFY(outlineSelection().empty());
}

// Issue 34: after a click in the Outline, Home moved the tree's current row and F2 renamed the
// object instead of framing the scene and following a ball. The view's keys are the window's,
// wherever the focus is, except in a text field being edited.
void TestEditorDocks::viewKeysWorkWhereverTheFocusIs() {
  view().frameScene();
  const double framed = view().camera().distance();
  auto* run = window_->findChild<QAction*>("run");
  auto* timeStep = window_->findChild<QDoubleSpinBox*>("timeStep");
  QVERIFY(run && timeStep);
  auto* history = window_->findChild<QUndoView*>();
  QVERIFY(history);
  const QModelIndex wall = outline().index(1, 0, outline().groupIndex(ObjectKind::Plane));
  for (QWidget* focus : {static_cast<QWidget*>(&tree()), static_cast<QWidget*>(history)}) {
    if (focus == &tree()) {
      clickRow(wall);
    } else {
      QTest::mouseClick(history->viewport(), Qt::LeftButton, Qt::NoModifier, QPoint(5, 5));
    }
    QTRY_VERIFY(focus->hasFocus());
    const QModelIndex current = tree().currentIndex();
    view().camera().zoom(-3);
    QTest::keyClick(focus, Qt::Key_Home);
    QVERIFY2(
        std::abs(view().camera().distance() - framed) < 1e-9,
        qPrintable(QString("distance %1, framed %2").arg(view().camera().distance()).arg(framed)));
    QCOMPARE(tree().currentIndex(), current);
    QTest::keyClick(focus, Qt::Key_F2);
    QCOMPARE(view().followedBall(), 0);
    QVERIFY(!tree().viewport()->findChild<QLineEdit*>() ||
            !tree().viewport()->findChild<QLineEdit*>()->isVisible());
    QTest::keyClick(focus, Qt::Key_F2);
    QCOMPARE(view().followedBall(), -1);
    QTest::keyClick(focus, Qt::Key_Space);
    QVERIFY(run->isChecked());
    QTest::keyClick(focus, Qt::Key_Space);
    QVERIFY(!run->isChecked());
    const double step = timeStep->value();
    QTest::keyClick(focus, Qt::Key_Plus);
    QCOMPARE(timeStep->value(), step * 1.25);
    QTest::keyClick(focus, Qt::Key_Minus);
    QVERIFY(std::abs(timeStep->value() - step) < 1e-15);
    QTest::keyClick(focus, Qt::Key_S);
    QTRY_VERIFY(currentSnapshot()->time > 0.0);
    QTest::keyClick(focus, Qt::Key_R);
    QTRY_COMPARE(currentSnapshot()->time, 0.0);
    QVERIFY(focus->hasFocus());  // the keys did not take the focus away
  }
  // In a text field being edited, the keys are the field's.
  startRenaming(wall);
  auto* editor = tree().viewport()->findChild<QLineEdit*>();
  QTRY_VERIFY(editor && editor->isVisible());
  QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClicks(editor, "s r+-");
  QCOMPARE(editor->text(), QString("s r+-"));
  QVERIFY(!run->isChecked());
  QTest::keyClick(editor, Qt::Key_Escape);
}

void TestEditorDocks::renamingInTheOutline() {
  const QModelIndex wall = outline().index(1, 0, outline().groupIndex(ObjectKind::Plane));
  clickRow(wall);
  startRenaming(wall);
  auto* editor = tree().viewport()->findChild<QLineEdit*>();
  QTRY_VERIFY(editor && editor->isVisible());
  QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClicks(editor, "west wall");  // spaces and letters reach the editor, not shortcuts
  QTest::keyClick(editor, Qt::Key_Return);
  // The item view commits on its next turn of the event loop.
  QTRY_COMPARE(document().scene().planes[1].name, std::string("west wall"));
  QCOMPARE(document().undoStack()->count(), 1);
  QCOMPARE(wall.data().toString(), QString("west wall"));
  // Space typed into the name did not run the simulation.
  QVERIFY(!window_->findChild<QAction*>("run")->isChecked());
  document().undoStack()->undo();
  QCOMPARE(document().scene().planes[1].name, std::string());
}

void TestEditorDocks::editsAFieldAsOneCommand() {
  document().setSelection({{ObjectKind::Ball, 0}});
  QCOMPARE(field("ballRadius")->text(), QString("0.5"));
  type("ballRadius", "0.25");
  QCOMPARE(document().scene().balls[0].radius, 0.25);
  type("position.y", "2");
  QCOMPARE(document().scene().balls[0].position, Vec3(0, 2, 0));
  type("velocity.x", "-1.5");
  QCOMPARE(document().scene().balls[0].velocity, Vec3(-1.5, 0, 0));
  type("name", "Cue ball");
  QCOMPARE(document().scene().balls[0].name, std::string("Cue ball"));
  QCOMPARE(document().undoStack()->count(), 4);
  QCOMPARE(document().undoStack()->text(0), QString("Change Radius"));
  // The typed value shows as the scene has it; the command undoes and redoes.
  QCOMPARE(field("velocity.x")->text(), QString("-1.5"));
  document().undoStack()->undo();
  document().undoStack()->undo();
  QCOMPARE(document().scene().balls[0].velocity, Vec3::Zero());
  QCOMPARE(field("velocity.x")->text(), QString("0"));
  document().undoStack()->redo();
  QCOMPARE(field("velocity.x")->text(), QString("-1.5"));
  // Units stand beside the fields.
  QVERIFY(properties().findChildren<QLabel*>().size() > 0);
  bool hasUnit = false;
  for (QLabel* label : properties().findChildren<QLabel*>())
    hasUnit |= label->isVisible() && label->text() == "m/s";
  QVERIFY(hasUnit);
  // Leaving a field unchanged makes no command (which would drop the redoable one).
  QTest::mouseClick(field("mass"), Qt::LeftButton);
  QTest::keyClick(field("mass"), Qt::Key_Return);
  QCOMPARE(document().undoStack()->index(), 3);
  QCOMPARE(document().undoStack()->count(), 4);
}

void TestEditorDocks::refusesBadValues_data() {
  QTest::addColumn<QString>("field");
  QTest::addColumn<QString>("typed");
  QTest::addColumn<QString>("message");
  QTest::newRow("negative radius") << "ballRadius"
                                   << "-1"
                                   << "Radius of first must be above zero (got -1 m)";
  QTest::newRow("zero mass") << "mass"
                             << "0"
                             << "Mass of first must be above zero (got 0 kg)";
  QTest::newRow("not a number") << "mass"
                                << "heavy"
                                << "“heavy” is not a number";
  QTest::newRow("nan") << "position.x"
                       << "nan"
                       << "Position of first must be a finite number";
  QTest::newRow("overflow") << "velocity.z"
                            << "1e400"
                            << "“1e400” is out of range";
  QTest::newRow("absurd") << "velocity.z"
                          << "1e300"
                          << "Velocity of first must lie within ±";
  QTest::newRow("restitution") << "restitution"
                               << "1.5"
                               << "Restitution of first must be between 0 and 1 (got 1.5)";
  QTest::newRow("colour") << "color"
                          << "red"
                          << "Colour of first must be empty or a colour";
  QTest::newRow("into the floor") << "position.y"
                                  << "0.2"
                                  << "first would overlap floor by 0.3 m";
}

void TestEditorDocks::refusesBadValues() {
  QFETCH(QString, field);
  QFETCH(QString, typed);
  QFETCH(QString, message);
  document().setSelection({{ObjectKind::Ball, 0}});
  const carom::Scene before = document().scene();
  const QString shownBefore = this->field(field)->text();
  type(field, typed);
  QVERIFY(document().scene() == before);
  QCOMPARE(document().undoStack()->count(), 0);
  QVERIFY2(properties().message().contains(message), qPrintable(properties().message()));
  QVERIFY2(statusMessage(*window_).contains(message), qPrintable(statusMessage(*window_)));
  QCOMPARE(this->field(field)->text(), shownBefore);  // the field shows the scene's value again
  // The next good edit clears the message.
  type("mass", "2");
  QCOMPARE(document().scene().balls[0].mass, 2.0);
  QVERIFY(properties().message().isEmpty());
}

void TestEditorDocks::editsEverySelectedObject() {
  carom::Scene edited = document().scene();
  carom::Ball second = edited.balls[0];
  second.position = Vec3(2, 1, 0);
  second.radius = 1.0;
  second.name = "second";
  edited.balls.push_back(second);
  QVERIFY(carom::testing::applyEdit(document(), edited, "add").isEmpty());
  document().setSelection({{ObjectKind::Ball, 0}, {ObjectKind::Ball, 1}});
  QVERIFY2(properties().heading().contains("2 selected"), qPrintable(properties().heading()));
  // Values the balls share show; those they do not are blank, marked "mixed".
  QCOMPARE(field("mass")->text(), QString("1"));
  QCOMPARE(field("ballRadius")->text(), QString());
  QCOMPARE(field("ballRadius")->placeholderText(), QString("mixed"));
  QCOMPARE(field("position.z")->text(), QString("0"));
  type("ballRadius", "0.4");
  QCOMPARE(document().scene().balls[0].radius, 0.4);
  QCOMPARE(document().scene().balls[1].radius, 0.4);
  QCOMPARE(document().undoStack()->count(), 2);  // the add and one edit for both
  // One component of a vector, for both: their x stays their own.
  type("velocity.y", "3");
  QCOMPARE(document().scene().balls[0].velocity, Vec3(0, 3, 0));
  QCOMPARE(document().scene().balls[1].velocity, Vec3(0, 3, 0));
  QCOMPARE(document().scene().balls[1].position.x(), 2.0);
}

// Every field of a box typed in, each one command that undoes; a box not turned shows empty
// rotation fields, and emptying the degrees takes the turn away.
void TestEditorDocks::editsABox() {
  addBox();
  document().setSelection({{ObjectKind::Box, 0}});
  QCOMPARE(properties().heading(), QString("Box 0"));
  QVERIFY(field("center.x")->isVisible() && field("halfExtents.z")->isVisible());
  QVERIFY(!field("position.x")->isVisible() && !field("point.x")->isVisible());
  QCOMPARE(field("center.y")->text(), QString("0.5"));
  QCOMPARE(field("halfExtents.x")->text(), QString("0.5"));
  QCOMPARE(field("rotationDegrees")->text(), QString());
  QCOMPARE(field("rotationDegrees")->placeholderText(), QString("none"));
  QCOMPARE(field("rotationAxis.y")->placeholderText(), QString("1"));
  QVERIFY(unitShown("m") && unitShown("°") && unitShown("(any length)"));

  const int before = document().undoStack()->count();
  type("name", "crate");
  type("center.z", "-1.5");
  type("halfExtents.y", "0.25");
  type("rotationDegrees", "30");
  type("rotationAxis.x", "1");
  type("restitution", "0.4");
  type("color", "#204080");
  const carom::Box& box = document().scene().boxes[0];
  QCOMPARE(box.name, std::string("crate"));
  QCOMPARE(box.center, Vec3(2, 0.5, -1.5));
  QCOMPARE(box.halfExtents, Vec3(0.5, 0.25, 0.5));
  QVERIFY(box.rotation == (carom::Rotation{Vec3(1, 1, 0), 30}));
  QCOMPARE(box.restitution, std::optional(0.4));
  QCOMPARE(box.color, std::string("#204080"));
  QCOMPARE(document().undoStack()->count(), before + 7);
  QCOMPARE(document().undoStack()->text(before + 2), QString("Resize Box"));
  QCOMPARE(document().undoStack()->text(before + 3), QString("Turn Box"));
  QCOMPARE(properties().heading(), QString("Box: crate"));
  QCOMPARE(field("rotationAxis.x")->text(), QString("1"));
  // Emptied degrees: not turned at all.
  type("rotationDegrees", "");
  QVERIFY(!document().scene().boxes[0].rotation);
  QCOMPARE(field("rotationAxis.x")->text(), QString());
  // Undo walks back through the turn, one field at a time.
  document().undoStack()->undo();
  QVERIFY(document().scene().boxes[0].rotation == (carom::Rotation{Vec3(1, 1, 0), 30}));
  QCOMPARE(field("rotationDegrees")->text(), QString("30"));
  for (int i = 0; i < 4; ++i) document().undoStack()->undo();
  QCOMPARE(document().scene().boxes[0].halfExtents, Vec3(0.5, 0.25, 0.5));
  QVERIFY(!document().scene().boxes[0].rotation);
  document().undoStack()->undo();
  QCOMPARE(field("halfExtents.y")->text(), QString("0.5"));
  document().undoStack()->redo();
  QCOMPARE(field("halfExtents.y")->text(), QString("0.25"));
  // The ball is untouched throughout.
  QCOMPARE(document().scene().balls[0].name, std::string("first"));
  // A turn about a zero axis is refused, whichever component makes it zero.
  type("rotationDegrees", "10");
  type("rotationAxis.y", "0");
  QVERIFY2(properties().message().contains("Rotation axis of crate must not be zero"),
           qPrintable(properties().message()));
  QVERIFY(document().scene().boxes[0].rotation == (carom::Rotation{Vec3::UnitY(), 10}));
}

void TestEditorDocks::refusesBadBoxValues_data() {
  QTest::addColumn<QString>("field");
  QTest::addColumn<QString>("typed");
  QTest::addColumn<QString>("message");
  QTest::newRow("zero size") << "halfExtents.x"
                             << "0"
                             << "Half extents x of Box 0 must be above zero";
  QTest::newRow("negative size") << "halfExtents.z"
                                 << "-0.5"
                                 << "Half extents z of Box 0 must be above zero";
  QTest::newRow("onto the ball") << "center.x"
                                 << "0.5"
                                 << "first would overlap Box 0 by";
  QTest::newRow("grown into the ball") << "halfExtents.x"
                                       << "1.8"
                                       << "first would overlap Box 0 by";
  QTest::newRow("not a number") << "rotationDegrees"
                                << "lots"
                                << "“lots” is not a number";
}

void TestEditorDocks::refusesBadBoxValues() {
  QFETCH(QString, field);
  QFETCH(QString, typed);
  QFETCH(QString, message);
  addBox();
  document().setSelection({{ObjectKind::Box, 0}});
  const carom::Scene before = document().scene();
  const int commands = document().undoStack()->count();
  const QString shownBefore = this->field(field)->text();
  type(field, typed);
  QVERIFY(document().scene() == before);
  QCOMPARE(document().undoStack()->count(), commands);
  QVERIFY2(properties().message().contains(message), qPrintable(properties().message()));
  QVERIFY2(statusMessage(*window_).contains(message), qPrintable(statusMessage(*window_)));
  QCOMPARE(this->field(field)->text(), shownBefore);
}

void TestEditorDocks::showsOnlyTheFieldsTheSelectionHas() {
  addCylinder();
  document().setSelection({{ObjectKind::Plane, 0}});
  QVERIFY(field("normal.y")->isVisible());
  QVERIFY(!field("ballRadius")->isVisible() && !field("axis.x")->isVisible());
  document().setSelection({{ObjectKind::Cylinder, 0}});
  QVERIFY(field("axis.y")->isVisible() && field("cylinderRadius")->isVisible());
  QCOMPARE(field("cylinderRadius")->text(), QString("0.3"));
  // A plane and a cylinder share their point, name, colour and restitution.
  document().setSelection({{ObjectKind::Plane, 1}, {ObjectKind::Cylinder, 0}});
  QVERIFY(field("point.x")->isVisible() && field("name")->isVisible());
  QVERIFY(!field("normal.x")->isVisible() && !field("axis.x")->isVisible());
  QVERIFY(!field("gravity.y")->isVisible());
  type("point.z", "-1");
  QCOMPARE(document().scene().planes[1].point.z(), -1.0);
  QCOMPARE(document().scene().cylinders[0].point.z(), -1.0);
  // Restitution left empty means the world's; typing sets the objects' own.
  QCOMPARE(field("restitution")->text(), QString());
  QVERIFY(field("restitution")->placeholderText().contains("1"));
  type("restitution", "0.5");
  QCOMPARE(document().scene().planes[1].restitution, std::optional(0.5));
  type("restitution", "");
  QCOMPARE(document().scene().planes[1].restitution, std::nullopt);
}

void TestEditorDocks::editsTheWorldWhenNothingIsSelected() {
  document().setSelection({});
  QVERIFY(properties().heading().contains("World"));
  QVERIFY(!field("name")->isVisible());
  type("gravity.y", "-3.5");
  QCOMPARE(document().scene().world.gravity, Vec3(0, -3.5, 0));
  // The toolbar shows the same world.
  QCOMPARE(window_->findChild<QDoubleSpinBox*>("gravityY")->value(), -3.5);
  type("timeStep", "0");
  QCOMPARE(properties().message(), QString("Time step must be above zero (got 0 s)"));
  QCOMPARE(document().scene().world.timeStep, 1.0 / 60.0);
  type("worldRestitution", "0.9");
  QCOMPARE(document().scene().world.restitution, 0.9);
  auto* method = properties().findChild<QComboBox*>("method");
  QVERIFY(method && method->isVisible());
  method->setCurrentIndex(int(carom::Method::Swept));
  QCOMPARE(document().scene().world.method, carom::Method::Swept);
  auto* integrator = properties().findChild<QComboBox*>("integrator");
  integrator->setCurrentIndex(int(carom::Integrator::VelocityVerlet));
  QCOMPARE(document().scene().world.integrator, carom::Integrator::VelocityVerlet);
  QCOMPARE(document().undoStack()->count(), 4);
  // A world edit from the toolbar shows in the dock.
  window_->findChild<QDoubleSpinBox*>("gravityX")->setValue(1.25);
  QCOMPARE(field("gravity.x")->text(), QString("1.25"));
}

void TestEditorDocks::picksAColour() {
  document().setSelection({{ObjectKind::Ball, 0}});
  QCOMPARE(field("color")->text(), QString("#ff0000"));
  auto* button = properties().findChild<QToolButton*>("pickColor");
  QVERIFY(button);
  carom::testing::ModalAnswerer<QColorDialog> answer([](QColorDialog* dialog) {
    QCOMPARE(dialog->currentColor(), QColor("#ff0000"));  // starts at the ball's colour
    dialog->setCurrentColor(QColor("#00ff80"));
    dialog->accept();
  });
  QTest::mouseClick(button, Qt::LeftButton);
  QTRY_VERIFY(answer.answered());
  QTRY_COMPARE(document().scene().balls[0].color, std::string("#00ff80"));
  QCOMPARE(field("color")->text(), QString("#00ff80"));
  QCOMPARE(document().undoStack()->count(), 1);
  // A colour typed in works as well; empty means the default.
  type("color", "");
  QCOMPARE(document().scene().balls[0].color, std::string());
}

void TestEditorDocks::turnsAPlaneByItsHandle() {
  chooseTool("toolSelect");
  document().setSelection({{ObjectKind::Plane, 1}});  // the wall at x = -4, facing +x
  const std::vector<carom::editor::EditorTools::Handle> handles = editorTools(*window_)->handles();
  QCOMPARE(handles.size(), std::size_t{1});
  const carom::editor::EditorTools::Handle* handle = &handles.front();
  QCOMPARE(handle->base, Vec3(-4, 0, 0));
  QVERIFY((handle->tip - handle->base).normalized().isApprox(Vec3::UnitX()));
  const QPoint tip = at(handle->tip);
  // Upwards on screen: the normal tilts up.
  drag(tip, tip + QPoint(0, -60), [&] { return document().scene().planes[1].normal.y() > 0.2; });
  const Vec3 normal = document().scene().planes[1].normal;
  QVERIFY2(normal.y() > 0.2 && normal.x() > 0.0,
           qPrintable(QString("%1 %2 %3").arg(normal.x()).arg(normal.y()).arg(normal.z())));
  QCOMPARE(normal.norm(), 1.0);
  QCOMPARE(document().scene().planes[1].point, Vec3(-4, 0, 0));  // turned, not moved
  QCOMPARE(document().undoStack()->count(), 1);
  QCOMPARE(document().undoStack()->text(0), QString("Turn Plane"));
  // The dock shows the new normal: six digits to read, all of them once the field is entered.
  QCOMPARE(field("normal.y")->text(), QString::number(normal.y(), 'g', 6));
  QTest::mouseClick(field("normal.y"), Qt::LeftButton);
  QCOMPARE(field("normal.y")->text().toDouble(), normal.y());
  document().undoStack()->undo();
  QCOMPARE(document().scene().planes[1].normal, Vec3(1, 0, 0));
}

void TestEditorDocks::turnsACylinderByItsHandle() {
  addCylinder();
  chooseTool("toolSelect");
  document().setSelection({{ObjectKind::Cylinder, 0}});
  const std::vector<carom::editor::EditorTools::Handle> handles = editorTools(*window_)->handles();
  QCOMPARE(handles.size(), std::size_t{1});
  const carom::editor::EditorTools::Handle* handle = &handles.front();
  QVERIFY((handle->tip - handle->base).normalized().isApprox(Vec3::UnitY()));
  const QPoint tip = at(handle->tip);
  drag(tip, tip + QPoint(80, 0),
       [&] { return std::abs(document().scene().cylinders[0].axis.y()) < 0.95; });
  const Vec3 axis = document().scene().cylinders[0].axis;
  QVERIFY2(std::abs(axis.y()) < 0.95, qPrintable(QString::number(axis.y())));
  QCOMPARE(document().undoStack()->count(), 2);
  QCOMPARE(document().undoStack()->text(1), QString("Turn Cylinder"));
}

namespace {

using Handle = carom::editor::EditorTools::Handle;
using HandleRole = carom::editor::EditorTools::HandleRole;

std::optional<Handle> findHandle(const std::vector<Handle>& handles, HandleRole role, int axis,
                                 int side = 1) {
  for (const Handle& handle : handles)
    if (handle.role == role && handle.axis == axis && handle.side == side) return handle;
  return std::nullopt;
}

}  // namespace

// A face's tip dragged out or in moves that face only: the opposite one stays where it was, so a
// box on the floor grown upwards still rests on it. Each drag is one command, and shows while it
// goes; a face dragged through the opposite one is refused.
void TestEditorDocks::resizesABoxByItsFaceHandles() {
  addBox();
  chooseTool("toolSelect");
  document().setSelection({{ObjectKind::Box, 0}});
  QCOMPARE(editorTools(*window_)->handles().size(), std::size_t{7});  // six faces and the turn
  const int commands = document().undoStack()->count();

  std::optional<Handle> face = findHandle(editorTools(*window_)->handles(), HandleRole::BoxFace, 0);
  QVERIFY(face);
  QCOMPARE(face->base, Vec3(2.5, 0.5, 0));
  drag(at(face->tip), at(face->tip + Vec3(1, 0, 0)),
       [&] { return document().scene().boxes[0].halfExtents.x() > 0.9; });
  const carom::Box wider = document().scene().boxes[0];
  QVERIFY2(std::abs(wider.halfExtents.x() - 1.0) < 0.05,
           qPrintable(QString::number(wider.halfExtents.x())));
  QVERIFY(std::abs(wider.center.x() - wider.halfExtents.x() - 1.5) < 1e-9);  // the -x face
  QCOMPARE(wider.halfExtents.y(), 0.5);
  QCOMPARE(wider.center.y(), 0.5);
  QCOMPARE(document().undoStack()->count(), commands + 1);
  QCOMPARE(document().undoStack()->undoText(), QString("Resize Box"));

  face = findHandle(editorTools(*window_)->handles(), HandleRole::BoxFace, 1);
  QVERIFY(face);
  drag(at(face->tip), at(face->tip + Vec3(0, 0.5, 0)),
       [&] { return document().scene().boxes[0].halfExtents.y() > 0.7; });
  const carom::Box taller = document().scene().boxes[0];
  QVERIFY2(std::abs(taller.halfExtents.y() - 0.75) < 0.05,
           qPrintable(QString::number(taller.halfExtents.y())));
  QVERIFY(std::abs(taller.center.y() - taller.halfExtents.y()) < 1e-9);  // still on the floor
  QCOMPARE(document().undoStack()->count(), commands + 2);

  // Through the opposite face: refused by the validation, the box stays at its last good size.
  face = findHandle(editorTools(*window_)->handles(), HandleRole::BoxFace, 2);
  QVERIFY(face);
  drag(at(face->tip), at(face->tip - Vec3(0, 0, 1.5)),
       [&] { return statusMessage(*window_).contains("Half extents z of Box 0"); });
  QVERIFY(document().scene().boxes[0].halfExtents.z() > 0.0);
  QVERIFY(std::abs(document().scene().boxes[0].center.z() -
                   document().scene().boxes[0].halfExtents.z() + 0.5) < 1e-9);

  QCOMPARE(document().undoStack()->count(), commands + 3);  // up to the last good size
  document().undoStack()->undo();
  QVERIFY(document().scene().boxes[0] == taller);
  document().undoStack()->undo();
  QVERIFY(document().scene().boxes[0] == wider);
  document().undoStack()->undo();
  QCOMPARE(document().scene().boxes[0].halfExtents, Vec3::Constant(0.5));
  document().undoStack()->redo();
  QVERIFY(document().scene().boxes[0] == wider);
}

// The -x face dragged outwards and the -z face inwards: each moves that face only, the +x and
// +z faces stay where they were.
void TestEditorDocks::resizesABoxFromItsNegativeFaces() {
  addBox();
  chooseTool("toolSelect");
  document().setSelection({{ObjectKind::Box, 0}});
  const int commands = document().undoStack()->count();
  std::optional<Handle> face =
      findHandle(editorTools(*window_)->handles(), HandleRole::BoxFace, 0, -1);
  QVERIFY(face);
  QCOMPARE(face->base, Vec3(1.5, 0.5, 0));
  QVERIFY((face->tip - face->base).normalized().isApprox(-Vec3::UnitX()));
  drag(at(face->tip), at(face->tip - Vec3(0.4, 0, 0)),
       [&] { return document().scene().boxes[0].halfExtents.x() > 0.65; });
  const carom::Box wider = document().scene().boxes[0];
  QVERIFY2(std::abs(wider.halfExtents.x() - 0.7) < 0.05,
           qPrintable(QString::number(wider.halfExtents.x())));
  QVERIFY(std::abs(wider.center.x() + wider.halfExtents.x() - 2.5) < 1e-9);  // the +x face
  QCOMPARE(wider.halfExtents.y(), 0.5);
  QCOMPARE(wider.halfExtents.z(), 0.5);
  QCOMPARE(document().undoStack()->count(), commands + 1);
  QCOMPARE(document().undoStack()->undoText(), QString("Resize Box"));

  face = findHandle(editorTools(*window_)->handles(), HandleRole::BoxFace, 2, -1);
  QVERIFY(face);
  QCOMPARE(face->base, Vec3(wider.center.x(), 0.5, -0.5));
  drag(at(face->tip), at(face->tip + Vec3(0, 0, 0.3)),
       [&] { return document().scene().boxes[0].halfExtents.z() < 0.4; });
  const carom::Box shallower = document().scene().boxes[0];
  QVERIFY2(std::abs(shallower.halfExtents.z() - 0.35) < 0.05,
           qPrintable(QString::number(shallower.halfExtents.z())));
  QVERIFY(std::abs(shallower.center.z() + shallower.halfExtents.z() - 0.5) < 1e-9);
  QCOMPARE(shallower.center.x(), wider.center.x());
  QCOMPARE(document().undoStack()->count(), commands + 2);
  document().undoStack()->undo();
  QVERIFY(document().scene().boxes[0] == wider);
  document().undoStack()->undo();
  QCOMPARE(document().scene().boxes[0].center, Vec3(2, 0.5, 0));
  QCOMPARE(document().scene().boxes[0].halfExtents, Vec3::Constant(0.5));
  document().undoStack()->redo();
  QVERIFY(document().scene().boxes[0] == wider);
}

// A cylinder's length, in metres, typed in; emptied, the cylinder is infinite again. Each is one
// command that undoes, and the point (the axis segment's middle) stays where it was.
void TestEditorDocks::editsACylindersLength() {
  addCylinder();
  document().setSelection({{ObjectKind::Cylinder, 0}});
  QLineEdit* length = field("cylinderLength");
  QVERIFY(length && length->isVisible());
  QCOMPARE(length->text(), QString());
  QCOMPARE(length->placeholderText(), QString("infinite"));
  QVERIFY2(length->toolTip().contains("empty: infinite"), qPrintable(length->toolTip()));
  QVERIFY(unitShown("m"));
  document().setSelection({{ObjectKind::Ball, 0}});
  QVERIFY(!length->isVisible());
  document().setSelection({{ObjectKind::Cylinder, 0}});

  const int commands = document().undoStack()->count();
  type("cylinderLength", "2");
  QCOMPARE(document().scene().cylinders[0].length, std::optional(2.0));
  QCOMPARE(document().scene().cylinders[0].point, Vec3(2, 1, -2));  // rising from the floor
  QCOMPARE(document().undoStack()->count(), commands + 1);
  QCOMPARE(document().undoStack()->undoText(), QString("Resize Cylinder"));
  QCOMPARE(length->text(), QString("2"));
  QVERIFY(properties().message().isEmpty());
  type("cylinderLength", "");
  QCOMPARE(document().scene().cylinders[0].length, std::nullopt);
  QCOMPARE(document().undoStack()->count(), commands + 2);
  QCOMPARE(length->placeholderText(), QString("infinite"));
  // Left as it is, it changes nothing.
  QTest::mouseClick(length, Qt::LeftButton);
  QTest::keyClick(length, Qt::Key_Return);
  QCOMPARE(document().undoStack()->count(), commands + 2);
  document().undoStack()->undo();
  QCOMPARE(document().scene().cylinders[0].length, std::optional(2.0));
  QCOMPARE(length->text(), QString("2"));
  document().undoStack()->undo();
  QCOMPARE(document().scene().cylinders[0].length, std::nullopt);
  document().undoStack()->redo();
  QCOMPARE(document().scene().cylinders[0].length, std::optional(2.0));
}

void TestEditorDocks::refusesBadLengths_data() {
  QTest::addColumn<QString>("typed");
  QTest::addColumn<QString>("message");
  QTest::newRow("negative") << "-1"
                            << "Length of Cylinder 0 must be above zero (got -1 m)";
  QTest::newRow("zero") << "0"
                        << "Length of Cylinder 0 must be above zero (got 0 m)";
  QTest::newRow("not a number") << "long"
                                << "“long” is not a number";
  QTest::newRow("infinity") << "inf"
                            << "Length of Cylinder 0 must be a finite number";
  QTest::newRow("grown into the ball") << "4"
                                       << "first would overlap Cylinder 0 by";
  QTest::newRow("made infinite through the ball") << ""
                                                  << "first would overlap Cylinder 0 by";
}

// A capped cylinder lying along x beside the ball: each bad length is refused with a message
// and leaves the scene, the undo stack and the field as they were.
void TestEditorDocks::refusesBadLengths() {
  QFETCH(QString, typed);
  QFETCH(QString, message);
  addCappedCylinder(Vec3(2, 0.5, 0), Vec3::UnitX(), 1.0);
  document().setSelection({{ObjectKind::Cylinder, 0}});
  const carom::Scene before = document().scene();
  const int commands = document().undoStack()->count();
  type("cylinderLength", typed);
  QVERIFY(document().scene() == before);
  QCOMPARE(document().undoStack()->count(), commands);
  QVERIFY2(properties().message().contains(message), qPrintable(properties().message()));
  QVERIFY2(statusMessage(*window_).contains(message), qPrintable(statusMessage(*window_)));
  QCOMPARE(field("cylinderLength")->text(), QString("1"));
}

// Several cylinders of different lengths show an empty field marked "mixed": left empty it
// changes none of them; typed into and emptied, it makes them all infinite; a number gives them
// all that length.
void TestEditorDocks::editsTheLengthOfSeveralCylinders() {
  addCappedCylinder(Vec3(2, 0.5, -2), Vec3::UnitY(), 1.0);
  addCappedCylinder(Vec3(-2, 1, -2), Vec3::UnitY(), 2.0);
  const Selection both{{ObjectKind::Cylinder, 0}, {ObjectKind::Cylinder, 1}};
  document().setSelection(both);
  QLineEdit* length = field("cylinderLength");
  QCOMPARE(length->text(), QString());
  QCOMPARE(length->placeholderText(), QString("mixed"));
  const carom::Scene before = document().scene();
  const int commands = document().undoStack()->count();
  type("cylinderLength", "");  // cleared while already empty: left as it was
  QVERIFY(document().scene() == before);
  QCOMPARE(document().undoStack()->count(), commands);

  QTest::mouseClick(length, Qt::LeftButton);
  QTest::keyClicks(length, "3");
  QTest::keyClick(length, Qt::Key_Backspace);
  QCOMPARE(length->placeholderText(), QString("infinite"));  // what Enter now does
  QTest::keyClick(length, Qt::Key_Return);
  QCOMPARE(document().scene().cylinders[0].length, std::nullopt);
  QCOMPARE(document().scene().cylinders[1].length, std::nullopt);
  QCOMPARE(document().undoStack()->count(), commands + 1);
  document().undoStack()->undo();
  QVERIFY(document().scene() == before);
  QCOMPARE(length->placeholderText(), QString("mixed"));

  type("cylinderLength", "1.5");
  QCOMPARE(document().scene().cylinders[0].length, std::optional(1.5));
  QCOMPARE(document().scene().cylinders[1].length, std::optional(1.5));
  QCOMPARE(document().scene().cylinders[1].point, Vec3(-2, 0.75, -2));  // still on the floor
  QCOMPARE(length->text(), QString("1.5"));
  // With an infinite one among them the lengths differ again.
  addCylinder();
  document().setSelection({{ObjectKind::Cylinder, 0}, {ObjectKind::Cylinder, 2}});
  QCOMPARE(length->placeholderText(), QString("mixed"));
}

// A capped cylinder shows a handle at each end and, beyond the upper one, the one that turns
// it. An end's tip dragged along the axis moves that end only; each drag is one command, an axis
// key held changes nothing, and an end dragged through the other is refused once, keeping the
// last good length.
void TestEditorDocks::resizesACappedCylinderByItsEnds() {
  addCappedCylinder(Vec3(2, 0.5, -2), Vec3::UnitY(), 1.0);  // from the floor up to y = 1
  chooseTool("toolSelect");
  document().setSelection({{ObjectKind::Cylinder, 0}});
  const std::vector<Handle> handles = editorTools(*window_)->handles();
  QCOMPARE(handles.size(), std::size_t{3});
  std::optional<Handle> top = findHandle(handles, HandleRole::CylinderEnd, 0, 1);
  const std::optional<Handle> bottom = findHandle(handles, HandleRole::CylinderEnd, 0, -1);
  const std::optional<Handle> turn = findHandle(handles, HandleRole::Direction, 0);
  QVERIFY(top && bottom && turn);
  QCOMPARE(top->base, Vec3(2, 1, -2));
  QCOMPARE(bottom->base, Vec3(2, 0, -2));
  QVERIFY((bottom->tip - bottom->base).normalized().isApprox(-Vec3::UnitY()));
  QCOMPARE(turn->base, top->tip);
  const int commands = document().undoStack()->count();

  drag(at(top->tip), at(top->tip + Vec3(0, 0.5, 0)),
       [&] { return document().scene().cylinders[0].length.value_or(0) > 1.45; });
  const carom::Cylinder longer = document().scene().cylinders[0];
  QVERIFY2(std::abs(*longer.length - 1.5) < 0.05, qPrintable(QString::number(*longer.length)));
  QVERIFY(std::abs(longer.point.y() - 0.5 * *longer.length) < 1e-9);  // still on the floor
  QCOMPARE(longer.point.x(), 2.0);
  QCOMPARE(longer.point.z(), -2.0);
  QCOMPARE(longer.axis, Vec3::UnitY());
  QCOMPARE(document().undoStack()->count(), commands + 1);
  QCOMPARE(document().undoStack()->undoText(), QString("Resize Cylinder"));
  QCOMPARE(field("cylinderLength")->text(), carom::editor::formatShortNumber(*longer.length));
  document().undoStack()->undo();
  QCOMPARE(document().scene().cylinders[0].length, std::optional(1.0));
  QCOMPARE(document().scene().cylinders[0].point, Vec3(2, 0.5, -2));
  document().undoStack()->redo();
  QVERIFY(document().scene().cylinders[0] == longer);

  // The lower end raised, with X held: the upper end stays.
  const std::optional<Handle> lower =
      findHandle(editorTools(*window_)->handles(), HandleRole::CylinderEnd, 0, -1);
  QVERIFY(lower);
  const QPoint from = at(lower->tip), to = at(lower->tip + Vec3(0, 0.4, 0));
  QTest::mousePress(&view(), Qt::LeftButton, Qt::NoModifier, from);
  QTest::keyPress(&view(), Qt::Key_X);
  for (int i = 1; i <= 10; ++i) QTest::mouseMove(&view(), from + (to - from) * i / 10);
  QTRY_VERIFY(document().scene().cylinders[0].length.value_or(0) < *longer.length - 0.35);
  QTest::mouseRelease(&view(), Qt::LeftButton, Qt::NoModifier, to);
  QTest::keyRelease(&view(), Qt::Key_X);
  const carom::Cylinder raised = document().scene().cylinders[0];
  QVERIFY2(std::abs(*raised.length - (*longer.length - 0.4)) < 0.05,
           qPrintable(QString::number(*raised.length)));
  QVERIFY(std::abs(raised.point.y() + 0.5 * *raised.length - *longer.length) < 1e-9);
  QCOMPARE(raised.point.x(), 2.0);
  QCOMPARE(raised.point.z(), -2.0);
  QCOMPARE(document().undoStack()->count(), commands + 2);

  // The upper end pulled down through the lower one: refused once, at the last good length.
  int refusals = 0;
  connect(editorTools(*window_), &carom::editor::EditorTools::refused, this, [&] { ++refusals; });
  top = findHandle(editorTools(*window_)->handles(), HandleRole::CylinderEnd, 0, 1);
  QVERIFY(top);
  drag(at(top->tip), at(top->tip - Vec3(0, 1.6, 0)),
       [&] { return statusMessage(*window_).contains("Length of Cylinder 0 must be above zero"); });
  QCOMPARE(refusals, 1);
  const carom::Cylinder shortest = document().scene().cylinders[0];
  QVERIFY(*shortest.length > 0.0 && *shortest.length < *raised.length);
  const double lowerEnd = raised.point.y() - 0.5 * *raised.length;
  QVERIFY(std::abs(shortest.point.y() - 0.5 * *shortest.length - lowerEnd) < 1e-9);
  QCOMPARE(document().undoStack()->count(), commands + 3);
  document().undoStack()->undo();
  QVERIFY(document().scene().cylinders[0] == raised);
}

// The turn handle's tip carried round the box's centre turns it about its up axis by the angle
// swept, in one command.
void TestEditorDocks::turnsABoxByItsHandle() {
  addBox();
  chooseTool("toolSelect");
  document().setSelection({{ObjectKind::Box, 0}});
  const int commands = document().undoStack()->count();
  const std::optional<Handle> turn =
      findHandle(editorTools(*window_)->handles(), HandleRole::BoxTurn, 1);
  QVERIFY(turn);
  QCOMPARE(turn->base, Vec3(2, 1, 0));
  // 30 degrees anticlockwise seen from above, in steps along the arc.
  const Vec3 top(2, 1, 0);
  const auto turnedTip = [&](double degrees) -> Vec3 {
    return top +
           Eigen::AngleAxisd(degrees * std::numbers::pi / 180, Vec3::UnitY()) * (turn->tip - top);
  };
  QTest::mousePress(&view(), Qt::LeftButton, Qt::NoModifier, at(turn->tip));
  for (int step = 1; step <= 10; ++step) QTest::mouseMove(&view(), at(turnedTip(3.0 * step)));
  QTRY_VERIFY(document().scene().boxes[0].rotation &&
              document().scene().boxes[0].rotation->degrees > 28);
  QTest::mouseRelease(&view(), Qt::LeftButton, Qt::NoModifier, at(turnedTip(30)));
  const carom::Box& box = document().scene().boxes[0];
  QVERIFY(box.rotation);
  QCOMPARE(box.rotation->axis, Vec3::UnitY());
  QVERIFY2(std::abs(box.rotation->degrees - 30) < 1.5,
           qPrintable(QString::number(box.rotation->degrees)));
  QCOMPARE(box.center, Vec3(2, 0.5, 0));
  QCOMPARE(box.halfExtents, Vec3::Constant(0.5));
  QCOMPARE(document().undoStack()->count(), commands + 1);
  QCOMPARE(document().undoStack()->undoText(), QString("Turn Box"));
  // The properties dock shows the turn as it stands.
  QCOMPARE(field("rotationDegrees")->text(),
           carom::editor::formatShortNumber(box.rotation->degrees));
  document().undoStack()->undo();
  QVERIFY(!document().scene().boxes[0].rotation);

  // A box tilted about x turns about its own tilted up axis: that axis stays, the others turn.
  carom::Scene tilted = document().scene();
  tilted.boxes[0].center.y() = 1.0;
  tilted.boxes[0].rotation = carom::Rotation{Vec3::UnitX(), 20};
  QVERIFY(carom::testing::applyEdit(document(), tilted, "Tilt").isEmpty());
  const carom::BoxShape before = carom::boxShape(document().scene().boxes[0]);
  const std::optional<Handle> tiltedTurn =
      findHandle(editorTools(*window_)->handles(), HandleRole::BoxTurn, 1);
  QVERIFY(tiltedTurn);
  const Vec3 centre = document().scene().boxes[0].center;
  const auto aroundUp = [&](double degrees) -> Vec3 {
    return centre + Eigen::AngleAxisd(degrees * std::numbers::pi / 180, before.axes.col(1)) *
                        (tiltedTurn->tip - centre);
  };
  QTest::mousePress(&view(), Qt::LeftButton, Qt::NoModifier, at(tiltedTurn->tip));
  for (int step = 1; step <= 10; ++step) QTest::mouseMove(&view(), at(aroundUp(-4.0 * step)));
  QTRY_VERIFY(carom::boxShape(document().scene().boxes[0]).axes.col(0).dot(before.axes.col(0)) <
              std::cos(35 * std::numbers::pi / 180));
  QTest::mouseRelease(&view(), Qt::LeftButton, Qt::NoModifier, at(aroundUp(-40)));
  const carom::BoxShape after = carom::boxShape(document().scene().boxes[0]);
  QVERIFY(after.axes.col(1).isApprox(before.axes.col(1), 1e-9));
  const double swept = std::acos(std::clamp(after.axes.col(0).dot(before.axes.col(0)), -1.0, 1.0));
  QVERIFY2(std::abs(swept * 180 / std::numbers::pi - 40) < 2,
           qPrintable(QString::number(swept * 180 / std::numbers::pi)));
  QCOMPARE(document().scene().boxes[0].center, centre);
}

void TestEditorDocks::typesANormal() {
  document().setSelection({{ObjectKind::Plane, 2}});  // the wall at x = 4, facing -x
  type("normal.x", "0");
  QVERIFY2(properties().message().contains("Normal of Plane 2 must not be zero"),
           qPrintable(properties().message()));
  QCOMPARE(document().scene().planes[2].normal, Vec3(-1, 0, 0));
  type("normal.z", "-1");
  QCOMPARE(document().scene().planes[2].normal, Vec3(-1, 0, -1));  // any length will do
  QCOMPARE(document().undoStack()->count(), 1);
}

void TestEditorDocks::saveTakesTheValueBeingTyped() {
  QTemporaryDir folder;
  const QString file = folder.filePath("typed.carom");
  QVERIFY(carom::io::saveSceneFile(carom::testing::floorScene(), file, nullptr));
  QVERIFY(window_->openFile(file, false));
  document().setSelection({{ObjectKind::Ball, 0}});
  QLineEdit* mass = field("mass");
  QTest::mouseClick(mass, Qt::LeftButton);
  QTest::keyClick(mass, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClicks(mass, "3");
  QTest::keyClick(mass, Qt::Key_S, Qt::ControlModifier);  // no Enter first
  const carom::io::SceneLoadResult saved = carom::io::loadSceneFile(file);
  QVERIFY(saved.scene);
  QCOMPARE(saved.scene->balls[0].mass, 3.0);
  QVERIFY(!document().isModified());
}

void TestEditorDocks::toolbarRefusesBadValues_data() {
  QTest::addColumn<QString>("box");
  QTest::addColumn<QString>("typed");
  QTest::addColumn<QString>("message");
  QTest::newRow("letters") << "timeStep"
                           << "fast"
                           << "Time step: “fast” is not a number";
  QTest::newRow("empty") << "gravityY"
                         << ""
                         << "Gravity y: “” is not a number";
  QTest::newRow("nan") << "gravityX"
                       << "nan"
                       << "Gravity x: must be finite (got nan)";
  QTest::newRow("inf") << "timeStep"
                       << "inf"
                       << "Time step: must be finite (got inf)";
  QTest::newRow("overflow") << "gravityZ"
                            << "1e400"
                            << "Gravity z: “1e400” is out of range";
  QTest::newRow("too large") << "timeStep"
                             << "2e6"
                             << "Time step: must be between 1e-12 and 1e+06 (got 2e+06)";
  QTest::newRow("zero") << "timeStep"
                        << "0"
                        << "Time step: must be between 1e-12 and 1e+06 (got 0)";
  QTest::newRow("absurd gravity") << "gravityY"
                                  << "-1e13"
                                  << "Gravity y: must be between -1e+12 and 1e+12 (got -1e+13)";
  QTest::newRow("speed") << "speed"
                         << "1000"
                         << "Speed: must be between 0.01 and 100 (got 1000)";
}

// Where QDoubleSpinBox would drop the keystrokes or clamp, the toolbar says why and keeps its
// value.
void TestEditorDocks::toolbarRefusesBadValues() {
  QFETCH(QString, box);
  QFETCH(QString, typed);
  QFETCH(QString, message);
  auto* spin = window_->findChild<QDoubleSpinBox*>(box);
  QVERIFY(spin);
  const double before = spin->value();
  const QString shownBefore = spin->text();
  const carom::Scene scene = document().scene();
  QTest::mouseClick(spin, Qt::LeftButton);
  QTest::keyClick(spin, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClick(spin, Qt::Key_Backspace);
  QTest::keyClicks(spin, typed);
  QCOMPARE(spin->text(), typed);  // every keystroke reached the box
  QTest::keyClick(spin, Qt::Key_Return);
  QVERIFY2(statusMessage(*window_).startsWith(message), qPrintable(statusMessage(*window_)));
  QCOMPARE(spin->value(), before);
  QCOMPARE(spin->text(), shownBefore);
  QVERIFY(document().scene() == scene);
  QCOMPARE(document().undoStack()->count(), 0);
  // A good value typed next is taken.
  QTest::keyClick(spin, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClicks(spin, "0.02");
  QTest::keyClick(spin, Qt::Key_Return);
  QCOMPARE(spin->value(), 0.02);
  if (box == "timeStep") QCOMPARE(document().scene().world.timeStep, 0.02);
}

void TestEditorDocks::toolbarShowsShortButKeepsExactValues() {
  auto* step = window_->findChild<QDoubleSpinBox*>("timeStep");
  QCOMPARE(step->text(), QString("0.0166667"));
  QTest::mouseClick(step, Qt::LeftButton);
  QTest::keyClick(step, Qt::Key_Return);  // entered without a change: 1/60 is not rounded
  QCOMPARE(document().scene().world.timeStep, 1.0 / 60.0);
  QCOMPARE(document().undoStack()->count(), 0);
  QTest::keyClick(step, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClicks(step, "0.000123456789");  // typed digits are all taken
  QTest::keyClick(step, Qt::Key_Return);
  QCOMPARE(document().scene().world.timeStep, 0.000123456789);
  QCOMPARE(step->text(), QString("0.000123457"));
}

// Issue 34: a field narrower than its text scrolled to its end, so that -0.642395 read
// "642395". However narrow, a number field at rest shows its value's start (the sign and the
// leading digits), also once a value typed in is left; so do the toolbar's boxes.
void TestEditorDocks::narrowFieldsShowTheStartOfTheirValues() {
  // The position under the left end of a field's text area: 0 when its text shows from the
  // start.
  const auto firstShown = [](QLineEdit* edit) {
    const QRect inner = edit->contentsRect();
    return edit->cursorPositionAt(QPoint(inner.left() + 1, inner.center().y()));
  };
  carom::Scene edited = document().scene();
  edited.balls[0].velocity = Vec3(-0.642395, -1.59698, -2.71828);
  QVERIFY(carom::testing::applyEdit(document(), edited, "set").isEmpty());
  document().setSelection({{ObjectKind::Ball, 0}});
  window_->resizeDocks({window_->propertiesDock()}, {150}, Qt::Horizontal);
  for (const char* name : {"velocity.x", "velocity.y", "velocity.z"}) {
    QLineEdit* edit = field(name);
    // Too narrow for the whole value, as it is to be.
    QTRY_VERIFY2(edit->fontMetrics().horizontalAdvance(edit->text()) > edit->contentsRect().width(),
                 qPrintable(QString("%1: %2 pixels").arg(name).arg(edit->width())));
    QVERIFY2(edit->text().startsWith('-'), qPrintable(edit->text()));
    QTRY_COMPARE(firstShown(edit), 0);
  }
  type("velocity.x", "-0.6423951");
  QCOMPARE(document().scene().balls[0].velocity.x(), -0.6423951);
  QTest::mouseClick(field("mass"), Qt::LeftButton);
  QCOMPARE(field("velocity.x")->text(), QString("-0.642395"));
  QTRY_COMPARE(firstShown(field("velocity.x")), 0);
  // The toolbar's gravity x, made as narrow, typed in and left.
  auto* gravityX = window_->findChild<QDoubleSpinBox*>("gravityX");
  QVERIFY(gravityX);
  auto* gravityText = gravityX->findChild<QLineEdit*>();
  gravityX->setFixedWidth(gravityX->minimumSizeHint().width());
  QTest::mouseClick(gravityText, Qt::LeftButton);
  QTest::keyClick(gravityText, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClicks(gravityText, "-1.234567");
  QTest::keyClick(gravityText, Qt::Key_Return);
  QCOMPARE(document().scene().world.gravity.x(), -1.234567);
  QTest::mouseClick(field("mass"), Qt::LeftButton);
  QTRY_VERIFY(!gravityX->hasFocus());
  QCOMPARE(gravityX->text(), QString("-1.23457"));
  QVERIFY2(gravityText->fontMetrics().horizontalAdvance(gravityText->text()) >
               gravityText->contentsRect().width(),
           qPrintable(QString::number(gravityText->width())));
  QTRY_COMPARE(firstShown(gravityText), 0);
}

// As the toolbar does: six significant digits to read; every digit while editing and in the
// tooltip.
void TestEditorDocks::fieldsShowSixDigitsAndEditAllOfThem() {
  carom::Scene edited = document().scene();
  edited.balls[0].position.x() = 0.1 + 0.2;  // 0.30000000000000004
  edited.balls[0].mass = 2.0 / 3.0;
  QVERIFY(carom::testing::applyEdit(document(), edited, "set").isEmpty());
  document().setSelection({{ObjectKind::Ball, 0}});
  QLineEdit* x = field("position.x");
  QLineEdit* mass = field("mass");
  QCOMPARE(x->text(), QString("0.3"));
  QCOMPARE(mass->text(), QString("0.666667"));
  QCOMPARE(x->toolTip(), QString("Position x: 0.30000000000000004"));
  QCOMPARE(mass->toolTip(), QString("Mass: 0.6666666666666666"));
  QTest::mouseClick(mass, Qt::LeftButton);
  QCOMPARE(mass->text(), QString("0.6666666666666666"));
  QCOMPARE(x->text(), QString("0.3"));  // only the field being edited shows everything
  // Leaving it shows six digits again; a value typed in is shown the same way.
  QTest::mouseClick(x, Qt::LeftButton);
  QCOMPARE(mass->text(), QString("0.666667"));
  QCOMPARE(x->text(), QString("0.30000000000000004"));
  type("ballRadius", "0.123456789");
  QCOMPARE(document().scene().balls[0].radius, 0.123456789);
  QCOMPARE(field("ballRadius")->text(), QString("0.123456789"));  // still being edited
  QTest::mouseClick(mass, Qt::LeftButton);
  QCOMPARE(field("ballRadius")->text(), QString("0.123457"));
  QCOMPARE(field("ballRadius")->toolTip(), QString("Radius: 0.123456789"));
  // Several objects that differ: empty, "mixed", and a tooltip with the name alone.
  carom::Scene two = document().scene();
  two.balls.push_back(two.balls[0]);
  two.balls[1].position = Vec3(2, 1, 0);
  QVERIFY(carom::testing::applyEdit(document(), two, "add").isEmpty());
  document().setSelection({{ObjectKind::Ball, 0}, {ObjectKind::Ball, 1}});
  QCOMPARE(x->text(), QString());
  QCOMPARE(x->placeholderText(), QString("mixed"));
  QCOMPARE(x->toolTip(), QString("Position x"));
}

// Entering a field and leaving it, by Enter or by the focus going elsewhere, never rounds the
// stored value to what was shown.
void TestEditorDocks::fieldsLeftAsTheyWereKeepExactValues() {
  carom::Scene edited = document().scene();
  edited.balls[0].velocity = Vec3(0.1, 1.0 / 3.0, 0);
  QVERIFY(carom::testing::applyEdit(document(), edited, "set").isEmpty());
  const int commands = document().undoStack()->count();
  document().setSelection({{ObjectKind::Ball, 0}});
  for (const char* name : {"velocity.x", "velocity.y"}) {
    QTest::mouseClick(field(name), Qt::LeftButton);
    QTest::keyClick(field(name), Qt::Key_Return);
    QTest::keyClick(field(name), Qt::Key_Tab);
  }
  QCOMPARE(document().scene().balls[0].velocity, Vec3(0.1, 1.0 / 3.0, 0));
  // The world's time step of 1/60, shown as 0.0166667.
  document().setSelection({});
  QLineEdit* step = field("timeStep");
  QCOMPARE(step->text(), QString("0.0166667"));
  QTest::mouseClick(step, Qt::LeftButton);
  QCOMPARE(step->text(), QString("0.016666666666666666"));
  QTest::mouseClick(field("worldRestitution"), Qt::LeftButton);  // left without Enter
  QCOMPARE(step->text(), QString("0.0166667"));
  QCOMPARE(document().scene().world.timeStep, 1.0 / 60.0);
  QCOMPARE(document().undoStack()->count(), commands);
  // The full text typed back unchanged is the same value: still no command.
  type("timeStep", "0.016666666666666666");
  QCOMPARE(document().scene().world.timeStep, 1.0 / 60.0);
  QCOMPARE(document().undoStack()->count(), commands);
}

// A refusal was the last row of the dock's scroll area: with a ball's rows at the default size it
// lay below Mass, out of sight, and in another layout it squashed the rows into slivers. It now
// stays under the scroll area, in sight, and the rows keep their height.
void TestEditorDocks::aRefusalLeavesTheRowsReadable() {
  document().setSelection({{ObjectKind::Ball, 0}});
  type("position.y", "0.2");  // into the floor
  QVERIFY(!properties().message().isEmpty());
  auto* message = properties().findChild<QLabel*>("propertiesMessage");
  QTRY_VERIFY(message->isVisible() && message->height() > 0);
  const auto squashed = [this]() -> QString {
    for (QLineEdit* edit : properties().findChildren<QLineEdit*>())
      if (edit->isVisible() && edit->height() < edit->minimumSizeHint().height())
        return QString("%1: %2 pixels high, at least %3")
            .arg(edit->objectName())
            .arg(edit->height())
            .arg(edit->minimumSizeHint().height());
    return QString();
  };
  QTest::qWait(100);  // the layout after the message
  QVERIFY2(squashed().isEmpty(), qPrintable(squashed()));
  // The message stays in sight whatever the rows' scrolling.
  QVERIFY(message->visibleRegion().boundingRect().height() == message->height());
}

void TestEditorDocks::refusalGoesOnceTheFieldIsValidAgain() {
  document().setSelection({{ObjectKind::Ball, 0}});
  type("mass", "heavy");
  QVERIFY(properties().message().contains("“heavy” is not a number"));
  // The value it had, typed again: nothing to change, and nothing wrong any more.
  type("mass", "1");
  QVERIFY2(properties().message().isEmpty(), qPrintable(properties().message()));
  QCOMPARE(document().undoStack()->count(), 0);
  // A refusal by the validation, then the field left with its (valid) value as it is.
  type("ballRadius", "-1");
  QVERIFY(properties().message().contains("Radius of first must be above zero"));
  QCOMPARE(field("ballRadius")->text(), QString("0.5"));
  QTest::keyClick(field("ballRadius"), Qt::Key_Return);
  QVERIFY2(properties().message().isEmpty(), qPrintable(properties().message()));
  // And an undo, which changes the scene, takes a refusal away too.
  type("ballRadius", "0.4");
  type("ballRadius", "-1");
  QVERIFY(!properties().message().isEmpty());
  document().undoStack()->undo();
  QVERIFY(properties().message().isEmpty());
  QCOMPARE(field("ballRadius")->text(), QString("0.5"));
}

// A name longer than the scene format allows, typed or pasted into the Name field, is refused
// by the validation with its message and changes nothing.
void TestEditorDocks::refusesNamesOverTheLimit() {
  document().setSelection({{ObjectKind::Ball, 0}});
  const carom::Scene before = document().scene();
  type("name", QString(257, 'n'));
  const QString typed = "Name of first must be at most 256 characters long (got 257)";
  QVERIFY2(properties().message().contains(typed), qPrintable(properties().message()));
  QVERIFY2(statusMessage(*window_).contains(typed), qPrintable(statusMessage(*window_)));
  QVERIFY(document().scene() == before);
  QCOMPARE(document().undoStack()->count(), 0);
  QCOMPARE(field("name")->text(), QString("first"));
  // Pasted: 30,000 characters in one go.
  QLineEdit* name = field("name");
  QApplication::clipboard()->setText(QString(30'000, 'p'));
  QTest::mouseClick(name, Qt::LeftButton);
  QTest::keyClick(name, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClick(name, Qt::Key_V, Qt::ControlModifier);
  QCOMPARE(name->text().size(), 30'000);
  QTest::keyClick(name, Qt::Key_Return);
  const QString pasted = "Name of first must be at most 256 characters long (got 30,000)";
  QVERIFY2(properties().message().contains(pasted), qPrintable(properties().message()));
  QVERIFY(document().scene() == before);
  QCOMPARE(document().undoStack()->count(), 0);
  QCOMPARE(name->text(), QString("first"));
  // At the limit it is taken.
  type("name", QString(256, 'n'));
  QCOMPARE(document().scene().balls[0].name, std::string(256, 'n'));
  QVERIFY(properties().message().isEmpty());
}

void TestEditorDocks::outlineRefusesNamesOverTheLimit() {
  const QModelIndex floor = outline().index(0, 0, outline().groupIndex(ObjectKind::Plane));
  clickRow(floor);
  const carom::Scene before = document().scene();
  startRenaming(floor);
  auto* editor = tree().viewport()->findChild<QLineEdit*>();
  QTRY_VERIFY(editor && editor->isVisible());
  QApplication::clipboard()->setText(QString(300, QChar(0x00e9)));
  QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClick(editor, Qt::Key_V, Qt::ControlModifier);
  QTest::keyClick(editor, Qt::Key_Return);
  // Named by the name it keeps.
  const QString refusal = "Name of floor must be at most 256 characters long (got 300)";
  QTRY_VERIFY2(statusMessage(*window_).contains(refusal), qPrintable(statusMessage(*window_)));
  QVERIFY(document().scene() == before);
  QCOMPARE(document().undoStack()->count(), 0);
  QCOMPARE(floor.data().toString(), QString("floor"));
}

// Names as long as the format allows, of wide letters, are shown elided: the Properties dock's
// heading fits the dock with no sideways scrolling, and the Ball story's legend and the outline
// take no more than a short label's room.
void TestEditorDocks::longNamesAreElided() {
  carom::Scene scene = carom::testing::floorScene();
  const QString ballName(256, 'W');
  scene.balls[0].name = ballName.toStdString();
  scene.planes[0].name.clear();
  for (int i = 0; i < 256; ++i) scene.planes[0].name += "\u00c9";
  window_->openScene(scene, {}, "long names");
  const QModelIndex ball = outline().index(0, 0, outline().groupIndex(ObjectKind::Ball));
  tree().expandAll();
  clickRow(ball);
  QCOMPARE(document().selection(), (Selection{{ObjectKind::Ball, 0}}));

  // The outline holds the whole name and elides it to its width.
  QCOMPARE(ball.data().toString(), ballName);
  QCOMPARE(tree().horizontalScrollBar()->maximum(), 0);

  // A short label is at most this wide, in average characters of the font it is shown in.
  const auto shortLabelWidth = [](const QFont& font) {
    return 40 * QFontMetrics(font).averageCharWidth();
  };
  auto* heading = properties().findChild<QLabel*>("propertiesHeading");
  QVERIFY(heading);
  QVERIFY2(heading->text().startsWith("Ball: WWW") && heading->text().contains("\u2026"),
           qPrintable(heading->text()));
  QVERIFY(heading->sizeHint().width() <= shortLabelWidth(heading->font()));
  auto* scroll = properties().findChild<QScrollArea*>();
  QTRY_VERIFY(scroll->widget()->width() <= scroll->viewport()->width());
  QVERIFY(!scroll->horizontalScrollBar()->isVisible());
  // The full name is in the Name field, whose width does not follow its text.
  QCOMPARE(field("name")->text(), ballName);
  QVERIFY(field("name")->sizeHint().width() <= shortLabelWidth(field("name")->font()));

  // The Ball story follows the ball under an elided name.
  auto* chart = ballStoryDock(*window_)->findChild<QChartView*>()->chart();
  const auto ballMarker = [chart]() -> QLegendMarker* {
    for (QLegendMarker* marker : chart->legend()->markers())
      if (marker->isVisible() && marker->label().startsWith("WWW")) return marker;
    return nullptr;
  };
  QTRY_VERIFY(ballMarker());
  const QString legend = ballMarker()->label();
  QVERIFY2(legend.contains("\u2026"), qPrintable(legend));
  QVERIFY(QFontMetrics(chart->legend()->font()).horizontalAdvance(legend) <=
          shortLabelWidth(chart->legend()->font()));

  // The plane too.
  clickRow(outline().index(0, 0, outline().groupIndex(ObjectKind::Plane)));
  QVERIFY2(heading->text().startsWith("Plane: \u00c9") && heading->text().contains("\u2026"),
           qPrintable(heading->text()));
  QVERIFY(heading->sizeHint().width() <= shortLabelWidth(heading->font()));
}

QTEST_MAIN(TestEditorDocks)
#include "test_editor_docks.moc"
