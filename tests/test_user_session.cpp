// Whole sessions as a user has them, through the real window: menus, clicks and keys under a real
// X server (Xvfb) with Mesa's OpenGL. Each bug found by using the window is reproduced here.

#include "sim/io/scene_file.h"
#include "tests/editor_fixture.h"
#include "tests/scene_helpers.h"
#include "ui/dialogs/accuracy_window.h"
#include "ui/editor/editor_tools.h"
#include "ui/editor/properties_dock.h"
#include "ui/editor/scene_recovery.h"
#include "ui/language.h"
#include "ui/render/render_scene.h"
#include "ui/run/run_session.h"
#include "ui/run/simulation_snapshot.h"

#include <QAction>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QSlider>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

using carom::Ball;
using carom::Scene;
using carom::Vec3;
using carom::editor::ObjectKind;
using carom::editor::SceneRecovery;
using carom::testing::DialogAnswerer;
using carom::testing::ModalAnswerer;

namespace {

// The menu bar's menu whose title, without its '&', is `title`.
QMenu* menuNamed(QMainWindow& window, const QString& title) {
  for (QAction* action : window.menuBar()->actions())
    if (action->menu() && action->text().remove('&') == title) return action->menu();
  return nullptr;
}

// The bundled magic room as the loader reads it.
Scene magicRoom() {
  return *carom::io::loadSceneFile(":/scenes/magic-room.json").scene;
}

// Every field of every object, compared one by one so that a failure names the object.
void compareObjects(const Scene& actual, const Scene& expected) {
  QCOMPARE(actual.balls.size(), expected.balls.size());
  QCOMPARE(actual.planes.size(), expected.planes.size());
  QCOMPARE(actual.cylinders.size(), expected.cylinders.size());
  QCOMPARE(actual.boxes.size(), expected.boxes.size());
  for (std::size_t i = 0; i < expected.balls.size(); ++i) {
    QCOMPARE(actual.balls[i].name, expected.balls[i].name);
    QCOMPARE(actual.balls[i].color, expected.balls[i].color);
    QVERIFY2(actual.balls[i] == expected.balls[i], expected.balls[i].name.c_str());
  }
  for (std::size_t i = 0; i < expected.planes.size(); ++i) {
    QCOMPARE(actual.planes[i].name, expected.planes[i].name);
    QCOMPARE(actual.planes[i].color, expected.planes[i].color);
    QVERIFY2(actual.planes[i] == expected.planes[i], expected.planes[i].name.c_str());
  }
  for (std::size_t i = 0; i < expected.cylinders.size(); ++i) {
    QCOMPARE(actual.cylinders[i].name, expected.cylinders[i].name);
    QCOMPARE(actual.cylinders[i].color, expected.cylinders[i].color);
    QCOMPARE(actual.cylinders[i].length, expected.cylinders[i].length);
    QVERIFY2(actual.cylinders[i] == expected.cylinders[i], expected.cylinders[i].name.c_str());
  }
  for (std::size_t i = 0; i < expected.boxes.size(); ++i) {
    QCOMPARE(actual.boxes[i].name, expected.boxes[i].name);
    QCOMPARE(actual.boxes[i].color, expected.boxes[i].color);
    QCOMPARE(actual.boxes[i].rotation.has_value(), expected.boxes[i].rotation.has_value());
    QVERIFY2(actual.boxes[i] == expected.boxes[i], qPrintable(QString("boxes[%1]").arg(i)));
  }
  QVERIFY(actual.world == expected.world);
}

using Handle = carom::editor::EditorTools::Handle;
using HandleRole = carom::editor::EditorTools::HandleRole;

std::optional<Handle> findHandle(const std::vector<Handle>& handles, HandleRole role, int axis,
                                 int side = 1) {
  for (const Handle& handle : handles)
    if (handle.role == role && handle.axis == axis && handle.side == side) return handle;
  return std::nullopt;
}

}  // namespace

class TestUserSession : public carom::testing::EditorFixture {
  Q_OBJECT

 private slots:
  void init();
  void cleanup() {
    window_.reset();
    carom::ui::installTranslation(*QCoreApplication::instance(), "en");  // as the next test expects
  }

  void deletingABallKeepsEveryOtherName();
  void deletingADuplicateKeepsTheOriginals();
  void objectsAddedAwayFromTheBallsAreDrawn();
  void backgroundClicksSelectNothing();
  void exampleAfterDiscardedRecoveryOpensUnmodified();
  void promptNamesTheSceneOfTheTitle();
  void openingAScenesFramesIt();
  void newGivesAFloorToBuildOn();
  void statusMessagesLeaveTheReadout();
  void openEditDeleteSaveReopen();
  void wholeSessionInEveryLanguage_data();
  void wholeSessionInEveryLanguage();
  void buildWithBoxesSaveReopen();
  void buildWithCappedCylindersSaveReopen();

 private:
  void openExample(const QString& title);
  // Clicks every point of a grid over the view where the picture shows only background.
  // Clicks every probe point with background all around it; counts them in backgroundClicks_.
  void clickTheBackground();
  void saveAsThroughTheDialog(const QString& file);
  void openThroughTheDialog(const QString& file);
  // Clicks into the properties dock's field `name`, replaces its text and presses Enter.
  void type(const QString& name, const QString& text);
  // Ctrl+Z, then Ctrl+Shift+Z: the scene is `before` in between and `after` at the end.
  void undoRedo(const Scene& before, const Scene& after);
  QTemporaryDir folder_;
  int backgroundClicks_ = 0;
};

