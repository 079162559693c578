// The `exact` method against analytic answers: bounces, projectiles, collisions of any masses,
// Newton's cradle, cylinders.

#include "sim/core/tolerances.h"
#include "sim/simulation.h"
#include "sim/validation/validation.h"
#include "tests/scene_helpers.h"

#include <QTest>

#include <cmath>

using namespace carom;
using carom::testing::makeBall;
using carom::testing::makePlane;

namespace {

Scene emptyScene(const Vec3& gravity) {
  Scene s;
  s.world.gravity = gravity;
  s.world.method = Method::Exact;
  return s;
}

}  // namespace

class TestExact : public QObject {
  Q_OBJECT
 private slots:
  void projectile() {
    Scene s = emptyScene({0, -9.81, 0});
    s.balls.push_back(makeBall({1, 2, 3}, {4, 5, -6}));
    Simulation sim(s);
    sim.advance(1.5);
    const Vec3 expected =
        Vec3(1, 2, 3) + 1.5 * Vec3(4, 5, -6) + 0.5 * 1.5 * 1.5 * Vec3(0, -9.81, 0);
    QVERIFY((sim.positions()[0] - expected).norm() < 1e-14);
    QCOMPARE(sim.stats().collisions.total(), std::uint64_t(0));
  }

  void bounceHeightAndPeriodOverManyBounces() {
    // Dropped from 1 m above touching: an elastic bounce keeps the period 2 sqrt(2h/g) and the
    // height forever.
    const double g = 9.81, h = 1.0, r = 0.1;
    Scene s = emptyScene({0, -g, 0});
    s.planes.push_back(makePlane({0, 0, 0}, {0, 1, 0}));
    s.balls.push_back(makeBall({0, r + h, 0}, {0, 0, 0}, r));
    Simulation sim(s);
    const double period = 2.0 * std::sqrt(2.0 * h / g);
    const int bounces = 1000;
    // The first impact comes half a period after the drop; after whole periods it is back at
    // the top.
    sim.advance(bounces * period);
    QCOMPARE(sim.stats().collisions.ballPlane, std::uint64_t(bounces));
    QVERIFY(std::abs(sim.positions()[0].y() - (r + h)) < 1e-9);
    QVERIFY(std::abs(sim.velocities()[0].y()) < 1e-8);
    QVERIFY(std::abs(sim.totalEnergy() - g * (r + h)) < 1e-12 * g * (r + h) * 100);
  }

  void independentOfFrameRate() {
    // The tutorial kicked gravity once per frame, so its motion depended on the frame rate and
    // gained energy at large steps. `exact` gives bit-identical states however the time is cut.
    Scene s = emptyScene({0, -9.81, 0});
    s.planes.push_back(makePlane({0, 0, 0}, {0, 1, 0}));
    s.planes.push_back(makePlane({2, 0, 0}, {-1, 0, 0}));
    s.balls.push_back(makeBall({0, 1, 0}, {1.3, 0, 0.2}));
    s.balls.push_back(makeBall({1, 2, 0.05}, {-0.4, 1, 0}));
    Simulation coarse(s), fine(s);
    coarse.advance(10.0);
    for (int k = 0; k < 10240; ++k) fine.advance(1.0 / 1024);  // sums to 10 exactly
    const std::vector<BallState> a = coarse.state(), b = fine.state();
    QVERIFY(coarse.stats().collisions.total() > 20);
    QCOMPARE(coarse.stats().collisions.total(), fine.stats().collisions.total());
    QCOMPARE(coarse.time(), fine.time());
    for (std::size_t i = 0; i < a.size(); ++i) {
      QVERIFY(a[i].position == b[i].position);
      QVERIFY(a[i].velocity == b[i].velocity);
    }
  }

