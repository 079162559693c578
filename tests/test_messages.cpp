// Refusals in the window speak the user's language (issue 34): a problem the scene validation
// finds names objects as the Outline names them and fields as the Properties dock labels them,
// with numbers in the language's locale, never by the file's paths ("balls[3].position"), which
// stay for files and carom-cli.
//
// With CAROM_SCREENSHOT_DIR set, pictures of the window showing the refusals are saved there.

#include "sim/core/tolerances.h"
#include "sim/validation/validation.h"
#include "tests/editor_fixture.h"
#include "ui/editor/object_ref.h"
#include "ui/editor/outline_dock.h"
#include "ui/editor/properties_dock.h"
#include "ui/editor/validation_text.h"
#include "ui/language.h"

#include <QDir>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpression>

#include <cmath>
#include <functional>
#include <vector>

using carom::Vec3;
using carom::editor::ObjectKind;
using carom::editor::ObjectRef;

Q_DECLARE_METATYPE(ObjectRef)

namespace {

// A floor under a ceiling too low for a ball (its surface at y = 0.4, facing down), between the
// fixture's walls at x = -4 and 4: no ball fits anywhere. Only the floor has a name.
carom::Scene lowRoom() {
  carom::Scene scene = carom::testing::floorScene();
  scene.balls.clear();
  carom::Plane ceiling;
  ceiling.point = Vec3(0, 0.4, 0);
  ceiling.normal = -Vec3::UnitY();
  scene.planes.insert(scene.planes.begin() + 1, ceiling);
  return scene;
}

// The file's way of naming things, which the window must not use.
bool hasPath(const QString& message) {
  for (const char* path : {"balls[", "planes[", "cylinders[", "boxes[", "world.", ".position"})
    if (message.contains(path)) return true;
  return false;
}

}  // namespace

class TestMessages : public carom::testing::EditorFixture {
  Q_OBJECT

 private slots:
  void cleanup() {
    window_.reset();
    carom::ui::installTranslation(*QCoreApplication::instance(), "en");
  }

  void placingABallNamesWhatItWouldOverlap_data();
  void placingABallNamesWhatItWouldOverlap();
  void typedPositionNamesWhatItWouldOverlap_data();
  void typedPositionNamesWhatItWouldOverlap();
  void typedRadiusNamesTheFieldAndTheBall_data();
  void typedRadiusNamesTheFieldAndTheBall();
  void typedWorldSettingNamesTheField();
  void everyProblemHasItsWords();