void TestUserSession::init() {
  QDir(SceneRecovery::folder()).removeRecursively();
  openWindow();
}

// Examples > `title`, as a click on the menu entry does.
void TestUserSession::openExample(const QString& title) {
  QMenu* examples = menuNamed(*window_, "Examples");
  QVERIFY(examples);
  // The file's name or its title, whichever the menu shows ("newtons-cradle", "Newton's cradle").
  const auto letters = [](QString text) {
    text.remove(QRegularExpression("[^A-Za-z0-9]"));
    return text.toLower();
  };
  for (QAction* action : examples->actions()) {
    if (letters(action->text()) == letters(title)) {
      action->trigger();
      return;
    }
  }
  QFAIL(qPrintable("no example " + title));
}

void TestUserSession::saveAsThroughTheDialog(const QString& file) {
  ModalAnswerer<QFileDialog> answer([&](QFileDialog* dialog) {
    dialog->selectFile(file);
    QMetaObject::invokeMethod(dialog, "accept");
  });
  QTest::keyClick(window_.get(), Qt::Key_S, Qt::ControlModifier | Qt::ShiftModifier);
  QVERIFY(answer.answered());
}

void TestUserSession::openThroughTheDialog(const QString& file) {
  ModalAnswerer<QFileDialog> answer([&](QFileDialog* dialog) {
    dialog->selectFile(file);
    QMetaObject::invokeMethod(dialog, "accept");
  });
  QTest::keyClick(window_.get(), Qt::Key_O, Qt::ControlModifier);
  QVERIFY(answer.answered());
}