  void headOnCollisionsForMassRatios_data() {
    QTest::addColumn<double>("ratio");
    QTest::addColumn<double>("restitution");
    for (double ratio : {1e-6, 1e-3, 0.5, 1.0, 3.0, 1e3, 1e6})
      for (double e : {1.0, 0.5, 0.0}) QTest::addRow("m2/m1=%g e=%g", ratio, e) << ratio << e;
  }
  void headOnCollisionsForMassRatios() {
    QFETCH(double, ratio);
    QFETCH(double, restitution);
    Scene s = emptyScene(Vec3::Zero());
    s.world.restitution = restitution;
    const double m1 = 1.0, m2 = ratio, u1 = 2.0, u2 = -1.0;
    s.balls.push_back(makeBall({0, 0, 0}, {u1, 0, 0}, 0.5, m1));
    s.balls.push_back(makeBall({3, 0, 0}, {u2, 0, 0}, 0.5, m2));
    Simulation sim(s);
    sim.advance(0.5);  // they meet at t = 2/3: not yet
    QCOMPARE(sim.stats().collisions.ballBall, std::uint64_t(0));
    sim.advance(10.0);
    QCOMPARE(sim.stats().collisions.ballBall, std::uint64_t(1));
    const double total = m1 + m2;
    // A dead stop (e = 0) still separates at the rest policy's collapse speed.
    const double rms = std::sqrt((m1 * u1 * u1 + m2 * u2 * u2) / total);
    const double separation =
        std::max(restitution * (u1 - u2), tolerance::kCollapseSpeedFraction * rms);
    const double v1 = (m1 * u1 + m2 * u2 - m2 * separation) / total;
    const double v2 = (m1 * u1 + m2 * u2 + m1 * separation) / total;
    const std::vector<Vec3> v = sim.velocities();
    QVERIFY2(std::abs(v[0].x() - v1) <= 1e-12 * (std::abs(v1) + 1),
             qPrintable(QString::number(v[0].x() - v1)));
    QVERIFY2(std::abs(v[1].x() - v2) <= 1e-12 * (std::abs(v2) + 1),
             qPrintable(QString::number(v[1].x() - v2)));
    const double p0 = m1 * u1 + m2 * u2;
    QVERIFY(std::abs(sim.momentum().x() - p0) <= 1e-14 * (m1 * 2 + m2 * 1));
  }

  void newtonsCradle() {
    // Five equal balls touching in a row; the first arrives at 1 m/s: the last leaves at 1 m/s
    // and the others stand still.
    Scene s = emptyScene(Vec3::Zero());
    const double r = 0.1;
    s.balls.push_back(makeBall({-0.5, 0, 0}, {1, 0, 0}, r));
    for (int i = 1; i < 5; ++i) s.balls.push_back(makeBall({2 * r * i, 0, 0}, {0, 0, 0}, r));
    QVERIFY(validateScene(s).empty());
    Simulation sim(s);
    sim.advance(2.0);
    const std::vector<Vec3> v = sim.velocities();
    for (int i = 0; i < 4; ++i) QVERIFY2(v[i].norm() < 1e-12, qPrintable(QString::number(i)));
    QVERIFY(std::abs(v[4].x() - 1.0) < 1e-12);
    QCOMPARE(sim.stats().collisions.ballBall, std::uint64_t(4));
  }

  void cornerHitReflectsStraightBack() {
    // Simultaneous contact with two perpendicular walls: the velocity comes straight back.
    Scene s = emptyScene(Vec3::Zero());
    s.planes.push_back(makePlane({1, 0, 0}, {-1, 0, 0}));
    s.planes.push_back(makePlane({0, 1, 0}, {0, -1, 0}));
    s.balls.push_back(makeBall({0, 0, 0}, {1, 1, 0}, 0.1));
    Simulation sim(s);
    sim.advance(2.0);
    QVERIFY((sim.velocities()[0] - Vec3(-1, -1, 0)).norm() < 1e-14);
    QCOMPARE(sim.stats().collisions.ballPlane, std::uint64_t(2));
  }