 private:
  void openIn(const QString& code, const carom::Scene& scene) {
    QVERIFY(carom::ui::installTranslation(*QCoreApplication::instance(), code));
    openWindow();
    window_->openScene(scene, {}, "room");
    QTRY_VERIFY(framesRendered(*window_) > 0);
  }
  QString outlineLabel(const ObjectRef& ref) {
    carom::editor::OutlineModel& outline = *window_->outlineDock()->model();
    return outline.data(outline.indexOf(ref), Qt::DisplayRole).toString();
  }
  carom::editor::PropertiesDock& properties() { return *window_->propertiesDock(); }
  // The label the Properties dock shows beside field `name`.
  QString fieldLabel(const QString& name) {
    for (QLabel* label : properties().findChildren<QLabel*>())
      if (label->buddy() && label->buddy()->objectName() == name) return label->text();
    return {};
  }
  // Clicks into the field, replaces its text as a user would, and presses Enter.
  void type(const QString& name, const QString& text) {
    auto* edit = properties().findChild<QLineEdit*>(name);
    QVERIFY2(edit && edit->isVisible(), qPrintable(name));
    QTest::mouseClick(edit, Qt::LeftButton);
    QTest::keyClick(edit, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClick(edit, Qt::Key_Backspace);
    QTest::keyClicks(edit, text);
    QTest::keyClick(edit, Qt::Key_Return);
  }
  // Saved as NAME-ROW.png, the row's tag in file name characters.
  void keepPicture(const QString& name) {
    const QString folder = qEnvironmentVariable("CAROM_SCREENSHOT_DIR");
    if (folder.isEmpty()) return;
    QDir().mkpath(folder);
    const QString row = QString(QTest::currentDataTag()).replace(QRegularExpression("\\W+"), "-");
    QVERIFY(window_->grab().save(QDir(folder).filePath(name + "-" + row + ".png")));
  }
};

void TestMessages::placingABallNamesWhatItWouldOverlap_data() {
  QTest::addColumn<QString>("code");
  QTest::addColumn<Vec3>("clicked");
  QTest::addColumn<ObjectRef>("overlapped");
  QTest::addColumn<QString>("english");
  // On the floor the ball's centre is above the ceiling's surface; against the wall, low, it
  // dips into the floor. Every spot nearby is as bad: the tool gives up.
  for (const char* code : {"en", "de", "ru"}) {
    QTest::addRow("%s, floor", code)
        << QString(code) << Vec3(1, 0, 1) << ObjectRef{ObjectKind::Plane, 1}
        << "No room for a ball there: Ball 0 would be 0.1 m behind the surface of Plane 1";
    QTest::addRow("%s, wall", code)
        << QString(code) << Vec3(-4, 0.2, 1) << ObjectRef{ObjectKind::Plane, 0}
        << "No room for a ball there: Ball 0 would overlap floor by ";
  }
}

void TestMessages::placingABallNamesWhatItWouldOverlap() {
  QFETCH(QString, code);
  QFETCH(Vec3, clicked);
  QFETCH(ObjectRef, overlapped);
  QFETCH(QString, english);
  openIn(code, lowRoom());
  chooseTool("toolAddBall");
  click(clicked);
  QVERIFY(document().scene().balls.empty());
  const QString message = statusMessage(*window_);
  QVERIFY2(!hasPath(message), qPrintable(message));
  // The plane as the Outline names it, the ball that would have been added as it would.
  QVERIFY2(message.contains(outlineLabel(overlapped)), qPrintable(message));
  carom::Scene added;
  added.balls.resize(1);
  QVERIFY2(message.contains(carom::editor::objectLabel(added, {ObjectKind::Ball, 0})),
           qPrintable(message));
  if (code == "en") QVERIFY2(message.startsWith(english), qPrintable(message));
  keepPicture("place");
}

void TestMessages::typedPositionNamesWhatItWouldOverlap_data() {
  QTest::addColumn<QString>("code");
  QTest::addColumn<QString>("name");
  QTest::addColumn<QString>("field");
  QTest::addColumn<QString>("typed");
  QTest::addColumn<ObjectRef>("overlapped");
  QTest::addColumn<QString>("english");
  for (const char* code : {"en", "de", "ru"}) {
    QTest::addRow("%s, named ball into the floor", code)
        << QString(code) << "first"
        << "position.y"
        << "0.2" << ObjectRef{ObjectKind::Plane, 0} << "first would overlap floor by 0.3 m";
    QTest::addRow("%s, unnamed ball into a wall", code)
        << QString(code) << ""
        << "position.x"
        << "3.75" << ObjectRef{ObjectKind::Plane, 2} << "Ball 0 would overlap Plane 2 by 0.25 m";
    QTest::addRow("%s, far below the floor", code)
        << QString(code) << "first"
        << "position.y"
        << "-1000000" << ObjectRef{ObjectKind::Plane, 0}
        << "first would be 1,000,000 m behind the surface of floor";
  }
}

void TestMessages::typedPositionNamesWhatItWouldOverlap() {
  QFETCH(QString, code);
  QFETCH(QString, name);
  QFETCH(QString, field);
  QFETCH(QString, typed);
  QFETCH(ObjectRef, overlapped);
  QFETCH(QString, english);
  carom::Scene scene = carom::testing::floorScene();
  scene.balls[0].name = name.toStdString();
  openIn(code, scene);
  const ObjectRef ball{ObjectKind::Ball, 0};
  document().setSelection({ball});
  type(field, typed);
  QCOMPARE(document().scene().balls[0].position, Vec3(0, 0.5, 0));
  const QString message = statusMessage(*window_);
  QCOMPARE(properties().message(), message);
  QVERIFY2(!hasPath(message), qPrintable(message));
  QVERIFY2(message.contains(outlineLabel(ball)), qPrintable(message));
  QVERIFY2(message.contains(outlineLabel(overlapped)), qPrintable(message));
  if (code == "en") QCOMPARE(message, english);
  // The depth in the language's numbers: "0,3" in German and Russian.
  if (code != "en" && english.contains("0."))
    QVERIFY2(message.contains(QString(english).section(' ', -2, -2).replace('.', ',')),
             qPrintable(message));
  keepPicture("position");
}

void TestMessages::typedRadiusNamesTheFieldAndTheBall_data() {
  QTest::addColumn<QString>("code");
  QTest::newRow("en") << "en";
  QTest::newRow("de") << "de";
  QTest::newRow("ru") << "ru";
}

void TestMessages::typedRadiusNamesTheFieldAndTheBall() {
  QFETCH(QString, code);
  openIn(code, carom::testing::floorScene());
  const ObjectRef ball{ObjectKind::Ball, 0};
  document().setSelection({ball});
  type("ballRadius", "-1");
  QCOMPARE(document().scene().balls[0].radius, 0.5);
  const QString message = statusMessage(*window_);
  QCOMPARE(properties().message(), message);
  QVERIFY2(!hasPath(message), qPrintable(message));
  QVERIFY2(message.contains(outlineLabel(ball)), qPrintable(message));
  const QString radius = fieldLabel("ballRadius");
  QVERIFY(!radius.isEmpty());
  QVERIFY2(message.contains(radius), qPrintable(message));
  if (code == "en") QCOMPARE(message, QString("Radius of first must be above zero (got -1 m)"));
  keepPicture("radius");
}

// With nothing selected the dock edits the world, which has no name: the field alone.
void TestMessages::typedWorldSettingNamesTheField() {
  openIn("en", carom::testing::floorScene());
  document().setSelection({});
  type("timeStep", "0");
  QCOMPARE(statusMessage(*window_), QString("Time step must be above zero (got 0 s)"));
  type("worldRestitution", "1.5");
  QCOMPARE(statusMessage(*window_), QString("Restitution must be between 0 and 1 (got 1.5)"));
}

// Each kind of problem the validation reports, worded: never the file's message in English.
void TestMessages::everyProblemHasItsWords() {
  openIn("en", carom::testing::floorScene());
  carom::Scene scene = carom::testing::floorScene();
  carom::Box box;
  box.center = Vec3(2, 0.5, 0);
  box.halfExtents = Vec3::Constant(0.5);
  scene.boxes.push_back(box);
  const auto words = [&](const std::function<void(carom::Scene&)>& edit) {
    carom::Scene edited = scene;
    edit(edited);
    const std::vector<carom::ValidationError> errors = carom::validateScene(edited, 1);
    return errors.empty() ? QString() : carom::editor::validationText(errors.front(), edited);
  };
  using carom::Scene;
  QCOMPARE(words([](Scene& s) { s.balls[0].position.x() = std::nan(""); }),
           QString("Position of first must be a finite number"));
  QCOMPARE(words([](Scene& s) { s.balls[0].velocity.z() = 1e13; }),
           QString("Velocity of first must lie within ±1e+12 m/s (got 1e+13 m/s)"));
  QCOMPARE(words([](Scene& s) { s.balls[0].mass = -2; }),
           QString("Mass of first must be above zero (got -2 kg)"));
  QCOMPARE(words([](Scene& s) { s.balls[0].radius = 1e-13; }),
           QString("Radius of first must be at least 1e-12 m (got 1e-13 m)"));
  QCOMPARE(words([](Scene& s) { s.balls[0].mass = 1e31; }),
           QString("Mass of first must be between 1e-30 kg and 1e+30 kg (got 1e+31 kg)"));
  QCOMPARE(words([](Scene& s) { s.world.timeStep = 2e6; }),
           QString("Time step must be between 1e-12 s and 1,000,000 s (got 2,000,000 s)"));
  QCOMPARE(words([](Scene& s) {
             s.world.autoMethod = carom::AccuracyTolerance{0.0, 0.05};
           }),
           QString("Accuracy must be above zero (got 0)"));
  QCOMPARE(words([](Scene& s) { s.planes[1].normal = Vec3::Zero(); }),
           QString("Normal of Plane 1 must not be zero: it gives a direction"));
  QCOMPARE(words([](Scene& s) { s.balls[0].color = "red"; }),
           QString("Colour of first must be empty or a colour such as #ff8000 (got “red”)"));
  QCOMPARE(words([](Scene& s) { s.boxes[0].halfExtents.y() = 0; }),
           QString("Half extents y of Box 0 must be above zero (got 0 m)"));
  QCOMPARE(words([](Scene& s) {
             s.boxes[0].rotation = carom::Rotation{Vec3::UnitY(), 1e13};
           }),
           QString("Rotation of Box 0 must lie within ±1e+12° (got 1e+13°)"));
  QCOMPARE(words([](Scene& s) { s.balls[0].angularVelocity.x() = 1e13; }),
           QString("Angular velocity of first must lie within ±1e+12 rad/s (got 1e+13 rad/s)"));
  QCOMPARE(words([](Scene& s) { s.boxes[0].friction = -1; }),
           QString("Friction of Box 0 must be between 0 and 1,000,000 (got -1)"));
  QCOMPARE(words([](Scene& s) { s.planes[1].rollingResistance = std::nan(""); }),
           QString("Rolling resistance of Plane 1 must be a finite number"));
  QCOMPARE(words([](Scene& s) { s.world.spinningFriction = 2e6; }),
           QString("Spinning friction must be between 0 and 1,000,000 (got 2,000,000)"));
  QCOMPARE(words([](Scene& s) { s.world.tangentialRestitution = 1.5; }),
           QString("Tangential restitution must be between 0 and 1 (got 1.5)"));
  QCOMPARE(words([](Scene& s) { s.balls[0].position.x() = 1.2; }),
           QString("first would overlap Box 0 by 0.2 m"));
  // A name too long for the file is named by the name it has, elided as the Outline elides it.
  const QString tooLong = words([](Scene& s) { s.balls[0].name = std::string(300, 'n'); });
  QVERIFY2(tooLong.startsWith("Name of nnn") && tooLong.contains("…") &&
               tooLong.endsWith(" must be at most 256 characters long (got 300)"),
           qPrintable(tooLong));
  QVERIFY2(tooLong.size() < 100, qPrintable(tooLong));

  // A list too long, and a tolerance given alone.
  QCOMPARE(carom::editor::validationText(
               carom::validateCounts({.balls = carom::tolerance::kMaxBalls + 1}).front(), scene),
           QString("Balls: at most 1,000,000 in a scene (this would make 1,000,001)"));
  QCOMPARE(carom::editor::validationText(carom::validateTolerance({1e-3, 0.0}).front(), scene),
           QString("Penetration tolerance must be above zero (got 0)"));
}

QTEST_MAIN(TestMessages)
#include "test_messages.moc"
