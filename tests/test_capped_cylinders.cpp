// Capped cylinders in a running simulation: bounces off the side, the caps and the rims with the
// closed-form time and direction, a ball coming to rest on a cap, energy kept in an elastic scene
// of balls, boxes and capped cylinders, and no ball ever inside a solid, under every method.

#include "scene_helpers.h"
#include "sim/measures.h"
#include "sim/scene_builders.h"
#include "sim/simulation.h"
#include "sim/validation.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <random>

using namespace carom;
using carom::testing::makeBall;
using carom::testing::makeBox;
using carom::testing::makeCylinder;
using carom::testing::makePlane;

namespace {
constexpr double kG = 9.81;

}  // namespace

class TestCappedCylinders : public QObject {
  Q_OBJECT
 private slots:
  // Dropped onto the cap of an upright cylinder: it meets it at t = sqrt(2 h / g), counted as
  // ball-cylinder, and comes back up to where it started.
  void dropOntoTheCap() {
    Scene s = testing::elasticSceneWithGravity();
    s.cylinders.push_back(makeCylinder({0, 0, 0}, {0, 1, 0}, 0.5, 2.0));
    s.balls.push_back(makeBall({0.2, 3.0, -0.1}, {0, 0, 0}, 0.1));
    Simulation sim(s);
    sim.setCollisionLog(true);
    const double fall = std::sqrt(2 * (3.0 - 1.1) / kG);
    sim.advanceTo(1.5 * fall);
    const std::vector<CollisionRecord> hits = sim.takeCollisions();
    QCOMPARE(hits.size(), std::size_t(1));
    QCOMPARE(hits[0].kind, ContactKind::BallCylinder);
    QVERIFY2(std::abs(hits[0].time - fall) < 1e-12, qPrintable(QString::number(hits[0].time)));
    sim.advanceTo(2 * fall);
    QVERIFY2(std::abs(sim.positions()[0].y() - 3.0) < 1e-9,
             qPrintable(QString::number(sim.positions()[0].y(), 'g', 17)));
  }

  // Onto the rim: it bounces along the line from the rim point to its centre.
  void dropOntoTheRimBouncesAlongTheRimLine() {
    Scene s = testing::elasticSceneWithGravity();
    s.cylinders.push_back(makeCylinder({0, 0, 0}, {0, 1, 0}, 0.5, 2.0));
    const double r = 0.2, dx = 0.1;
    s.balls.push_back(makeBall({0.5 + dx, 3.0, 0}, {0, 0, 0}, r));
    Simulation sim(s);
    sim.setCollisionLog(true);
    const double rise = std::sqrt(r * r - dx * dx);
    const double fall = std::sqrt(2 * (3.0 - 1.0 - rise) / kG);
    sim.advanceTo(fall + 1e-6);
    const std::vector<CollisionRecord> hits = sim.takeCollisions();
    QCOMPARE(hits.size(), std::size_t(1));
    QVERIFY2(std::abs(hits[0].time - fall) < 1e-12, qPrintable(QString::number(hits[0].time)));
    const Vec3 n = Vec3(dx, rise, 0) / r;
    const Vec3 before(0, -kG * fall, 0);
    const Vec3 expected = before - 2 * before.dot(n) * n + Vec3(0, -kG * 1e-6, 0);
    QVERIFY2((sim.velocities()[0] - expected).norm() < 1e-9 * before.norm(),
             qPrintable(QString::number((sim.velocities()[0] - expected).norm())));
  }

  // Onto the side of a lying cylinder, and past its end.
  void dropOntoTheSideAndPastTheEnd() {
    Scene s = testing::elasticSceneWithGravity();
    s.cylinders.push_back(makeCylinder({0, 0, 0}, {1, 0, 0}, 0.5, 4.0));
    s.balls.push_back(makeBall({1.9, 3.0, 0}, {0, 0, 0}, 0.2));
    s.balls.push_back(makeBall({2.21, 3.0, 2.0}, {0, 0, 0}, 0.2));
    s.balls.push_back(makeBall({2.21, 3.0, 0}, {0, 0, 0}, 0.2));
    Simulation sim(s);
    sim.setCollisionLog(true);
    const double fall = std::sqrt(2 * (3.0 - 0.7) / kG);
    sim.advanceTo(1.0);
    const std::vector<CollisionRecord> hits = sim.takeCollisions();
    QCOMPARE(hits.size(), std::size_t(1));
    QCOMPARE(hits[0].ball, 0);
    QVERIFY2(std::abs(hits[0].time - fall) < 1e-12, qPrintable(QString::number(hits[0].time)));
  }

