// Capped cylinders in a running simulation: bounces off the side, the caps and the rims with the
// closed-form time and direction, a ball coming to rest on a cap, energy kept in an elastic scene
// of balls, boxes and capped cylinders, and no ball ever inside a solid, under every method.

#include "scene_helpers.h"
#include "sim/measure/measures.h"
#include "sim/model/scene_builders.h"
#include "sim/simulation.h"
#include "sim/validation/validation.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

using namespace carom;
using carom::testing::makeBall;
using carom::testing::makeBox;
using carom::testing::makeCylinder;
using carom::testing::makePlane;

namespace {
constexpr double kG = 9.81;

// The deepest any ball is inside any cylinder.
double depthInCylinders(const Scene& scene, const std::vector<Vec3>& positions) {
  double depth = 0.0;
  for (const Cylinder& cylinder : scene.cylinders) {
    const CylinderShape shape = cylinderShape(cylinder);
    for (std::size_t i = 0; i < positions.size(); ++i)
      depth = std::max(depth, -shape.contact(positions[i], scene.balls[i].radius).gap);
  }
  return depth;
}

// A capped cylinder (R = 1, length 1) at the origin whose axis is turned by `degrees` from y
// towards x: its axis, the way down its top cap and the cap's centre.
struct TiltedCap {
  Vec3 axis, down, capCentre;
};
TiltedCap tiltedCap(double degrees) {
  const double a = degrees * std::numbers::pi / 180.0;
  const Vec3 axis(std::sin(a), std::cos(a), 0);
  return {axis, Vec3(std::cos(a), -std::sin(a), 0), 0.5 * axis};
}

}  // namespace

class TestCappedCylinders : public QObject {
  Q_OBJECT
 private slots:
  // A 1e-6 m ball on the cap of an upright cylinder 8e11 m up, where its centre rounds onto the
  // cap, inside the cylinder in doubles: it slides across the cap as near the origin (it hopped
  // at the rest speed, 3.5 million times; see test_boxes).
  void smallBallFarOutSlidesAcrossACap_data() {
    testing::addMethodRows({Method::Exact, Method::Swept});
  }
  void smallBallFarOutSlidesAcrossACap() {
    QFETCH(int, method);
    // The same scene near the origin and far out; the far one's heights are relative to its top.
    const auto run = [&](double top, double until) {
      Scene s;
      s.world.gravity = Vec3(0, -9.81, 0);
      s.world.restitution = 0.5;
      s.world.method = Method(method);
      s.cylinders.push_back(makeCylinder({0, top - 1.0, 0}, Vec3::UnitY(), 1e3, 2.0));
      s.balls.push_back(makeBall({0, top + 0.5, 0}, {10, 0, 0}, 1e-6));
      Simulation sim(s);
      sim.advanceTo(until);
      return std::pair{Vec3(sim.positions()[0] - Vec3(0, top, 0)), sim.stats().events};
    };
    // Sliding half way across, in the few events of the bounces before (not millions).
    const auto [far, events] = run(8e11, 50.0);
    QVERIFY2(events < 100, qPrintable(QString::number(events)));
    QVERIFY2(std::abs(far.x() - 500.0) < 1e-9 && far.y() == 0.0,
             qPrintable(QString("%1 %2").arg(far.x(), 0, 'g', 17).arg(far.y(), 0, 'g', 17)));
    // At the rim, where its centre rounds onto the rim's circle, it is stopped by the burst
    // guard instead of falling on (a torus of the ball's radius is below the positions'
    // resolution there), but it does not hop there for ever either.
    const auto [atRim, eventsByThen] = run(8e11, 110.0);
    QVERIFY2(eventsByThen < 200, qPrintable(QString::number(eventsByThen)));
    QVERIFY2(atRim.x() >= 1000.0 - 1e-9, qPrintable(QString::number(atRim.x(), 'g', 17)));
  }

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