void TestUserSession::type(const QString& name, const QString& text) {
  auto* edit = window_->propertiesDock()->findChild<QLineEdit*>(name);
  QVERIFY2(edit && edit->isVisible(), qPrintable(name));
  QTest::mouseClick(edit, Qt::LeftButton);
  QTest::keyClick(edit, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClick(edit, Qt::Key_Backspace);
  QTest::keyClicks(edit, text);
  QTest::keyClick(edit, Qt::Key_Return);
}

void TestUserSession::undoRedo(const Scene& before, const Scene& after) {
  QVERIFY(document().scene() == after);
  QTest::keyClick(window_.get(), Qt::Key_Z, Qt::ControlModifier);
  QVERIFY(document().scene() == before);
  QTest::keyClick(window_.get(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
  QVERIFY(document().scene() == after);
}

// Examples > magic-room, click the red ball, Delete, Save As: every other object keeps its name
// and colour in the saved file (they were wiped).
void TestUserSession::deletingABallKeepsEveryOtherName() {
  openExample("magic-room");
  const Scene room = magicRoom();
  QVERIFY(document().scene() == room);
  QCOMPARE(room.balls[0].color, std::string("#e63946"));  // the red one
  QTRY_VERIFY(framesRendered(*window_) > 2);
  click(room.balls[0].position);
  QCOMPARE(document().selection(), (carom::editor::Selection{{ObjectKind::Ball, 0}}));
  QTest::keyClick(window_.get(), Qt::Key_Delete);

  const QString file = folder_.filePath("room.carom");
  saveAsThroughTheDialog(file);
  const carom::io::SceneLoadResult saved = carom::io::loadSceneFile(file);
  QVERIFY2(saved.scene, qPrintable(saved.error));
  Scene expected = room;
  expected.balls.erase(expected.balls.begin());
  compareObjects(*saved.scene, expected);
}

// Duplicating ball 9 and deleting the copy gave ten balls named "Ball 0…9" in default colours.
void TestUserSession::deletingADuplicateKeepsTheOriginals() {
  openExample("magic-room");
  const Scene room = magicRoom();
  QTRY_VERIFY(framesRendered(*window_) > 2);
  click(room.balls[9].position);
  QCOMPARE(document().selection(), (carom::editor::Selection{{ObjectKind::Ball, 9}}));
  QTest::keyClick(window_.get(), Qt::Key_D, Qt::ControlModifier);
  QCOMPARE(document().scene().balls.size(), room.balls.size() + 1);
  QCOMPARE(document().selection(), (carom::editor::Selection{{ObjectKind::Ball, 10}}));
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  compareObjects(document().scene(), room);
  // Undo twice is back at the start, redo twice at the same place again.
  QTest::keyClick(window_.get(), Qt::Key_Z, Qt::ControlModifier);
  QCOMPARE(document().scene().balls.size(), room.balls.size() + 1);
  QCOMPARE(document().scene().balls[10].name, room.balls[9].name);
  QTest::keyClick(window_.get(), Qt::Key_Z, Qt::ControlModifier);
  compareObjects(document().scene(), room);
}

// File > New, three balls, then a plane clicked behind them and a cylinder lower left: both are
// drawn where they were placed (only their arrows were).
void TestUserSession::objectsAddedAwayFromTheBallsAreDrawn() {
  QTest::keyClick(window_.get(), Qt::Key_N, Qt::ControlModifier);
  QVERIFY(document().scene().balls.empty());
  QTRY_VERIFY(framesRendered(*window_) > 2);
  const QSize size = view().size();
  QTest::keyClick(window_.get(), Qt::Key_B);
  for (double x : {0.45, 0.5, 0.55})
    QTest::mouseClick(&view(), Qt::LeftButton, {},
                      QPoint(int(x * size.width()), size.height() / 2));
  QCOMPARE(document().scene().balls.size(), std::size_t{3});

  const QPoint behind(size.width() / 2, size.height() / 6);
  const QPoint lowerLeft(size.width() / 8, size.height() * 7 / 8);
  QTest::keyClick(window_.get(), Qt::Key_P);
  QTest::mouseClick(&view(), Qt::LeftButton, {}, behind);
  QTest::keyClick(window_.get(), Qt::Key_C);
  QTest::mouseClick(&view(), Qt::LeftButton, {}, lowerLeft);
  const Scene& scene = document().scene();
  QVERIFY(!scene.planes.empty());
  QCOMPARE(scene.cylinders.size(), std::size_t{1});
  const carom::Plane& wall = scene.planes.back();

  // The render data holds both, each through its own point.
  const std::shared_ptr<const carom::render::RenderScene> shown = view().scene();
  QVERIFY(shown);
  QCOMPARE(shown->planes.size(), scene.planes.size());
  QVERIFY(shown->planes.back().polygon.size() >= 3);
  const carom::render::Bounds& bounds = shown->bounds;
  for (const Vec3& point : {wall.point, scene.cylinders[0].point})
    QVERIFY((point.array() >= bounds.min.array()).all() &&
            (point.array() <= bounds.max.array()).all());
  QVERIFY(shown->cylinders[0].start != shown->cylinders[0].end);

  // And the picture shows them there. The floor now reaches the horizon behind everything, in
  // the grey of a new wall: each gets a colour of its own to be told apart.
  Scene coloured = document().scene();
  coloured.planes.back().color = "#ff00ff";
  coloured.cylinders[0].color = "#00ffff";
  QVERIFY(carom::testing::applyEdit(document(), coloured, "colours").isEmpty());
  document().setSelection({});
  view().setHandleArrows({});
  const auto shows = [&](const QPoint& at, int missing) {
    const QImage picture = view().grabFramebuffer();
    const QColor colour = picture.pixelColor(at * picture.devicePixelRatio());
    const int channels[3] = {colour.red(), colour.green(), colour.blue()};
    for (int c = 0; c < 3; ++c)
      if (c != missing && channels[c] < channels[missing] + 40) return false;
    return true;
  };
  QTRY_VERIFY(shows(behind, 1));     // magenta: no green
  QTRY_VERIFY(shows(lowerLeft, 0));  // cyan: no red
}

// A click where the view shows only background selects nothing, whatever infinite wall lies
// beyond the drawn part: in the magic room, and in a new scene with a wall and a post placed away
// from its balls.
void TestUserSession::backgroundClicksSelectNothing() {
  backgroundClicks_ = 0;
  for (const char* example :
       {"magic-room", "galton-board", "gas-box", "inelastic-pile", "newtons-cradle"}) {
    openExample(example);
    // From the default direction, and from below and behind.
    for (const double turn : {0.0, 2.5}) {
      view().camera().orbit(turn, -0.4 * turn);
      view().update();
      QTRY_VERIFY(framesRendered(*window_) > 2);
      clickTheBackground();
    }
  }
  QTest::keyClick(window_.get(), Qt::Key_N, Qt::ControlModifier);
  const std::size_t staticObjects = document().scene().planes.size();
  const QSize size = view().size();
  QTest::keyClick(window_.get(), Qt::Key_B);
  QTest::mouseClick(&view(), Qt::LeftButton, {}, QPoint(size.width() / 2, size.height() / 2));
  QTest::keyClick(window_.get(), Qt::Key_P);
  QTest::mouseClick(&view(), Qt::LeftButton, {}, QPoint(size.width() / 2, size.height() / 6));
  QTest::keyClick(window_.get(), Qt::Key_C);
  QTest::mouseClick(&view(), Qt::LeftButton, {}, QPoint(size.width() / 8, size.height() * 7 / 8));
  QCOMPARE(document().scene().planes.size() + document().scene().cylinders.size(),
           staticObjects + 2);
  QTest::keyClick(window_.get(), Qt::Key_V);
  clickTheBackground();
  // The probe did probe: closed rooms and floors drawn out to the horizon leave some views no
  // background, but not all of them.
  QVERIFY2(backgroundClicks_ > 10, qPrintable(QString::number(backgroundClicks_)));
}

void TestUserSession::clickTheBackground() {
  document().setSelection({});
  view().setHandleArrows({});
  QTest::qWait(50);  // a frame without the selection's highlight
  const QImage picture = view().grabFramebuffer();
  const QColor background = picture.pixelColor(2, 2);
  const QSize size = view().size();
  int backgroundClicks = 0;
  // Fine enough to find background above the horizon, where the floor's far part ends.
  for (int gy = 1; gy < 36; ++gy) {
    for (int gx = 1; gx < 48; ++gx) {
      const QPoint at(size.width() * gx / 48, size.height() * gy / 36);
      // Background all around: an edge's pixel is drawn by its centre, a click's ray passes
      // through its corner.
      bool onlyBackground = true;
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx)
          if (picture.pixelColor((at + QPoint(dx, dy)) * picture.devicePixelRatio()) != background)
            onlyBackground = false;
      if (!onlyBackground) continue;
      ++backgroundClicks;
      document().setSelection({{ObjectKind::Ball, 0}});
      QTest::mouseClick(&view(), Qt::LeftButton, {}, at);
      if (!document().selection().empty()) {
        QFAIL(qPrintable(QString("click at %1,%2 selected %3")
                             .arg(at.x())
                             .arg(at.y())
                             .arg(carom::editor::objectLabel(document().scene(),
                                                             document().selection().front()))));
      }
    }
  }
  backgroundClicks_ += backgroundClicks;
}

// Recover a crash copy, then open an example and discard the recovered scene: the example opens
// unmodified (it opened as "magic-room*" with Undo greyed out, and Quit asked to save it).
void TestUserSession::exampleAfterDiscardedRecoveryOpensUnmodified() {
  // A recovered scene is unsaved, with nothing to undo.
  Scene recovered = carom::testing::floorScene();
  recovered.balls[0].name = "recovered";
  window_->openScene(recovered, {});
  document().markUnsaved();
  QVERIFY(document().isModified());
  {
    DialogAnswerer discard(QMessageBox::Discard);
    openExample("magic-room");
    QVERIFY(discard.answered());
  }
  QVERIFY(document().scene() == magicRoom());
  QVERIFY(!document().isModified());
  QVERIFY(!window_->isWindowModified());
  QVERIFY(!document().undoStack()->canUndo());
  // Quit closes without a question.
  QVERIFY(window_->close());
}

// An edited example is asked about by the name its title shows, not as "untitled".
void TestUserSession::promptNamesTheSceneOfTheTitle() {
  openExample("magic-room");
  const QString name = document().displayName();
  QVERIFY2(!name.isEmpty() && name != "untitled", qPrintable(name));
  QVERIFY2(window_->windowTitle().startsWith(name), qPrintable(window_->windowTitle()));
  document().setSelection({{ObjectKind::Ball, 0}});
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  QVERIFY(window_->isWindowModified());
  DialogAnswerer cancel(QMessageBox::Cancel);
  QVERIFY(!window_->close());
  QVERIFY(cancel.answered());
  QVERIFY2(cancel.text().contains(name), qPrintable(cancel.text()));
  QVERIFY(!cancel.text().contains("untitled"));
}

// Opening a scene frames it as Home does, whatever the camera did before.
void TestUserSession::openingAScenesFramesIt() {
  // Move the camera away first, as a user does.
  view().camera().zoom(6);
  view().camera().orbit(1.0, 0.3);
  openExample("gas-box");
  QTRY_VERIFY(framesRendered(*window_) > 2);
  carom::render::Camera home;
  home.setAspectRatio(view().camera().aspectRatio());
  home.home(view().scene()->bounds);
  const auto sameCamera = [&] {
    const carom::render::Camera& camera = view().camera();
    return std::abs(camera.distance() - home.distance()) < 1e-6 * home.distance() &&
           (camera.target() - home.target()).length() < 1e-4 &&
           std::abs(camera.yaw() - home.yaw()) < 1e-9 &&
           std::abs(camera.pitch() - home.pitch()) < 1e-9;
  };
  QVERIFY(sameCamera());
  // Every way of opening does it: New, and a file.
  view().camera().zoom(-4);
  QTest::keyClick(window_.get(), Qt::Key_N, Qt::ControlModifier);
  home.home(view().scene()->bounds);
  QVERIFY(sameCamera());
  const QString file = folder_.filePath("cradle.carom");
  QVERIFY(carom::io::saveSceneFile(*carom::io::loadSceneFile(":/scenes/newtons-cradle.json").scene,
                                   file, nullptr));
  view().camera().zoom(3);
  openThroughTheDialog(file);
  QCOMPARE(document().fileName(), QFileInfo(file).absoluteFilePath());
  home.home(view().scene()->bounds);
  QVERIFY(sameCamera());
}

// File > New has a floor at y = 0, an object like any other: balls added rest on it, and it can
// be deleted.
void TestUserSession::newGivesAFloorToBuildOn() {
  QTest::keyClick(window_.get(), Qt::Key_N, Qt::ControlModifier);
  const Scene& fresh = document().scene();
  QCOMPARE(fresh.planes.size(), std::size_t{1});
  QVERIFY(fresh.planes[0].point.isZero());
  QVERIFY(fresh.planes[0].normal == Vec3::UnitY());
  QVERIFY(!document().isModified());
  QTRY_VERIFY(framesRendered(*window_) > 2);
  QTest::keyClick(window_.get(), Qt::Key_B);
  const QSize size = view().size();
  QTest::mouseClick(&view(), Qt::LeftButton, {}, QPoint(size.width() / 2, size.height() / 2));
  QCOMPARE(document().scene().balls.size(), std::size_t{1});
  const Ball& ball = document().scene().balls[0];
  QVERIFY(std::abs(ball.position.y() - ball.radius) < 1e-9);  // resting on the floor
  // The floor is picked and deleted like anything else.
  QTest::keyClick(window_.get(), Qt::Key_V);
  click(Vec3(3, 0, 3));
  QCOMPARE(document().selection(), (carom::editor::Selection{{ObjectKind::Plane, 0}}));
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  QVERIFY(document().scene().planes.empty());
  QCOMPARE(document().scene().balls.size(), std::size_t{1});
}

// A passing message (a refusal, a save) shows beside the time/fps/energy readout, not over it.
void TestUserSession::statusMessagesLeaveTheReadout() {
  window_->setRunning(true);
  QTRY_VERIFY(statusText(*window_).contains("fps"));
  window_->setRunning(false);
  const QStringList labels = [&] {
    QStringList texts;
    for (QLabel* label : window_->statusBar()->findChildren<QLabel*>())
      if (label->isVisible()) texts << label->text();
    return texts;
  }();
  QVERIFY(labels.join(' ').contains("fps"));
  window_->showMessage("Something was refused");
  QCOMPARE(statusMessage(*window_), QString("Something was refused"));
  bool readoutVisible = false;
  for (QLabel* label : window_->statusBar()->findChildren<QLabel*>())
    if (label->isVisible() && label->text().contains("fps")) readoutVisible = true;
  QVERIFY(readoutVisible);
}

// Open a file, edit each kind of object, delete from the start, middle and end, save, open it
// again in a new window, and compare every field of every object with what was meant.
void TestUserSession::wholeSessionInEveryLanguage_data() {
  QTest::addColumn<QString>("language");
  // Under the sanitizers one language: the session's memory is the same in each, and the plain
  // suite walks all three.
  for (const char* code : {"en", "de", "ru"})
    if (!carom::testing::sanitizerRun() || QByteArray(code) == "en")
      QTest::newRow(code) << QString(code);
}

// Issue 34's whole scenario, in each language: open an example, add one of each shape, type
// negative values, drag and cancel, run, grab, scrub, study, save, reopen and compare every
// field of every object.
void TestUserSession::wholeSessionInEveryLanguage() {
  QFETCH(QString, language);
  QAction* chooseLanguage = window_->findChild<QAction*>("language:" + language);
  QVERIFY(chooseLanguage);
  chooseLanguage->trigger();
  const QChar point = QLocale().decimalPoint().front();
  const auto number = [point](QString text) { return text.replace('.', point); };

  // An example: the Galton board, which stands on an open floor (y = 0).
  window_->findChild<QAction*>("example:galton-board")->trigger();
  const Scene board = *carom::io::loadSceneFile(":/scenes/galton-board.json").scene;
  QTRY_VERIFY(document().scene() == board);
  QTRY_VERIFY(framesRendered(*window_) > 2);
  const std::size_t ball = board.balls.size(), peg = board.cylinders.size();

  // One of each shape, on the floor in front of the board and behind it.
  QTest::keyClick(window_.get(), Qt::Key_B);
  click(Vec3(1.5, 0, 1.0));
  QVERIFY2(document().scene().balls.size() == ball + 1, qPrintable(statusMessage(*window_)));
  QTest::keyClick(window_.get(), Qt::Key_K);
  click(Vec3(-1.5, 0, 1.0));
  QVERIFY2(document().scene().boxes.size() == board.boxes.size() + 1,
           qPrintable(statusMessage(*window_)));
  const std::size_t box = board.boxes.size();
  const carom::Box& placed = document().scene().boxes[box];
  QVERIFY(std::abs(placed.center.y() - placed.halfExtents.y()) < 1e-9);  // on the floor
  QTest::keyClick(window_.get(), Qt::Key_C);
  auto* toolLength = window_->findChild<QLineEdit*>("toolCylinderLength");
  QTRY_VERIFY(toolLength && toolLength->isVisible());
  QTest::mouseClick(toolLength, Qt::LeftButton);
  QTest::keyClick(toolLength, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClicks(toolLength, number("1.5"));
  QTest::keyClick(toolLength, Qt::Key_Return);
  click(Vec3(1.5, 0, -1.0));
  QVERIFY2(document().scene().cylinders.size() == peg + 1, qPrintable(statusMessage(*window_)));
  const carom::Cylinder post = document().scene().cylinders[peg];
  QCOMPARE(post.length, std::optional(1.5));
  QVERIFY2(std::abs(post.point.y() - 0.75) < 1e-9, qPrintable(QString::number(post.point.y())));
  QTest::keyClick(window_.get(), Qt::Key_P);
  // A wall behind the board, as the camera looks: everything stays on its side.
  const QVector3D eye = view().camera().eye(), target = view().camera().target();
  const Vec3 away = Vec3(target.x() - eye.x(), 0, target.z() - eye.z()).normalized();
  const Vec3 aside(-away.z(), 0, away.x());  // past the board's side, not through it
  click(Vec3(target.x(), 0, target.z()) + 1.2 * away + 1.2 * aside);
  QVERIFY2(document().scene().planes.size() == board.planes.size() + 1,
           qPrintable(statusMessage(*window_)));

  // Negative values typed in the language's format, each shown from its sign.
  QTest::keyClick(window_.get(), Qt::Key_V);
  document().setSelection({{ObjectKind::Ball, int(ball)}});
  type("velocity.x", number("-0.5"));
  type("velocity.z", number("-0.25"));
  QCOMPARE(document().scene().balls[ball].velocity, Vec3(-0.5, 0, -0.25));
  document().setSelection({{ObjectKind::Box, int(box)}});
  type("center.x", number("-1.642395"));
  QCOMPARE(document().scene().boxes[box].center.x(), -1.642395);
  auto* centreX = window_->propertiesDock()->findChild<QLineEdit*>("center.x");
  centreX->clearFocus();  // the user moves on: the field shows six digits, from the sign
  QVERIFY2(centreX->text().startsWith(number("-1.642")), qPrintable(centreX->text()));
  QCOMPARE(centreX->cursorPosition(), 0);
  type("halfExtents.x", number("0.25"));

  // A drag of the box, cancelled with Escape: nothing changes.
  const Scene edited = document().scene();
  const int steps = document().undoStack()->count();
  const carom::Box& crate = edited.boxes[box];
  const QPoint from = at(crate.center + Vec3(0, crate.halfExtents.y(), 0));
  const QPoint to = from + QPoint(60, 40);
  QTest::mousePress(&view(), Qt::LeftButton, Qt::NoModifier, from);
  for (int i = 1; i <= 10; ++i) QTest::mouseMove(&view(), from + (to - from) * i / 10);
  QTRY_VERIFY(!(document().scene() == edited));
  QTest::keyClick(&view(), Qt::Key_Escape);
  QTest::mouseRelease(&view(), Qt::LeftButton, Qt::NoModifier, to);
  QVERIFY(document().scene() == edited);
  QCOMPARE(document().undoStack()->count(), steps);

  // Run, then pause.
  QTest::keyClick(window_.get(), Qt::Key_Space);
  QVERIFY(QTest::qWaitFor(
      [&] {
        const auto s = window_->simulation().latest();
        return s && s->running && s->time > 0.5;
      },
      20000));
  QTest::keyClick(window_.get(), Qt::Key_Space);
  QVERIFY(QTest::qWaitFor([&] { return !currentSnapshot()->running; }, 10000));

  // Grab the added ball and lift it: the run's state, not an edit.
  const auto paused = window_->simulation().latest();
  const Vec3 held = paused->positions[ball];
  const QPoint grabAt = at(held);
  QTest::mousePress(&view(), Qt::LeftButton, Qt::NoModifier, grabAt);
  for (int i = 1; i <= 10; ++i) QTest::mouseMove(&view(), grabAt + QPoint(0, -3 * i));
  QVERIFY(QTest::qWaitFor(
      [&] {
        const auto s = window_->simulation().latest();
        return s->grabbed == int(ball) && s->positions[ball].y() > held.y() + 0.05;
      },
      10000));
  QTest::mouseRelease(&view(), Qt::LeftButton, Qt::NoModifier, grabAt + QPoint(0, -30));
  QVERIFY(document().scene() == edited);

  // Scrub back along the timeline with its keys.
  auto* slider = window_->findChild<QSlider*>("timelineSlider");
  QVERIFY(slider);
  QTest::mouseClick(slider, Qt::LeftButton, Qt::NoModifier, QPoint(slider->width() / 2, 3));
  QTest::keyClick(slider, Qt::Key_PageDown);
  QVERIFY(QTest::qWaitFor(
      [&] {
        const auto s = window_->simulation().latest();
        return s->frame < s->frameCount;
      },
      10000));

  // A short study of speed against accuracy.
  carom::ui::AccuracyWindow* study = window_->openAccuracyWindow(0.5);
  QVERIFY(study);
  QTRY_VERIFY_WITH_TIMEOUT(!study->isRunning(), 120000);
  QVERIFY(!study->results().empty());
  study->close();

  // Save, open something else, reopen: every field of every object as it was.
  const QString file = folder_.filePath("session-" + language + ".carom");
  saveAsThroughTheDialog(file);
  QVERIFY(!document().isModified());
  window_->findChild<QAction*>("example:gas-box")->trigger();
  QTRY_VERIFY(document().scene().planes.size() != edited.planes.size() ||
              document().scene().balls.size() != edited.balls.size());
  openThroughTheDialog(file);
  QCOMPARE(document().fileName(), QFileInfo(file).absoluteFilePath());
  compareObjects(document().scene(), edited);
  QVERIFY(document().scene().world == edited.world);
  QVERIFY(document().scene() == edited);
  QVERIFY(!document().isModified());
}

void TestUserSession::openEditDeleteSaveReopen() {
  Scene start = magicRoom();
  const QString file = folder_.filePath("session.carom");
  QVERIFY(carom::io::saveSceneFile(start, file, nullptr));
  openThroughTheDialog(file);
  QVERIFY(document().scene() == start);
  QTRY_VERIFY(framesRendered(*window_) > 2);

  Scene expected = start;
  // Delete the first plane (the floor), a middle cylinder, and the last ball, each by a click
  // in the view or a selection from the document as the outline makes it, then Delete.
  click(start.balls.back().position);
  QCOMPARE(document().selection(), (carom::editor::Selection{{ObjectKind::Ball, 9}}));
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  expected.balls.pop_back();
  document().setSelection({{ObjectKind::Cylinder, 1}});
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  expected.cylinders.erase(expected.cylinders.begin() + 1);
  document().setSelection({{ObjectKind::Plane, 0}, {ObjectKind::Ball, 0}, {ObjectKind::Ball, 4}});
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  expected.planes.erase(expected.planes.begin());
  expected.balls.erase(expected.balls.begin() + 4);
  expected.balls.erase(expected.balls.begin());
  compareObjects(document().scene(), expected);

  // Duplicate a cylinder: the copy keeps the name and colour.
  document().setSelection({{ObjectKind::Cylinder, 0}});
  QTest::keyClick(window_.get(), Qt::Key_D, Qt::ControlModifier);
  QCOMPARE(document().scene().cylinders.size(), expected.cylinders.size() + 1);
  expected.cylinders.push_back(document().scene().cylinders.back());
  QCOMPARE(expected.cylinders.back().name, start.cylinders[0].name);

  QTest::keyClick(window_.get(), Qt::Key_S, Qt::ControlModifier);
  QVERIFY(!document().isModified());

  window_.reset();
  openWindow();
  openThroughTheDialog(file);
  compareObjects(document().scene(), expected);
  QVERIFY(!document().isModified());
}

// A scene built with boxes by mouse and keys: Add Box (K) clicks on the floor and on a box's
// top, a cylinder (C) beside them; a box's fields typed in the properties dock, another resized
// and turned by its handles, the stacked one deleted; every step undone and redone with the
// keys; then Save As, a new window, Open, and every field of every object compared.
void TestUserSession::buildWithBoxesSaveReopen() {
  QTRY_VERIFY(framesRendered(*window_) > 2);
  QTest::keyClick(window_.get(), Qt::Key_K);
  QVERIFY(window_->findChild<QAction*>("toolAddBox")->isChecked());
  Scene before = document().scene();
  click(Vec3(2, 0, 1.5));
  QCOMPARE(document().scene().boxes.size(), std::size_t{1});
  const carom::Box first = document().scene().boxes[0];
  QVERIFY2(std::abs(first.center.y() - 0.5) < 1e-9, qPrintable(QString::number(first.center.y())));
  QVERIFY((first.center - Vec3(2, 0.5, 1.5)).norm() < 0.1);
  undoRedo(before, document().scene());
  click(Vec3(-2, 0, 1));
  click(first.center + Vec3(0, 0.5, 0));  // onto the first box's top
  QCOMPARE(document().scene().boxes.size(), std::size_t{3});
  QVERIFY(std::abs(document().scene().boxes[2].center.y() - 1.5) < 1e-9);
  QTest::keyClick(window_.get(), Qt::Key_C);
  click(Vec3(-2, 0, -2));
  QCOMPARE(document().scene().cylinders.size(), std::size_t{1});

  // The first box's fields, typed into the properties dock after a click on its front face.
  QTest::keyClick(window_.get(), Qt::Key_V);
  click(first.center + Vec3(0, -0.2, 0.5));
  QCOMPARE(document().selection(), (carom::editor::Selection{{ObjectKind::Box, 0}}));
  const auto typed = [&](const QString& field, const QString& text) {
    const Scene previous = document().scene();
    type(field, text);
    QVERIFY2(!(document().scene() == previous), qPrintable(field));
    undoRedo(previous, document().scene());
  };
  typed("name", "crate");
  typed("color", "#4080c0");
  typed("restitution", "0.7");
  typed("halfExtents.z", "0.4");
  typed("rotationDegrees", "15");
  const carom::Box& crate = document().scene().boxes[0];
  QCOMPARE(crate.name, std::string("crate"));
  QCOMPARE(crate.color, std::string("#4080c0"));
  QCOMPARE(crate.restitution, std::optional(0.7));
  QCOMPARE(crate.halfExtents, Vec3(0.5, 0.5, 0.4));
  QVERIFY(crate.rotation == (carom::Rotation{Vec3::UnitY(), 15}));
  // Flattened to nothing, it is refused with the validation's message.
  const Scene typedIn = document().scene();
  type("halfExtents.y", "0");
  QVERIFY(document().scene() == typedIn);
  QVERIFY2(statusMessage(*window_).contains("Half extents y of crate must be above zero"),
           qPrintable(statusMessage(*window_)));

  // The second box, made longer by its +x face and turned by its handle.
  click(document().scene().boxes[1].center + Vec3(0, 0.5, 0));
  QCOMPARE(document().selection(), (carom::editor::Selection{{ObjectKind::Box, 1}}));
  before = document().scene();
  std::optional<Handle> face = findHandle(editorTools(*window_)->handles(), HandleRole::BoxFace, 0);
  QVERIFY(face);
  drag(at(face->tip), at(face->tip + Vec3(0.5, 0, 0)),
       [&] { return document().scene().boxes[1].halfExtents.x() > 0.7; });
  const carom::Box longer = document().scene().boxes[1];
  QVERIFY(std::abs(longer.center.x() - longer.halfExtents.x() -
                   (before.boxes[1].center.x() - 0.5)) < 1e-9);
  undoRedo(before, document().scene());
  before = document().scene();
  const std::optional<Handle> turn =
      findHandle(editorTools(*window_)->handles(), HandleRole::BoxTurn, 1);
  QVERIFY(turn);
  const Vec3 top = turn->base;
  const auto turnedTip = [&](double degrees) -> Vec3 {
    return top +
           Eigen::AngleAxisd(degrees * std::numbers::pi / 180, Vec3::UnitY()) * (turn->tip - top);
  };
  QTest::mousePress(&view(), Qt::LeftButton, Qt::NoModifier, at(turn->tip));
  for (int step = 1; step <= 10; ++step) QTest::mouseMove(&view(), at(turnedTip(3.0 * step)));
  QTRY_VERIFY(document().scene().boxes[1].rotation &&
              document().scene().boxes[1].rotation->degrees > 28);
  QTest::mouseRelease(&view(), Qt::LeftButton, Qt::NoModifier, at(turnedTip(30)));
  QVERIFY(std::abs(document().scene().boxes[1].rotation->degrees - 30) < 1.5);
  QCOMPARE(document().scene().boxes[1].center, longer.center);
  undoRedo(before, document().scene());

  // The stacked box goes; nothing else changes, names and fields included.
  click(document().scene().boxes[2].center + Vec3(0, 0.5, 0));
  QCOMPARE(document().selection(), (carom::editor::Selection{{ObjectKind::Box, 2}}));
  before = document().scene();
  QTest::keyClick(window_.get(), Qt::Key_Delete);
  Scene expected = before;
  expected.boxes.pop_back();
  compareObjects(document().scene(), expected);
  undoRedo(before, expected);

  const QString file = folder_.filePath("boxes.carom");
  saveAsThroughTheDialog(file);
  QVERIFY(!document().isModified());
  window_.reset();
  openWindow();
  openThroughTheDialog(file);
  compareObjects(document().scene(), expected);
  QCOMPARE(document().scene().balls.size(), std::size_t{1});
  QCOMPARE(document().scene().planes.size(), std::size_t{3});
  QCOMPARE(document().scene().boxes[0].name, std::string("crate"));
  QVERIFY(!document().isModified());
}

// A box and capped cylinders built with the tools, the keys and the properties dock: a post
// added and given a length, standing on the floor; a second added capped like it, lengthened by its
// end handle and named; the box narrowed by its -x face; the first post made infinite and capped
// again; every step undone and redone with the keys; then Save As, a new window, Open, and
// every field of every object compared.
void TestUserSession::buildWithCappedCylindersSaveReopen() {
  QTRY_VERIFY(framesRendered(*window_) > 2);
  QTest::keyClick(window_.get(), Qt::Key_K);
  click(Vec3(2, 0, 1.5));
  QCOMPARE(document().scene().boxes.size(), std::size_t{1});
  QTest::keyClick(window_.get(), Qt::Key_C);
  QVERIFY(window_->findChild<QAction*>("toolAddCylinder")->isChecked());
  Scene before = document().scene();
  click(Vec3(-2, 0, -2));
  QCOMPARE(document().scene().cylinders.size(), std::size_t{1});
  QCOMPARE(document().scene().cylinders[0].length, std::nullopt);  // the first: infinite
  undoRedo(before, document().scene());
  QCOMPARE(document().selection(), (carom::editor::Selection{{ObjectKind::Cylinder, 0}}));
  const auto typed = [&](const QString& field, const QString& text) {
    const Scene previous = document().scene();
    type(field, text);
    QVERIFY2(!(document().scene() == previous), qPrintable(field));
    undoRedo(previous, document().scene());
  };
  typed("cylinderLength", "1.2");  // standing on the floor, it rises from it
  const carom::Cylinder first = document().scene().cylinders[0];
  QCOMPARE(first.length, std::optional(1.2));
  QVERIFY(std::abs(first.point.x() + 2) < 0.1 && std::abs(first.point.z() + 2) < 0.1);
  QVERIFY2(std::abs(first.point.y() - 0.6) < 1e-9, qPrintable(QString::number(first.point.y())));
  // No length at all is refused with the validation's message, and changes nothing.
  const Scene standing = document().scene();
  const int commands = document().undoStack()->count();
  type("cylinderLength", "0");
  QVERIFY(document().scene() == standing);
  QCOMPARE(document().undoStack()->count(), commands);
  QVERIFY2(statusMessage(*window_).contains("Length of Cylinder 0 must be above zero"),
           qPrintable(statusMessage(*window_)));

  // The next post is capped like the last one, with its lower cap on the floor.
  before = document().scene();
  click(Vec3(-2, 0, 1));
  QCOMPARE(document().scene().cylinders.size(), std::size_t{2});
  const carom::Cylinder second = document().scene().cylinders[1];
  QCOMPARE(second.length, std::optional(1.2));
  QVERIFY2(std::abs(second.point.y() - 0.6) < 1e-9, qPrintable(QString::number(second.point.y())));
  undoRedo(before, document().scene());

  // Taller by its upper end's handle, then named and coloured.
  QTest::keyClick(window_.get(), Qt::Key_V);
  before = document().scene();
  std::optional<Handle> end =
      findHandle(editorTools(*window_)->handles(), HandleRole::CylinderEnd, 0, 1);
  QVERIFY(end);
  drag(at(end->tip), at(end->tip + Vec3(0, 0.5, 0)),
       [&] { return document().scene().cylinders[1].length.value_or(0) > 1.65; });
  const carom::Cylinder taller = document().scene().cylinders[1];
  QVERIFY2(std::abs(*taller.length - 1.7) < 0.05, qPrintable(QString::number(*taller.length)));
  QVERIFY(std::abs(taller.point.y() - 0.5 * *taller.length - (second.point.y() - 0.6)) < 1e-9);
  undoRedo(before, document().scene());
  typed("name", "post");
  typed("color", "#c08040");
  typed("restitution", "0.8");
  typed("cylinderRadius", "0.25");

  // The box narrowed by its -x face; its +x face stays.
  click(document().scene().boxes[0].center + Vec3(0, 0.5, 0));
  QCOMPARE(document().selection(), (carom::editor::Selection{{ObjectKind::Box, 0}}));
  before = document().scene();
  const std::optional<Handle> face =
      findHandle(editorTools(*window_)->handles(), HandleRole::BoxFace, 0, -1);
  QVERIFY(face);
  drag(at(face->tip), at(face->tip + Vec3(0.4, 0, 0)),
       [&] { return document().scene().boxes[0].halfExtents.x() < 0.35; });
  const carom::Box narrower = document().scene().boxes[0];
  QVERIFY(std::abs(narrower.center.x() + narrower.halfExtents.x() -
                   (before.boxes[0].center.x() + 0.5)) < 1e-9);
  undoRedo(before, document().scene());
  typed("name", "crate");

  // The first post made infinite, then capped again by typing.
  click(first.point + Vec3(0, 0.3, 0.3));
  QCOMPARE(document().selection(), (carom::editor::Selection{{ObjectKind::Cylinder, 0}}));
  typed("cylinderLength", "");
  QCOMPARE(document().scene().cylinders[0].length, std::nullopt);
  typed("cylinderLength", "0.8");
  QCOMPARE(document().scene().cylinders[0].length, std::optional(0.8));

  const Scene expected = document().scene();
  const QString file = folder_.filePath("posts.carom");
  saveAsThroughTheDialog(file);
  QVERIFY(!document().isModified());
  window_.reset();
  openWindow();
  openThroughTheDialog(file);
  compareObjects(document().scene(), expected);
  QCOMPARE(document().scene().cylinders[1].name, std::string("post"));
  QCOMPARE(document().scene().cylinders[1].radius, 0.25);
  QVERIFY(!document().isModified());
}

QTEST_MAIN(TestUserSession)
#include "test_user_session.moc"