  void symmetricBreakConservesMomentumAndEnergy() {
    // A ball hits two touching balls at once: resolved as binary collisions in a fixed order;
    // momentum and energy are kept.
    Scene s = emptyScene(Vec3::Zero());
    const double r = 0.5;
    s.balls.push_back(makeBall({-3, 0, 0}, {2, 0, 0}, r));
    s.balls.push_back(makeBall({std::sqrt(3.0) * r, r, 0}, {0, 0, 0}, r));
    s.balls.push_back(makeBall({std::sqrt(3.0) * r, -r, 0}, {0, 0, 0}, r));
    Simulation sim(s);
    const double e0 = sim.kineticEnergy();
    sim.advance(5.0);
    QVERIFY(std::abs(sim.kineticEnergy() - e0) < 1e-13 * e0);
    QVERIFY((sim.momentum() - Vec3(2, 0, 0)).norm() < 1e-13);
    QVERIFY(sim.stats().collisions.ballBall >= 2);
  }

  void cylinderHeadOnAndGrazing() {
    Scene s = emptyScene(Vec3::Zero());
    Cylinder c;
    c.point = Vec3::Zero();
    c.axis = Vec3(0, 1, 0);
    c.radius = 1.0;
    s.cylinders.push_back(c);
    s.balls.push_back(makeBall({-5, 0, 0}, {1, 0, 0}, 0.5));                 // head-on
    s.balls.push_back(makeBall({-5, 3, 1.5 * (1 - 1e-9)}, {1, 0, 0}, 0.5));  // grazes
    s.balls.push_back(makeBall({-5, 6, 1.5 * (1 + 1e-9)}, {1, 0, 0}, 0.5));  // misses
    Simulation sim(s);
    sim.advance(10.0);
    const std::vector<Vec3> v = sim.velocities();
    QVERIFY((v[0] - Vec3(-1, 0, 0)).norm() < 1e-14);
    QVERIFY(v[1].x() > 0.99 && v[1].x() < 1.0 && v[1].z() > 0.0);
    QVERIFY((v[2] - Vec3(1, 0, 0)).norm() == 0.0);
    QCOMPARE(sim.stats().collisions.ballCylinder, std::uint64_t(2));
  }

  void parallelToCylinderAxis() {
    // Touching a cylinder and moving along its axis under gravity along the axis: no contact.
    Scene s = emptyScene({0, -9.81, 0});
    Cylinder c;
    c.axis = Vec3(0, 1, 0);
    c.radius = 1.0;
    s.cylinders.push_back(c);
    s.balls.push_back(makeBall({1.5, 0, 0}, {0, 3, 0}, 0.5));
    Simulation sim(s);
    sim.advance(3.0);
    QCOMPARE(sim.stats().collisions.total(), std::uint64_t(0));
    QVERIFY(std::abs(sim.positions()[0].x() - 1.5) == 0.0);
  }

  void ballOnTiltedCylinderUnderGravity() {
    // Dropped onto the top of a cylinder tilted along (0,1,1): it bounces off, never gets in.
    Scene s = emptyScene({0, -9.81, 0});
    Cylinder c;
    c.point = Vec3(-2, 0, 0);
    c.axis = Vec3(0, 1, 1);
    c.radius = 0.3;
    s.cylinders.push_back(c);
    s.balls.push_back(makeBall({-2.05, 2.0, 0.0}, {0.1, 0, 0.1}, 0.2));
    Simulation sim(s);
    for (int k = 0; k < 200; ++k) {
      sim.advance(0.01);
      const Vec3 p = sim.positions()[0];
      const Vec3 d = p - c.point;
      const Vec3 axis = c.axis.normalized();
      QVERIFY((d - d.dot(axis) * axis).norm() >= 0.5 - 1e-12);
    }
    QVERIFY(sim.stats().collisions.ballCylinder >= 1);
    QVERIFY(std::abs(sim.totalEnergy() - (-9.81 * -1.0 * 2.0 + 0.5 * 0.02)) < 1e-9 * 20);
  }
};

QTEST_APPLESS_MAIN(TestExact)
#include "test_exact.moc"