  // A ball set sliding across a level cap follows it exactly and leaves its rim on the parabola
  // that starts there, in a few events: the cap is a slide surface, and the slide ends when the
  // centre's distance from the axis reaches the radius (it used to hop at touching height, about
  // a million events, and leave the rim off the parabola).
  void slidesAcrossALevelCapAndLeavesItsRim_data() {
    testing::addMethodRows({Method::Exact, Method::Swept});
  }
  void slidesAcrossALevelCapAndLeavesItsRim() {
    QFETCH(int, method);
    Scene s = testing::elasticSceneWithGravity();
    s.world.method = Method(method);
    s.cylinders.push_back(makeCylinder({0, 0, 0}, {0, 1, 0}, 1.0, 1.0));
    // v^2 = 0.25 across the rim, well above r g: it flies clear of the rim's rounding.
    const double r = 0.01, speed = 0.5, z = 0.3, x0 = -0.5;
    s.balls.push_back(makeBall({x0, 0.5 + r, z}, {speed, 0, 0}, r));
    QVERIFY(validateScene(s).empty());
    Simulation sim(s);
    const double rimX = std::sqrt(1.0 - z * z), rim = (rimX - x0) / speed;
    sim.advanceTo(0.5 * rim);
    const double onCap = (sim.positions()[0] - Vec3(x0 + 0.5 * rim * speed, 0.5 + r, z)).norm();
    const std::uint64_t eventsOnCap = sim.stats().events;
    double worst = 0.0;
    for (const double after : {0.1, 0.25}) {
      sim.advanceTo(rim + after);
      const Vec3 expected(rimX + speed * after, 0.5 + r - 0.5 * kG * after * after, z);
      worst = std::max(worst, (sim.positions()[0] - expected).norm());
    }
    qDebug(
        "%llu events (%llu halfway across), %llu ball-cylinder; off the cap by %.1e halfway, "
        "off the parabola by %.1e",
        static_cast<unsigned long long>(sim.stats().events),
        static_cast<unsigned long long>(eventsOnCap),
        static_cast<unsigned long long>(sim.stats().collisions.ballCylinder), onCap, worst);
    // The stepped method sweeps straight chords below the parabola: an error of the order of one
    // step's kick.
    const bool exact = Method(method) == Method::Exact;
    QVERIFY2(onCap < (exact ? 1e-12 : kG * s.world.timeStep), qPrintable(QString::number(onCap)));
    QVERIFY2(worst < (exact ? 1e-12 : kG * s.world.timeStep), qPrintable(QString::number(worst)));
    if (exact) QVERIFY2(sim.stats().events < 10, qPrintable(QString::number(sim.stats().events)));
  }

  // On a tilted capped cylinder's cap a ball placed at rest slides down the cap as down a ramp,
  // g sin(a) t^2 / 2 along it, and leaves the rim on the parabola that starts there.
  void slidesDownATiltedCapAndLeavesItsRim_data() {
    testing::addMethodRows({Method::Exact, Method::Swept});
  }
  void slidesDownATiltedCapAndLeavesItsRim() {
    QFETCH(int, method);
    Scene s = testing::elasticSceneWithGravity();
    s.world.method = Method(method);
    const double degrees = 20.0, a = degrees * std::numbers::pi / 180.0, r = 0.1;
    const TiltedCap cap = tiltedCap(degrees);
    s.cylinders.push_back(makeCylinder({0, 0, 0}, cap.axis, 1.0, 1.0));
    const Vec3 start = cap.capCentre + r * cap.axis - 0.5 * cap.down;
    s.balls.push_back(makeBall(start, {0, 0, 0}, r));
    QVERIFY(validateScene(s).empty());
    Simulation sim(s);
    const double along = kG * std::sin(a);
    const double rim = std::sqrt(2.0 * 1.5 / along);  // from 0.5 before the centre to R after
    // A stepped method kicks once a step: its slide is off by about a step's kick times the time.
    const bool exact = Method(method) == Method::Exact;
    for (const double t : {0.5, 0.9}) {
      sim.advanceTo(t);
      const double error = (sim.positions()[0] - (start + 0.5 * along * t * t * cap.down)).norm();
      qDebug("at %.1f s: %llu events, off the slide by %.1e", t,
             static_cast<unsigned long long>(sim.stats().events), error);
      QVERIFY2(error < (exact ? 1e-9 : kG * s.world.timeStep * t),
               qPrintable(QString::number(error)));
    }
    if (exact) QVERIFY2(sim.stats().events < 10, qPrintable(QString::number(sim.stats().events)));
    // v^2 = 10 at the rim, far above r g cos(a): it flies.
    const Vec3 rimPoint = cap.capCentre + r * cap.axis + cap.down;
    const Vec3 rimVelocity = along * rim * cap.down;
    const double after = 0.2;
    sim.advanceTo(rim + after);
    const Vec3 expected = rimPoint + rimVelocity * after + 0.5 * after * after * s.world.gravity;
    const double error = (sim.positions()[0] - expected).norm();
    qDebug("%llu events; off the parabola by %.1e",
           static_cast<unsigned long long>(sim.stats().events), error);
    QVERIFY2(error < (exact ? 1e-9 : kG * s.world.timeStep * rim),
             qPrintable(QString::number(error)));
  }