  // An inelastic ball dropped onto a cap comes to rest on it, touching it.
  void inelasticBallRestsOnACap_data() { testing::addMethodRows({Method::Exact, Method::Swept}); }
  void inelasticBallRestsOnACap() {
    QFETCH(int, method);
    Scene s = testing::elasticSceneWithGravity();
    s.world.method = Method(method);
    s.world.restitution = 0.6;
    s.cylinders.push_back(makeCylinder({0, 0, 0}, {0, 1, 0}, 0.8, 1.0));
    s.balls.push_back(makeBall({0.1, 2.0, 0.2}, {0, 0, 0}, 0.1));
    Simulation sim(s);
    sim.advanceTo(10.0);
    qDebug("resting after %llu events, %.1e from touching",
           static_cast<unsigned long long>(sim.stats().events), sim.positions()[0].y() - 0.6);
    QVERIFY(sim.state()[0].resting);
    QVERIFY2(std::abs(sim.positions()[0].y() - 0.6) < 1e-9,
             qPrintable(QString::number(sim.positions()[0].y() - 0.6)));
    QVERIFY2(sim.stats().events < 1000, qPrintable(QString::number(sim.stats().events)));
  }

  // Twelve balls in a closed room with two boxes and three capped cylinders (upright, lying and
  // tilted), elastic, under gravity: a million events keep the energy to 1e-9 under `exact`, and
  // no ball is ever inside a solid.
  void elasticRoomOfFiniteShapesKeepsItsEnergy() {
    Scene s = testing::elasticSceneWithGravity();
    for (int a = 0; a < 3; ++a)
      for (const double side : {-1.0, 1.0})
        s.planes.push_back(makePlane(side * 3.0 * Vec3::Unit(a), -side * Vec3::Unit(a)));
    s.boxes.push_back(makeBox({-1.5, -2.0, 0}, {0.8, 0.4, 1.2}));
    s.boxes.push_back(makeBox({1.2, -0.5, 1.0}, {0.5, 0.5, 0.5}, Rotation{{1, 1, 0}, 30.0}));
    s.cylinders.push_back(makeCylinder({1.5, -2.2, -1.5}, {0, 1, 0}, 0.6, 1.2));
    s.cylinders.push_back(makeCylinder({0.0, 1.0, -1.5}, {1, 0, 0}, 0.3, 2.5));
    s.cylinders.push_back(makeCylinder({-1.2, 0.0, 1.5}, {1, 2, -1}, 0.4, 1.5));
    std::mt19937_64 engine(5);
    std::normal_distribution<double> normal;
    for (int k = 0; k < 12; ++k) {
      const Vec3 p(-2.5 + 0.45 * k, 2.5, (k % 3) - 1.0);
      s.balls.push_back(
          makeBall(p, Vec3(normal(engine), normal(engine), normal(engine)) * 3, 0.15));
    }
    QVERIFY(validateScene(s).empty());
    Simulation sim(s);
    const Bodies bodies = makeBodies(s);
    const double before = sim.totalEnergy();
    double worst = 0.0;
    int escaped = 0;
    while (sim.stats().events < 1'000'000) {
      sim.advance(1.0);
      const OverlapReport overlaps = measureOverlaps(bodies, sim.positions());
      worst = std::max(worst, overlaps.maxPenetration);
      escaped += overlaps.escaped;
    }
    qDebug("%llu events in %.0f s: %llu ball-cylinder, %llu ball-box; drift %.2e, deepest %.1e",
           static_cast<unsigned long long>(sim.stats().events), sim.time(),
           static_cast<unsigned long long>(sim.stats().collisions.ballCylinder),
           static_cast<unsigned long long>(sim.stats().collisions.ballBox),
           (sim.totalEnergy() - before) / before, worst);
    QVERIFY2(std::abs(sim.totalEnergy() - before) < 1e-9 * std::abs(before),
             qPrintable(QString::number((sim.totalEnergy() - before) / before)));
    QVERIFY2(sim.stats().collisions.ballCylinder > 10'000,
             qPrintable(QString::number(sim.stats().collisions.ballCylinder)));
    QVERIFY2(worst < 1e-9 && escaped == 0, qPrintable(QString::number(worst)));
  }

