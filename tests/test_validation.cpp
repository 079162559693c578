// validateScene: every rule with its exact message, file order, limits and the speed of the
// ball-ball overlap test.

#include "sim/core/tolerances.h"
#include "sim/model/scene.h"
#include "sim/validation/validation.h"

#include <QObject>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

using carom::Ball;
using carom::Cylinder;
using carom::Plane;
using carom::Scene;
using carom::Vec3;

using SceneEdit = std::function<void(Scene&)>;
Q_DECLARE_METATYPE(SceneEdit)

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

Ball makeBall(const Vec3& position, double radius) {
  Ball ball;
  ball.position = position;
  ball.radius = radius;
  return ball;
}

// A valid scene with one object of each kind before the balls that the cases edit: a floor at
// y = 0, a cylinder along z through (5, 1, 0) of radius 0.5, a cube of side 1 around (-5, 1, 0)
// and two balls of radius 0.5.
Scene baseScene() {
  Scene scene;
  Plane floor;
  floor.point = Vec3(0, 0, 0);
  floor.normal = Vec3(0, 1, 0);
  scene.planes.push_back(floor);
  Cylinder post;
  post.point = Vec3(5, 1, 0);
  post.axis = Vec3(0, 0, 1);
  post.radius = 0.5;
  scene.cylinders.push_back(post);
  carom::Box cube;
  cube.center = Vec3(-5, 1, 0);
  cube.halfExtents = Vec3(0.5, 0.5, 0.5);
  scene.boxes.push_back(cube);
  scene.balls.push_back(makeBall(Vec3(0, 1, 0), 0.5));
  scene.balls.push_back(makeBall(Vec3(2, 1, 0), 0.5));
  return scene;
}

QStringList texts(const std::vector<carom::ValidationError>& errors) {
  QStringList result;
  for (const auto& error : errors) result << QString::fromStdString(error.text());
  return result;
}

// Every overlap of a ball with an earlier ball, in the order validateScene reports them, found
// the slow and obvious way.
QStringList bruteForceOverlaps(const std::vector<Ball>& balls) {
  QStringList result;
  for (std::size_t later = 0; later < balls.size(); ++later) {
    for (std::size_t earlier = 0; earlier < later; ++earlier) {
      const double sum = balls[later].radius + balls[earlier].radius;
      const double distance = (balls[later].position - balls[earlier].position).norm();
      if (sum - distance > carom::tolerance::kTouchFraction * sum)
        result << QString("balls[%1].position: overlaps balls[%2]").arg(later).arg(earlier);
    }
  }
  return result;
}

}  // namespace

class ValidationTest : public QObject {
  Q_OBJECT

 private slots:
  void validSceneHasNoErrors() {
    const Scene scene = baseScene();
    QCOMPARE(texts(carom::validateScene(scene)), QStringList());
    QVERIFY(carom::validateScene(Scene()).empty());
  }