  // A ball placed on a tilted cap against a wall that gravity along the cap presses it into
  // slides along the crease of the two (rule 2's creases) exactly, with gravity's component
  // along the crease line.
  void slidesAlongTheCreaseOfACapAndAWall() {
    Scene s = testing::elasticSceneWithGravity();
    const Vec3 axis = Vec3(0.3, 1.0, 0.2).normalized();
    s.cylinders.push_back(makeCylinder({0, 0, 0}, axis, 1.0, 1.0));
    const double r = 0.1;
    // Down the cap runs towards +z: the wall there, touching the ball 0.3 from the cap's centre.
    const Vec3 across = (Vec3::UnitZ() - axis.z() * axis).normalized();
    const Vec3 start = (0.5 + r) * axis + 0.3 * across;
    s.planes.push_back(makePlane(start + r * Vec3::UnitZ(), -Vec3::UnitZ()));
    s.balls.push_back(makeBall(start, {0, 0, 0}, r));
    QVERIFY(validateScene(s).empty());
    Simulation sim(s);
    Vec3 line = axis.cross(Vec3::UnitZ()).normalized();
    if (line.dot(s.world.gravity) < 0.0) line = -line;
    const double along = line.dot(s.world.gravity);
    QVERIFY(along > 1.0);
    const double t = 0.3;  // within the cap
    sim.advanceTo(t);
    const Vec3 expected = start + 0.5 * along * t * t * line;
    QVERIFY2((sim.positions()[0] - expected).norm() < 1e-9,
             qPrintable(QString::number((sim.positions()[0] - expected).norm())));
    QVERIFY2(sim.stats().events < 10, qPrintable(QString::number(sim.stats().events)));
  }

  // A ball falling onto one sliding on a cap presses it into the cap: the cap answers as a
  // ball-cylinder contact, as a box's face answers as a ball-box one.
  void aPressedSlideOnACapCountsAsBallCylinder() {
    Scene s = testing::elasticSceneWithGravity();
    s.cylinders.push_back(makeCylinder({0, 0, 0}, {0, 1, 0}, 1.0, 1.0));
    s.balls.push_back(makeBall({0, 0.6, 0}, {0.2, 0, 0}, 0.1));
    s.balls.push_back(makeBall({0.1, 1.3, 0}, {0, 0, 0}, 0.1));
    Simulation sim(s);
    sim.advanceTo(1.0);
    const CollisionCounts& counts = sim.stats().collisions;
    QVERIFY2(counts.ballBall > 0 && counts.ballCylinder > 1,
             qPrintable(QString("%1 %2").arg(counts.ballBall).arg(counts.ballCylinder)));
    QCOMPARE(counts.ballPlane, std::uint64_t(0));
  }

  // A ball that reaches a cap's rim slower than sqrt(r g_n) cannot fly clear of the rim's
  // rounding: it meets the rim there and goes over it in hops, never inside the cylinder (it sank
  // 9 mm when it flew), and an elastic one keeps its energy. Only `exact` bends its path: a
  // straight sweep leaves the rim along its tangent.
  void slowBallGoesOverARimWithoutSinkingIntoIt_data() {
    QTest::addColumn<double>("restitution");
    QTest::newRow("elastic") << 1.0;
    QTest::newRow("inelastic") << 0.5;
  }
  void slowBallGoesOverARimWithoutSinkingIntoIt() {
    QFETCH(double, restitution);
    Scene s = testing::elasticSceneWithGravity();
    s.world.restitution = restitution;
    const double degrees = 20.0, a = degrees * std::numbers::pi / 180.0, r = 0.1;
    const TiltedCap cap = tiltedCap(degrees);
    s.cylinders.push_back(makeCylinder({0, 0, 0}, cap.axis, 1.0, 1.0));
    // 5 cm before the rim, at rest: it reaches the rim at 0.58 m/s, where clearing the rounding
    // of a 10 cm ball needs 0.96.
    s.balls.push_back(makeBall(cap.capCentre + r * cap.axis + 0.95 * cap.down, {0, 0, 0}, r));
    QVERIFY(2.0 * kG * std::sin(a) * 0.05 < r * kG * std::cos(a));
    QVERIFY(validateScene(s).empty());
    Simulation sim(s);
    const double energy = sim.totalEnergy();
    double deepest = 0.0;
    for (int k = 1; k <= 800; ++k) {
      sim.advanceTo(1e-3 * k);
      deepest = std::max(deepest, depthInCylinders(s, sim.positions()));
    }
    qDebug("%llu events, %llu ball-cylinder; deepest %.1e, energy %.1e",
           static_cast<unsigned long long>(sim.stats().events),
           static_cast<unsigned long long>(sim.stats().collisions.ballCylinder), deepest,
           (sim.totalEnergy() - energy) / std::abs(energy));
    QVERIFY2(deepest < 1e-10, qPrintable(QString::number(deepest)));
    // Over the rim and falling past the cylinder's side.
    const Vec3 p = sim.positions()[0];
    QVERIFY2(p.dot(cap.down) > 1.0 + r && p.y() < -1.0,
             qPrintable(QString("%1 %2").arg(p.dot(cap.down)).arg(p.y())));
    QVERIFY2(sim.stats().events < 10000, qPrintable(QString::number(sim.stats().events)));
    if (restitution >= 1.0)
      QVERIFY2(std::abs(sim.totalEnergy() - energy) < 1e-9 * std::abs(energy),
               qPrintable(QString::number(sim.totalEnergy() - energy)));
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