  // `discrete` pushes a ball that sank into a cap or a side out by the closest point, and the
  // measures count no ball inside; a fast ball never passes through a thin disc (exact, swept).
  void discreteKeepsBallsOutOfACylinder() {
    Scene s = testing::elasticSceneWithGravity();
    s.world.method = Method::Discrete;
    s.world.restitution = 0.5;
    s.planes.push_back(makePlane({0, 0, 0}, Vec3::UnitY()));
    s.cylinders.push_back(makeCylinder({0, 0.5, 0}, {0, 1, 0}, 0.6, 1.0));
    for (int k = 0; k < 6; ++k)
      s.balls.push_back(makeBall({-0.5 + 0.2 * k, 2.0 + 0.3 * k, 0.1 * (k % 2)}, {0, 0, 0}, 0.08));
    Simulation sim(s);
    sim.advanceTo(5.0);
    const OverlapReport overlaps = measureOverlaps(makeBodies(s), sim.positions());
    QCOMPARE(overlaps.escaped, 0);
    QVERIFY2(overlaps.maxPenetration < 0.08, qPrintable(QString::number(overlaps.maxPenetration)));
    QVERIFY(sim.stats().collisions.ballCylinder > 0);
  }

  void fastBallDoesNotPassThroughAThinDisc_data() {
    testing::addMethodRows({Method::Exact, Method::Swept});
  }
  void fastBallDoesNotPassThroughAThinDisc() {
    QFETCH(int, method);
    for (const double speed : {1.0, 1e3, 1e6}) {
      Scene s;
      s.world.gravity = Vec3::Zero();
      s.world.method = Method(method);
      s.cylinders.push_back(makeCylinder({0, 0, 0}, {1, 0, 0}, 1.0, 0.002));
      s.balls.push_back(makeBall({-2, 0.3, 0.2}, {speed, 0, 0}, 0.05));
      Simulation sim(s);
      sim.advanceTo(4.0 / speed);
      QVERIFY2(sim.positions()[0].x() < 0.0, qPrintable(QString::number(speed)));
      QCOMPARE(sim.stats().collisions.ballCylinder, std::uint64_t(1));
    }
  }
  // The benchmark's Galton board: valid as built, at least 300 finite pegs and boxes for
  // 10,000 balls, and its balls pour through the funnel and pegs without entering any solid.
  void galtonBoardPoursWithoutEnteringASolid() {
    const Scene big = makeGaltonBoard(10000, 1);
    QVERIFY(validateScene(big).empty());
    QVERIFY2(big.cylinders.size() + big.boxes.size() >= 300,
             qPrintable(QString::number(big.cylinders.size() + big.boxes.size())));
    for (const Cylinder& peg : big.cylinders) QVERIFY(peg.length.has_value());
    const Scene scene = makeGaltonBoard(150, 2, 0.02);
    QVERIFY(validateScene(scene).empty());
    Simulation sim(scene);
    double worst = 0.0;
    int escaped = 0;
    for (int k = 1; k <= 40; ++k) {
      sim.advanceTo(0.025 * k);
      const OverlapReport overlaps = measureOverlaps(sim.bodies(), sim.positions());
      worst = std::max(worst, overlaps.maxPenetration);
      escaped += overlaps.escaped;
    }
    QVERIFY(escaped == 0);
    // A ball sliding slowly off the inner end of a funnel board sank into the board's edge here
    // (0.3 mm for 2 cm balls, at t = 0.74 s) until the slide's end looked for the edge at once.
    QVERIFY2(worst < 1e-9 * 0.02, qPrintable(QString::number(worst)));
    // By then the balls have met the funnel, the pegs and one another.
    QVERIFY(sim.stats().collisions.ballBox > 0);
    QVERIFY(sim.stats().collisions.ballCylinder > 0);
    QVERIFY(sim.stats().collisions.ballBall > 0);
  }
};

QTEST_APPLESS_MAIN(TestCappedCylinders)
#include "test_capped_cylinders.moc"