  void badValue_data() {
    QTest::addColumn<SceneEdit>("edit");
    QTest::addColumn<QString>("error");

    const auto row = [](const char* name, SceneEdit edit, const char* error) {
      QTest::newRow(name) << edit << QString(error);
    };
    row(
        "gravity nan", [](Scene& s) { s.world.gravity.y() = kNaN; },
        "world.gravity: must be finite");
    row(
        "gravity inf", [](Scene& s) { s.world.gravity.x() = -kInf; },
        "world.gravity: must be finite");
    row(
        "gravity absurd", [](Scene& s) { s.world.gravity.z() = 1e300; },
        "world.gravity: must be at most 1e12 in magnitude (got 1e300)");
    row(
        "time step zero", [](Scene& s) { s.world.timeStep = 0; },
        "world.timeStep: must be positive (got 0)");
    row(
        "time step negative", [](Scene& s) { s.world.timeStep = -1; },
        "world.timeStep: must be positive (got -1)");
    row(
        "time step tiny", [](Scene& s) { s.world.timeStep = 1e-13; },
        "world.timeStep: must be between 1e-12 and 1e6 (got 1e-13)");
    row(
        "time step huge", [](Scene& s) { s.world.timeStep = 1e7; },
        "world.timeStep: must be between 1e-12 and 1e6 (got 1e7)");
    row(
        "time step nan", [](Scene& s) { s.world.timeStep = kNaN; },
        "world.timeStep: must be finite");
    row(
        "world restitution high", [](Scene& s) { s.world.restitution = 1.5; },
        "world.restitution: must be between 0 and 1 (got 1.5)");
    row(
        "world restitution negative", [](Scene& s) { s.world.restitution = -0.1; },
        "world.restitution: must be between 0 and 1 (got -0.1)");
    row(
        "world restitution inf", [](Scene& s) { s.world.restitution = kInf; },
        "world.restitution: must be finite");
    row(
        "world friction negative", [](Scene& s) { s.world.friction = -0.5; },
        "world.friction: must be between 0 and 1e6 (got -0.5)");
    row(
        "world friction nan", [](Scene& s) { s.world.friction = kNaN; },
        "world.friction: must be finite");
    row(
        "world rolling resistance inf", [](Scene& s) { s.world.rollingResistance = kInf; },
        "world.rollingResistance: must be finite");
    row(
        "world spinning friction huge", [](Scene& s) { s.world.spinningFriction = 2e6; },
        "world.spinningFriction: must be between 0 and 1e6 (got 2e6)");
    row(
        "tangential restitution high", [](Scene& s) { s.world.tangentialRestitution = 1.5; },
        "world.tangentialRestitution: must be between 0 and 1 (got 1.5)");
    row(
        "tangential restitution negative", [](Scene& s) { s.world.tangentialRestitution = -0.25; },
        "world.tangentialRestitution: must be between 0 and 1 (got -0.25)");
    row(
        "tangential restitution nan", [](Scene& s) { s.world.tangentialRestitution = kNaN; },
        "world.tangentialRestitution: must be finite");

    row(
        "plane point inf", [](Scene& s) { s.planes[0].point.x() = kInf; },
        "planes[0].point: must be finite");
    row(
        "plane point absurd", [](Scene& s) { s.planes[0].point.x() = -2e12; },
        "planes[0].point: must be at most 1e12 in magnitude (got -2e12)");
    row(
        "plane normal zero", [](Scene& s) { s.planes[0].normal = Vec3::Zero(); },
        "planes[0].normal: must not be zero-length");
    row(
        "plane normal tiny", [](Scene& s) { s.planes[0].normal = Vec3(0, 1e-101, 0); },
        "planes[0].normal: must not be zero-length");
    row(
        "plane normal nan", [](Scene& s) { s.planes[0].normal = Vec3(0, kNaN, 0); },
        "planes[0].normal: must be finite");
    row(
        "plane normal absurd", [](Scene& s) { s.planes[0].normal = Vec3(0, 1e300, 0); },
        "planes[0].normal: must be at most 1e12 in magnitude (got 1e300)");
    row(
        "plane restitution high", [](Scene& s) { s.planes[0].restitution = 2.0; },
        "planes[0].restitution: must be between 0 and 1 (got 2)");
    row(
        "plane friction negative", [](Scene& s) { s.planes[0].friction = -1.0; },
        "planes[0].friction: must be between 0 and 1e6 (got -1)");
    row(
        "plane rolling resistance nan", [](Scene& s) { s.planes[0].rollingResistance = kNaN; },
        "planes[0].rollingResistance: must be finite");
    row(
        "plane colour name", [](Scene& s) { s.planes[0].color = "red"; },
        "planes[0].color: must be empty or \"#rrggbb\" (got \"red\")");
    row(
        "plane colour bad digit", [](Scene& s) { s.planes[0].color = "#12345g"; },
        "planes[0].color: must be empty or \"#rrggbb\" (got \"#12345g\")");
    row(
        "plane colour short", [](Scene& s) { s.planes[0].color = "#abc"; },
        "planes[0].color: must be empty or \"#rrggbb\" (got \"#abc\")");

    row(
        "cylinder point nan", [](Scene& s) { s.cylinders[0].point.z() = kNaN; },
        "cylinders[0].point: must be finite");
    row(
        "cylinder axis zero", [](Scene& s) { s.cylinders[0].axis = Vec3::Zero(); },
        "cylinders[0].axis: must not be zero-length");
    row(
        "cylinder radius zero", [](Scene& s) { s.cylinders[0].radius = 0; },
        "cylinders[0].radius: must be positive (got 0)");
    row(
        "cylinder radius negative", [](Scene& s) { s.cylinders[0].radius = -2; },
        "cylinders[0].radius: must be positive (got -2)");
    row(
        "cylinder radius tiny", [](Scene& s) { s.cylinders[0].radius = 1e-13; },
        "cylinders[0].radius: must be at least 1e-12 (got 1e-13)");
    row(
        "cylinder radius absurd", [](Scene& s) { s.cylinders[0].radius = 1e300; },
        "cylinders[0].radius: must be at most 1e12 in magnitude (got 1e300)");
    row(
        "cylinder radius inf", [](Scene& s) { s.cylinders[0].radius = kInf; },
        "cylinders[0].radius: must be finite");
    row(
        "cylinder restitution low", [](Scene& s) { s.cylinders[0].restitution = -1.0; },
        "cylinders[0].restitution: must be between 0 and 1 (got -1)");
    row(
        "cylinder spinning friction negative",
        [](Scene& s) { s.cylinders[0].spinningFriction = -1e-3; },
        "cylinders[0].spinningFriction: must be between 0 and 1e6 (got -0.001)");
    row(
        "cylinder friction inf", [](Scene& s) { s.cylinders[0].friction = kInf; },
        "cylinders[0].friction: must be finite");
    row(
        "cylinder colour", [](Scene& s) { s.cylinders[0].color = "#1234567"; },
        "cylinders[0].color: must be empty or \"#rrggbb\" (got \"#1234567\")");

    row(
        "ball position nan", [](Scene& s) { s.balls[1].position.y() = kNaN; },
        "balls[1].position: must be finite");
    row(
        "ball position absurd", [](Scene& s) { s.balls[1].position.x() = 1e300; },
        "balls[1].position: must be at most 1e12 in magnitude (got 1e300)");
    row(
        "ball velocity inf", [](Scene& s) { s.balls[1].velocity.z() = kInf; },
        "balls[1].velocity: must be finite");
    row(
        "ball velocity absurd", [](Scene& s) { s.balls[1].velocity.z() = -1e13; },
        "balls[1].velocity: must be at most 1e12 in magnitude (got -1e13)");
    row(
        "ball angular velocity nan", [](Scene& s) { s.balls[1].angularVelocity.x() = kNaN; },
        "balls[1].angularVelocity: must be finite");
    row(
        "ball angular velocity inf", [](Scene& s) { s.balls[1].angularVelocity.y() = -kInf; },
        "balls[1].angularVelocity: must be finite");
    row(
        "ball angular velocity absurd", [](Scene& s) { s.balls[1].angularVelocity.z() = 1e13; },
        "balls[1].angularVelocity: must be at most 1e12 in magnitude (got 1e13)");
    row(
        "ball radius zero", [](Scene& s) { s.balls[1].radius = 0; },
        "balls[1].radius: must be positive (got 0)");
    row(
        "ball radius negative", [](Scene& s) { s.balls[1].radius = -1; },
        "balls[1].radius: must be positive (got -1)");
    row(
        "ball radius nan", [](Scene& s) { s.balls[1].radius = kNaN; },
        "balls[1].radius: must be finite");
    row(
        "ball radius tiny", [](Scene& s) { s.balls[1].radius = 1e-15; },
        "balls[1].radius: must be at least 1e-12 (got 1e-15)");
    row(
        "ball mass zero", [](Scene& s) { s.balls[1].mass = 0; },
        "balls[1].mass: must be positive (got 0)");
    row(
        "ball mass negative", [](Scene& s) { s.balls[1].mass = -1; },
        "balls[1].mass: must be positive (got -1)");
    row(
        "ball mass huge", [](Scene& s) { s.balls[1].mass = 1e31; },
        "balls[1].mass: must be between 1e-30 and 1e30 (got 1e31)");
    row(
        "ball mass tiny", [](Scene& s) { s.balls[1].mass = 1e-31; },
        "balls[1].mass: must be between 1e-30 and 1e30 (got 1e-31)");
    row(
        "ball mass inf", [](Scene& s) { s.balls[1].mass = kInf; }, "balls[1].mass: must be finite");
    row(
        "ball restitution high", [](Scene& s) { s.balls[1].restitution = 1.5; },
        "balls[1].restitution: must be between 0 and 1 (got 1.5)");
    row(
        "ball restitution nan", [](Scene& s) { s.balls[1].restitution = kNaN; },
        "balls[1].restitution: must be finite");
    row(
        "ball friction huge", [](Scene& s) { s.balls[1].friction = 1e7; },
        "balls[1].friction: must be between 0 and 1e6 (got 1e7)");
    row(
        "ball rolling resistance negative", [](Scene& s) { s.balls[1].rollingResistance = -2; },
        "balls[1].rollingResistance: must be between 0 and 1e6 (got -2)");
    row(
        "ball spinning friction nan", [](Scene& s) { s.balls[1].spinningFriction = kNaN; },
        "balls[1].spinningFriction: must be finite");
    row(
        "ball colour", [](Scene& s) { s.balls[1].color = "blue"; },
        "balls[1].color: must be empty or \"#rrggbb\" (got \"blue\")");

    row(
        "ball overlaps ball", [](Scene& s) { s.balls[1].position = Vec3(0.9, 1, 0); },
        "balls[1].position: overlaps balls[0] by 0.1");
    row(
        "ball overlaps plane", [](Scene& s) { s.balls[1].position = Vec3(2, 0.45, 0); },
        "balls[1].position: overlaps planes[0] by 0.05");
    row(
        "ball behind plane", [](Scene& s) { s.balls[1].position = Vec3(2, -0.1, 0); },
        "balls[1].position: overlaps planes[0] (is 0.1 behind its surface)");
    row(
        "ball overlaps cylinder", [](Scene& s) { s.balls[1].position = Vec3(4.1, 1, 7); },
        "balls[1].position: overlaps cylinders[0] by 0.1");
    row(
        "ball inside cylinder", [](Scene& s) { s.balls[1].position = Vec3(5, 1, -3); },
        "balls[1].position: overlaps cylinders[0] by 1");
    row(
        "box centre nan", [](Scene& s) { s.boxes[0].center.y() = kNaN; },
        "boxes[0].center: must be finite");
    row(
        "box half extent negative", [](Scene& s) { s.boxes[0].halfExtents.z() = -1; },
        "boxes[0].halfExtents[2]: must be positive (got -1)");
    row(
        "box half extent tiny", [](Scene& s) { s.boxes[0].halfExtents.x() = 1e-13; },
        "boxes[0].halfExtents[0]: must be at least 1e-12 (got 1e-13)");
    row(
        "box rotation axis zero",
        [](Scene& s) {
          s.boxes[0].rotation = carom::Rotation{Vec3::Zero(), 30};
        },
        "boxes[0].rotation.axis: must not be zero-length");
    row(
        "box rotation degrees inf",
        [](Scene& s) {
          s.boxes[0].rotation = carom::Rotation{Vec3::UnitX(), kInf};
        },
        "boxes[0].rotation.degrees: must be finite");
    row(
        "box restitution high", [](Scene& s) { s.boxes[0].restitution = 2; },
        "boxes[0].restitution: must be between 0 and 1 (got 2)");
    row(
        "box rolling resistance negative", [](Scene& s) { s.boxes[0].rollingResistance = -0.5; },
        "boxes[0].rollingResistance: must be between 0 and 1e6 (got -0.5)");
    row(
        "box friction huge", [](Scene& s) { s.boxes[0].friction = 1.5e6; },
        "boxes[0].friction: must be between 0 and 1e6 (got 1500000)");
    row(
        "ball overlaps box", [](Scene& s) { s.balls[1].position = Vec3(-4.25, 1, 0); },
        "balls[1].position: overlaps boxes[0] by 0.25");
    row(
        "ball inside box", [](Scene& s) { s.balls[1].position = Vec3(-5, 1.25, 0); },
        "balls[1].position: overlaps boxes[0] by 0.75");
    row(
        "ball over a turned box's edge",
        [](Scene& s) {
          // Turned 90 degrees about y the cube is the same cube: the same overlap.
          s.boxes[0].rotation = carom::Rotation{Vec3(0, 3, 0), 90};
          s.balls[1].position = Vec3(-4.25, 1, 0);
        },
        "balls[1].position: overlaps boxes[0] by 0.25");

    row(
        "earlier ball overlaps later", [](Scene& s) { s.balls[0].position = Vec3(1.2, 1, 0); },
        "balls[1].position: overlaps balls[0] by 0.2");
    row(
        "overlap with unnormalised directions",
        [](Scene& s) {
          s.planes[0].normal = Vec3(0, 1e-3, 0);
          s.cylinders[0].axis = Vec3(0, 0, -40);
          s.balls[1].position = Vec3(4.2, 1, 0);
        },
        "balls[1].position: overlaps cylinders[0] by 0.2");
  }

  void badValue() {
    QFETCH(SceneEdit, edit);
    QFETCH(QString, error);
    Scene scene = baseScene();
    edit(scene);
    QCOMPARE(texts(carom::validateScene(scene)), QStringList{error});
  }

  // Touching is allowed up to kTouchFraction of the radius (sum); just past it is an overlap.
  void touching_data() {
    QTest::addColumn<SceneEdit>("edit");
    QTest::addColumn<bool>("valid");

    const double within = 0.5 * carom::tolerance::kTouchFraction;
    const double beyond = 2.0 * carom::tolerance::kTouchFraction;
    QTest::newRow("ball on ball") << SceneEdit([](Scene& s) { s.balls[1].position.x() = 1.0; })
                                  << true;
    QTest::newRow("ball on ball within tolerance")
        << SceneEdit([=](Scene& s) { s.balls[1].position.x() = 1.0 - within; }) << true;
    QTest::newRow("ball on ball beyond tolerance")
        << SceneEdit([=](Scene& s) { s.balls[1].position.x() = 1.0 - beyond; }) << false;
    QTest::newRow("ball on floor")
        << SceneEdit([](Scene& s) { s.balls[1].position.y() = 0.5; }) << true;
    QTest::newRow("ball on floor within tolerance")
        << SceneEdit([=](Scene& s) { s.balls[1].position.y() = 0.5 - 0.5 * within; }) << true;
    QTest::newRow("ball on floor beyond tolerance")
        << SceneEdit([=](Scene& s) { s.balls[1].position.y() = 0.5 - 0.5 * beyond; }) << false;
    QTest::newRow("ball on cylinder")
        << SceneEdit([](Scene& s) { s.balls[1].position = Vec3(4, 1, 3); }) << true;
    QTest::newRow("ball on cylinder beyond tolerance")
        << SceneEdit([=](Scene& s) { s.balls[1].position = Vec3(4 + beyond, 1, 3); }) << false;
    QTest::newRow("cradle row") << SceneEdit([](Scene& s) {
      s.balls.clear();
      for (int i = 0; i < 5; ++i) s.balls.push_back(makeBall(Vec3(0.2 * i, 1, 0), 0.1));
    }) << true;
  }

  void touching() {
    QFETCH(SceneEdit, edit);
    QFETCH(bool, valid);
    Scene scene = baseScene();
    edit(scene);
    const auto errors = carom::validateScene(scene);
    QCOMPARE(errors.empty(), valid);
    if (!valid) QVERIFY(QString::fromStdString(errors.front().message).startsWith("overlaps "));
  }

  void tooMany_data() {
    QTest::addColumn<SceneEdit>("edit");
    QTest::addColumn<QString>("error");
    QTest::newRow("balls") << SceneEdit([](Scene& s) {
      s.balls.resize(carom::tolerance::kMaxBalls + 1);
    }) << "balls: must have at most 1000000 entries (got 1000001)";
    QTest::newRow("planes") << SceneEdit([](Scene& s) {
      s.planes.resize(carom::tolerance::kMaxPlanes + 1);
    }) << "planes: must have at most 10000 entries (got 10001)";
    QTest::newRow("cylinders") << SceneEdit([](Scene& s) {
      s.cylinders.resize(carom::tolerance::kMaxCylinders + 1);
    }) << "cylinders: must have at most 10000 entries (got 10001)";
    QTest::newRow("boxes") << SceneEdit([](Scene& s) {
      s.boxes.resize(carom::tolerance::kMaxBoxes + 1);
    }) << "boxes: must have at most 10000 entries (got 10001)";
  }

  // Counts are checked before anything else, so even a million coincident balls are refused at
  // once rather than compared pair by pair.
  void tooMany() {
    QFETCH(SceneEdit, edit);
    QFETCH(QString, error);
    Scene scene;
    scene.world.timeStep = -1;  // not reported: counts come first and stop validation
    edit(scene);
    const auto errors = carom::validateScene(scene);
    QCOMPARE(texts(errors), QStringList{error});
  }

  void exactlyAtTheLimits() {
    Scene scene;
    scene.planes.resize(carom::tolerance::kMaxPlanes);
    for (Plane& plane : scene.planes) plane.point = Vec3(0, -10, 0);
    QVERIFY(carom::validateScene(scene).empty());
  }

  // Friction coefficients from 0 to kMaxFriction, β from 0 to 1 and any angular velocity within
  // the magnitude limit are accepted, on the world and on every kind of object; the check of an
  // edit refuses what the whole scene's does.
  void frictionLimitsHoldForScenesAndEdits() {
    constexpr double kMax = carom::tolerance::kMaxFriction;
    for (const double coefficient : {0.0, kMax}) {
      Scene scene = baseScene();
      carom::World& world = scene.world;
      world.friction = world.rollingResistance = world.spinningFriction = coefficient;
      world.tangentialRestitution = coefficient == 0.0 ? 0.0 : 1.0;
      const auto give = [coefficient](carom::ObjectInfo& info) {
        info.friction = info.rollingResistance = info.spinningFriction = coefficient;
      };
      give(scene.planes[0]);
      give(scene.cylinders[0]);
      give(scene.boxes[0]);
      give(scene.balls[0]);
      scene.balls[0].angularVelocity = Vec3(-1e12, 0, 1e12);
      QCOMPARE(texts(carom::validateScene(scene)), QStringList());
      QCOMPARE(texts(carom::validateObjects(scene, {{0}, {0}, {0}, {0}})), QStringList());
    }
    Scene bad = baseScene();
    bad.boxes[0].spinningFriction = -1;
    bad.balls[1].angularVelocity.x() = kNaN;
    const QStringList refused{"boxes[0].spinningFriction: must be between 0 and 1e6 (got -1)",
                              "balls[1].angularVelocity: must be finite"};
    QCOMPARE(texts(carom::validateScene(bad)), refused);
    QCOMPARE(texts(carom::validateObjects(bad, {{}, {}, {0}, {1}})), refused);
  }

  // A name is limited in characters (code points of its UTF-8), for every kind of object, with
  // the field's path; the same from the check of an edit's objects alone.
  void namesOverTheLimitAreRefused_data() {
    QTest::addColumn<SceneEdit>("edit");
    QTest::addColumn<QString>("error");
    const std::string tooLong(carom::tolerance::kMaxNameCharacters + 1, 'n');
    QTest::newRow("plane") << SceneEdit([tooLong](Scene& s) { s.planes[0].name = tooLong; })
                           << "planes[0].name: must be at most 256 characters (got 257)";
    QTest::newRow("cylinder") << SceneEdit([tooLong](Scene& s) { s.cylinders[0].name = tooLong; })
                              << "cylinders[0].name: must be at most 256 characters (got 257)";
    QTest::newRow("box") << SceneEdit([tooLong](Scene& s) { s.boxes[0].name = tooLong; })
                         << "boxes[0].name: must be at most 256 characters (got 257)";
    QTest::newRow("ball") << SceneEdit([tooLong](Scene& s) { s.balls[1].name = tooLong; })
                          << "balls[1].name: must be at most 256 characters (got 257)";
    QTest::newRow("30,000 characters")
        << SceneEdit([](Scene& s) { s.balls[0].name = std::string(30'000, 'x'); })
        << "balls[0].name: must be at most 256 characters (got 30000)";
    // "é" is two bytes: 257 of them are 514 bytes, counted as 257 characters.
    QTest::newRow("two-byte characters") << SceneEdit([](Scene& s) {
      for (int i = 0; i < 257; ++i) s.balls[1].name += "\u00e9";
    }) << "balls[1].name: must be at most 256 characters (got 257)";
    QTest::newRow("four-byte characters") << SceneEdit([](Scene& s) {
      for (int i = 0; i < 300; ++i) s.planes[0].name += "\U0001F3B1";
    }) << "planes[0].name: must be at most 256 characters (got 300)";
  }

  void namesOverTheLimitAreRefused() {
    QFETCH(SceneEdit, edit);
    QFETCH(QString, error);
    Scene scene = baseScene();
    edit(scene);
    QCOMPARE(texts(carom::validateScene(scene)), QStringList{error});
    const carom::SceneObjectIndices all{{0}, {0}, {0}, {0, 1}};
    QCOMPARE(texts(carom::validateObjects(scene, all)), QStringList{error});
  }

  void namesAtTheLimitAreAccepted() {
    Scene scene = baseScene();
    const std::size_t limit = carom::tolerance::kMaxNameCharacters;
    scene.planes[0].name = std::string(limit, 'p');
    scene.cylinders[0].name = std::string(limit, 'c');
    for (std::size_t i = 0; i < limit; ++i) scene.boxes[0].name += "\u00e9";      // 512 bytes
    for (std::size_t i = 0; i < limit; ++i) scene.balls[0].name += "\u4e2d";      // 768 bytes
    for (std::size_t i = 0; i < limit; ++i) scene.balls[1].name += "\U0001F3B1";  // 1,024 bytes
    QCOMPARE(texts(carom::validateScene(scene)), QStringList());
    QCOMPARE(texts(carom::validateObjects(scene, {{0}, {0}, {0}, {0, 1}})), QStringList());
  }

  // A wrong colour is quoted in its message, but a long one only in part: the message stays a
  // line whatever the file holds.
  void longColoursAreQuotedInPart() {
    Scene scene = baseScene();
    scene.balls[1].color = "#" + std::string(10'000'000, 'z');
    QCOMPARE(texts(carom::validateScene(scene)),
             QStringList{"balls[1].color: must be empty or \"#rrggbb\" (got \"#" +
                         QString(31, 'z') + "\u2026\")"});
    // Cut between characters, never inside one.
    scene.balls[1].color = std::string(31, '#');
    for (int i = 0; i < 40; ++i) scene.balls[1].color += "\u00e9";
    QCOMPARE(texts(carom::validateScene(scene)),
             QStringList{"balls[1].color: must be empty or \"#rrggbb\" (got \"" + QString(31, '#') +
                         "\u00e9\u2026\")"});
  }

  // Beside the file's words, each error says what it is about as data, for the window to word
  // it (ui/editor/validation_text.h): the problem, the object and field, the other object of an
  // overlap, and the numbers.
  void errorsCarryWhatTheyAreAbout() {
    using carom::ValidationError;
    using carom::ValidationObject;
    using F = carom::ValidationField;
    using P = carom::ValidationProblem;
    using S = carom::ValidationSubject;
    const auto only = [](const std::vector<ValidationError>& errors) {
      return errors.size() == 1 ? errors.front() : ValidationError{};
    };
    const auto edited = [](const SceneEdit& edit) {
      Scene scene = baseScene();
      edit(scene);
      return scene;
    };

    ValidationError e =
        only(carom::validateScene(edited([](Scene& s) { s.balls[1].radius = -1; })));
    QCOMPARE(e.path, std::string("balls[1].radius"));
    QCOMPARE(e.problem, P::NotPositive);
    QVERIFY(e.object == (ValidationObject{S::Balls, 1}));
    QCOMPARE(e.field, F::Radius);
    QCOMPARE(e.value, -1.0);
    QVERIFY(!e.other);

    e = only(carom::validateScene(edited([](Scene& s) { s.balls[0].mass = 1e31; })));
    QCOMPARE(e.problem, P::NotBetween);
    QCOMPARE(e.field, F::Mass);
    QCOMPARE(e.value, 1e31);
    QCOMPARE(e.low, carom::tolerance::kMinMass);
    QCOMPARE(e.high, carom::tolerance::kMaxMass);

    e = only(carom::validateScene(edited([](Scene& s) { s.cylinders[0].radius = 1e-13; })));
    QCOMPARE(e.problem, P::TooSmall);
    QVERIFY(e.object == (ValidationObject{S::Cylinders, 0}));
    QCOMPARE(e.low, carom::tolerance::kMinRadius);

    e = only(carom::validateScene(edited([](Scene& s) { s.boxes[0].halfExtents.y() = 0; })));
    QCOMPARE(e.path, std::string("boxes[0].halfExtents[1]"));
    QCOMPARE(e.field, F::HalfExtentY);

    e = only(carom::validateScene(edited([](Scene& s) { s.world.gravity.z() = 1e300; })));
    QCOMPARE(e.problem, P::TooLarge);
    QVERIFY(e.object == (ValidationObject{S::World, std::nullopt}));
    QCOMPARE(e.field, F::Gravity);
    QCOMPARE(e.value, 1e300);
    QCOMPARE(e.high, carom::tolerance::kMaxMagnitude);

    e = only(carom::validateScene(edited([](Scene& s) { s.planes[0].normal = Vec3::Zero(); })));
    QCOMPARE(e.problem, P::ZeroLength);
    QCOMPARE(e.field, F::Normal);

    e = only(carom::validateScene(edited([](Scene& s) { s.planes[0].color = "red"; })));
    QCOMPARE(e.problem, P::BadColor);
    QCOMPARE(e.field, F::Color);
    QCOMPARE(e.quoted, std::string("red"));

    e = only(carom::validateScene(edited([](Scene& s) { s.boxes[0].friction = -1; })));
    QCOMPARE(e.problem, P::NotBetween);
    QVERIFY(e.object == (ValidationObject{S::Boxes, 0}));
    QCOMPARE(e.field, F::Friction);
    QCOMPARE(e.low, 0.0);
    QCOMPARE(e.high, carom::tolerance::kMaxFriction);
    e = only(carom::validateScene(edited([](Scene& s) { s.world.spinningFriction = kInf; })));
    QCOMPARE(e.problem, P::NotFinite);
    QCOMPARE(e.field, F::SpinningFriction);
    e = only(carom::validateScene(edited([](Scene& s) { s.planes[0].rollingResistance = 2e6; })));
    QCOMPARE(e.field, F::RollingResistance);
    e = only(carom::validateScene(edited([](Scene& s) { s.world.tangentialRestitution = 2; })));
    QCOMPARE(e.path, std::string("world.tangentialRestitution"));
    QCOMPARE(e.field, F::TangentialRestitution);
    QCOMPARE(e.high, 1.0);
    e = only(
        carom::validateScene(edited([](Scene& s) { s.balls[0].angularVelocity.y() = -2e12; })));
    QCOMPARE(e.problem, P::TooLarge);
    QCOMPARE(e.field, F::AngularVelocity);
    QCOMPARE(e.value, -2e12);

    e = only(
        carom::validateScene(edited([](Scene& s) { s.balls[0].name = std::string(300, 'n'); })));
    QCOMPARE(e.problem, P::NameTooLong);
    QCOMPARE(e.value, 300.0);
    QCOMPARE(e.high, double(carom::tolerance::kMaxNameCharacters));

    // Overlaps name the ball and what it overlaps, by how much.
    e = only(carom::validateScene(edited([](Scene& s) { s.balls[1].position.y() = 0.2; })));
    QCOMPARE(e.problem, P::Overlaps);
    QVERIFY(e.object == (ValidationObject{S::Balls, 1}));
    QCOMPARE(e.field, F::None);
    QVERIFY(e.other == (ValidationObject{S::Planes, 0}));
    QVERIFY(std::abs(e.value - 0.3) < 1e-12);
    e = only(carom::validateScene(edited([](Scene& s) { s.balls[1].position.y() = -1; })));
    QCOMPARE(e.problem, P::BehindSurface);
    QCOMPARE(e.value, 1.0);
    const Scene pair = edited([](Scene& s) { s.balls[1].position.x() = 0.5; });
    for (const ValidationError& error : {only(carom::validateScene(pair)),
                                         only(carom::validateObjects(pair, {{}, {}, {}, {0}}))}) {
      QCOMPARE(error.problem, P::Overlaps);
      QVERIFY(error.object == (ValidationObject{S::Balls, 1}));
      QVERIFY(error.other == (ValidationObject{S::Balls, 0}));
      QCOMPARE(error.value, 0.5);
    }
    e = only(carom::validateScene(edited([](Scene& s) { s.balls[1].position = Vec3(5, 1, 0.9); })));
    QVERIFY(e.other == (ValidationObject{S::Cylinders, 0}));
    e = only(
        carom::validateScene(edited([](Scene& s) { s.balls[1].position = Vec3(-4.2, 1, 0); })));
    QVERIFY(e.other == (ValidationObject{S::Boxes, 0}));

    // A whole list, and a tolerance given alone.
    e = only(carom::validateCounts({.balls = carom::tolerance::kMaxBalls + 1}));
    QCOMPARE(e.problem, P::TooMany);
    QVERIFY(e.object == (ValidationObject{S::Balls, std::nullopt}));
    QCOMPARE(e.value, double(carom::tolerance::kMaxBalls + 1));
    QCOMPARE(e.high, double(carom::tolerance::kMaxBalls));
    e = only(carom::validateTolerance({0.0, 0.1}));
    QCOMPARE(e.path, std::string("tolerance.energy"));
    QCOMPARE(e.problem, P::NotAboveZero);
    QVERIFY(e.object == (ValidationObject{S::Tolerance, std::nullopt}));
    QCOMPARE(e.field, F::EnergyTolerance);
  }

  void errorsComeInFileOrder() {
    Scene scene = baseScene();
    scene.balls.push_back(makeBall(Vec3(2.5, 1, 0), 0.5));  // overlaps balls[1]
    scene.balls[0].radius = -1;
    scene.cylinders[0].radius = 0;
    scene.planes[0].color = "green";
    scene.world.restitution = 3;
    scene.world.timeStep = 0;
    QCOMPARE(texts(carom::validateScene(scene)),
             (QStringList{"world.timeStep: must be positive (got 0)",
                          "world.restitution: must be between 0 and 1 (got 3)",
                          "planes[0].color: must be empty or \"#rrggbb\" (got \"green\")",
                          "cylinders[0].radius: must be positive (got 0)",
                          "balls[0].radius: must be positive (got -1)",
                          "balls[2].position: overlaps balls[1] by 0.5"}));
  }

  void oneBallWithSeveralErrors() {
    Scene scene = baseScene();
    Ball& ball = scene.balls[1];
    ball.position = Vec3(0, 0.3, 0);  // overlaps the floor and balls[0]
    QCOMPARE(texts(carom::validateScene(scene)),
             (QStringList{"balls[1].position: overlaps planes[0] by 0.2",
                          "balls[1].position: overlaps balls[0] by 0.3"}));
    ball.velocity.x() = kNaN;
    ball.mass = 0;
    ball.restitution = 7;
    // An object with a bad field takes no part in overlap tests.
    QCOMPARE(
        texts(carom::validateScene(scene)),
        (QStringList{"balls[1].velocity: must be finite", "balls[1].mass: must be positive (got 0)",
                     "balls[1].restitution: must be between 0 and 1 (got 7)"}));
  }

  void eachOverlapOnceOnTheLaterBall() {
    Scene scene;
    scene.balls = {makeBall(Vec3(0, 0, 0), 1), makeBall(Vec3(1, 0, 0), 1),
                   makeBall(Vec3(1.5, 0, 0), 1)};
    QCOMPARE(texts(carom::validateScene(scene)),
             (QStringList{"balls[1].position: overlaps balls[0] by 1",
                          "balls[2].position: overlaps balls[0] by 0.5",
                          "balls[2].position: overlaps balls[1] by 1.5"}));
  }

  void maxErrorsIsRespected() {
    Scene scene;
    for (int i = 0; i < 50; ++i) scene.balls.push_back(makeBall(Vec3(0, 0, 0), -1));
    const auto errors = carom::validateScene(scene, 5);
    QCOMPARE(errors.size(), std::size_t{5});
    QCOMPARE(QString::fromStdString(errors[4].path), QString("balls[4].radius"));
    QCOMPARE(carom::validateScene(scene).size(), std::size_t{20});
    QVERIFY(carom::validateScene(scene, 0).empty());
  }

  // Coincident balls: the errors stop at the limit long before all pairs are looked at.
  void coincidentBallsStopAtTheLimit() {
    Scene scene;
    scene.balls.assign(200'000, makeBall(Vec3(1, 2, 3), 0.5));
    const auto errors = carom::validateScene(scene, 3);
    QCOMPARE(texts(errors), (QStringList{"balls[1].position: overlaps balls[0] by 1",
                                         "balls[2].position: overlaps balls[0] by 1",
                                         "balls[2].position: overlaps balls[1] by 1"}));
  }

  // The grid against the obvious all-pairs test, over radii spanning three orders of magnitude
  // and positions far from the origin.
  void overlapsMatchBruteForce_data() {
    QTest::addColumn<double>("offset");
    QTest::addColumn<double>("smallestRadius");
    QTest::newRow("near origin") << 0.0 << 0.01;
    QTest::newRow("far away") << 3e11 << 0.01;
    QTest::newRow("tiny balls off the origin") << -5e5 << 1e-9;
  }

  void overlapsMatchBruteForce() {
    QFETCH(double, offset);
    QFETCH(double, smallestRadius);
    std::mt19937_64 random(12345);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double boxSide = 200 * smallestRadius;
    Scene scene;
    for (int i = 0; i < 1500; ++i) {
      const Vec3 position =
          Vec3(unit(random), unit(random), unit(random)) * boxSide + Vec3::Constant(offset);
      const double radius = smallestRadius * std::pow(10.0, 3.0 * std::pow(unit(random), 6.0));
      scene.balls.push_back(makeBall(position, radius));
    }
    // Exactly touching pairs, in the same class and across classes.
    scene.balls.push_back(makeBall(scene.balls[3].position + Vec3(scene.balls[3].radius * 2, 0, 0),
                                   scene.balls[3].radius));
    scene.balls.push_back(
        makeBall(scene.balls[5].position - Vec3(0, scene.balls[5].radius + smallestRadius, 0),
                 smallestRadius));

    QStringList found;
    for (const auto& error : carom::validateScene(scene, 1'000'000)) {
      QString text = QString::fromStdString(error.text());
      found << text.left(text.lastIndexOf(" by "));
    }
    const QStringList expected = bruteForceOverlaps(scene.balls);
    QVERIFY(expected.size() > 50);  // the case must exercise the grid
    QCOMPARE(found, expected);
  }

  // An edit is checked on the objects it touches only (validateObjects): from a valid scene,
  // random edits of a few objects (moves into and out of overlaps, bad values, appended
  // objects) must give exactly the errors validateScene gives for the whole edited scene.
  void editChecksMatchTheWholeScene() {
    std::mt19937_64 random(777);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Scene valid;
    Plane floor;
    valid.planes.push_back(floor);
    Plane wall;
    wall.point = Vec3(10, 0, 0);
    wall.normal = Vec3(-1, 0, 0);
    valid.planes.push_back(wall);
    Cylinder post;
    post.point = Vec3(5, 0, 5);
    post.radius = 0.5;
    valid.cylinders.push_back(post);
    carom::Box block;
    block.center = Vec3(2, 1, 7);
    block.halfExtents = Vec3(0.8, 0.4, 0.6);
    block.rotation = carom::Rotation{Vec3(1, 1, 0), 25};
    valid.boxes.push_back(block);
    while (valid.balls.size() < 200) {
      Ball ball = makeBall(Vec3(unit(random) * 9, 0.3 + unit(random) * 5, unit(random) * 9),
                           0.1 + 0.2 * unit(random));
      Scene attempt = valid;
      attempt.balls.push_back(ball);
      if (carom::validateScene(attempt, 1).empty()) valid = attempt;
    }
    const auto randomPoint = [&] {
      return Vec3(unit(random) * 11 - 0.5, unit(random) * 6 - 0.5, unit(random) * 11 - 0.5);
    };
    int failing = 0;
    for (int trial = 0; trial < 400; ++trial) {
      Scene edited = valid;
      carom::SceneObjectIndices touched;
      const int edits = 1 + int(unit(random) * 3);
      for (int e = 0; e < edits; ++e) {
        const double what = unit(random);
        if (what < 0.5) {
          const std::size_t i = std::size_t(unit(random) * edited.balls.size());
          edited.balls[i].position = randomPoint();
          if (unit(random) < 0.1) edited.balls[i].radius = unit(random) < 0.5 ? -1.0 : kNaN;
          touched.balls.push_back(i);
        } else if (what < 0.65) {
          edited.balls.push_back(makeBall(randomPoint(), 0.2));
          touched.balls.push_back(edited.balls.size() - 1);
        } else if (what < 0.7) {
          edited.boxes[0].center = randomPoint();
          edited.boxes[0].halfExtents = Vec3(0.2 + unit(random), 0.2 + unit(random), 0.3);
          if (unit(random) < 0.1) edited.boxes[0].halfExtents.y() = -0.5;
          touched.boxes.push_back(0);
        } else if (what < 0.8) {
          const std::size_t i = std::size_t(unit(random) * edited.planes.size());
          edited.planes[i].point.y() = unit(random) * 0.6 - 0.3;
          if (unit(random) < 0.1) edited.planes[i].normal = Vec3::Zero();
          touched.planes.push_back(i);
        } else {
          edited.cylinders[0].point = randomPoint();
          edited.cylinders[0].radius = 0.2 + unit(random);
          touched.cylinders.push_back(0);
        }
      }
      // Now and then every ball is listed (as Use Current State does), which takes the check of
      // the whole scene.
      if (trial % 25 == 0)
        for (std::size_t i = 0; i < edited.balls.size(); ++i) touched.balls.push_back(i);
      const QStringList whole = texts(carom::validateScene(edited, 1000));
      QCOMPARE(texts(carom::validateObjects(edited, touched, 1000)), whole);
      QCOMPARE(texts(carom::validateObjects(edited, touched, 1)), whole.mid(0, 1));
      failing += !whole.isEmpty();
    }
    // Both outcomes must have been exercised.
    QVERIFY2(failing > 50 && failing < 350, qPrintable(QString::number(failing)));
  }

  // 200,000 touching balls on a lattice and one intruder: exactly the intruder's eight overlaps
  // are found (touching neighbours are not overlaps). All pairs would be 2e10 comparisons: this
  // finishes only because the test is not all-pairs.
  void largeSceneFindsTheIntruder() {
    const auto errors = validateLattice(200'000);
    QCOMPARE(errors.size(), std::size_t{8});
    for (const auto& error : errors)
      QCOMPARE(QString::fromStdString(error.path), QString("balls[200000].position"));
  }

 private:
  // `count` touching balls of radius 0.5 on a unit lattice, one ball in the middle of a lattice
  // cell (overlapping its 8 corners) and one huge ball far away in a size class of its own.
  static std::vector<carom::ValidationError> validateLattice(int count) {
    Scene scene;
    const int side = 60;
    for (int i = 0; i < count; ++i)
      scene.balls.push_back(makeBall(Vec3(i % side, (i / side) % side, i / (side * side)), 0.5));
    scene.balls.push_back(makeBall(Vec3(10.5, 20.5, 2.5), 0.5));
    scene.balls.push_back(makeBall(Vec3(1e6, 0, 0), 1e4));
    return carom::validateScene(scene);
  }
};

QTEST_APPLESS_MAIN(ValidationTest)
#include "test_validation.moc"
