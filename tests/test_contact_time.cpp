// Contact times of every shape pair against closed-form answers.

#include "sim/contact_time.h"

#include <QTest>

#include <cmath>
#include <limits>

using namespace carom;

namespace {
constexpr double kNever = std::numeric_limits<double>::infinity();
BallPath path(const Vec3& p, const Vec3& v, const Vec3& a = Vec3::Zero()) {
  return {p, v, a};
}
const PlaneShape kFloor{Vec3::UnitY(), 0.0};
}  // namespace

class TestContactTime : public QObject {
  Q_OBJECT
 private slots:
  void planeStraightApproach() {
    // Centre at height 5, radius 1, falling at 2: touches when the centre is at 1, after 2 s.
    QCOMPARE(ballPlaneContactTime(path({0, 5, 0}, {3, -2, 0}), 1.0, kFloor, kNever), 2.0);
    QCOMPARE(ballPlaneContactTime(path({0, 5, 0}, {3, 2, 0}), 1.0, kFloor, kNever), kNever);
    QCOMPARE(ballPlaneContactTime(path({0, 5, 0}, {3, -2, 0}), 1.0, kFloor, 1.5), kNever);
  }
  void planeUnderGravity() {
    // Thrown up at 4 from height 1 (radius 1: touching) under g = 2: back down at t = 4.
    const double t =
        ballPlaneContactTime(path({0, 1, 0}, {0, 4, 0}, {0, -2, 0}), 1.0, kFloor, kNever);
    QVERIFY(std::abs(t - 4.0) < 1e-14);
    QVERIFY(t <= 4.0);  // never later than the true contact
    // Dropped from rest at height 3: h = g t^2 / 2 -> t = sqrt(2 * 2 / 2) = sqrt(2).
    const double drop =
        ballPlaneContactTime(path({0, 3, 0}, {0, 0, 0}, {0, -2, 0}), 1.0, kFloor, kNever);
    QVERIFY(std::abs(drop - std::sqrt(2.0)) < 1e-15);
  }
  void touchingAndApproachingFiresAtOnce() {
    QCOMPARE(ballPlaneContactTime(path({0, 1, 0}, {1, -1e-9, 0}), 1.0, kFloor, kNever), 0.0);
    // Resting on the floor with gravity pressing it in: also at once.
    QCOMPARE(ballPlaneContactTime(path({0, 1, 0}, {1, 0, 0}, {0, -9.81, 0}), 1.0, kFloor, kNever),
             0.0);
    // Touching and leaving: no contact.
    QCOMPARE(ballPlaneContactTime(path({0, 1, 0}, {0, 1e-9, 0}), 1.0, kFloor, kNever), kNever);
    QCOMPARE(
        ballBallContactTime(path({0, 0, 0}, {1, 0, 0}), path({2, 0, 0}, {0, 0, 0}), 2.0, kNever),
        0.0);
    QCOMPARE(
        ballBallContactTime(path({0, 0, 0}, {-1, 0, 0}), path({2, 0, 0}, {0, 0, 0}), 2.0, kNever),
        kNever);
  }
  void behindPlaneStillCollides() {
    // A ball whose centre is behind the surface and moving further in is an overlap that fires
    // at once: nothing passes through a plane from either side.
    QCOMPARE(ballPlaneContactTime(path({0, -3, 0}, {0, -1, 0}), 1.0, kFloor, kNever), 0.0);
  }
  void ballBallHeadOnAndGrazing() {
    // Gap of 8 closing at 4: t = 2.
    QCOMPARE(
        ballBallContactTime(path({0, 0, 0}, {2, 0, 0}), path({10, 0, 0}, {-2, 0, 0}), 2.0, kNever),
        2.0);
    // Offset by just under the radius sum: a grazing hit; just over: a miss.
    const double sigma = 2.0;
    const double hit = ballBallContactTime(
        path({0, 0, 0}, {1, 0, 0}), path({10, sigma * (1 - 1e-9), 0}, {0, 0, 0}), sigma, kNever);
    QVERIFY(hit < kNever);
    QVERIFY(std::abs(hit - 10.0) < 1e-3);
    QCOMPARE(ballBallContactTime(path({0, 0, 0}, {1, 0, 0}),
                                 path({10, sigma * (1 + 1e-12), 0}, {0, 0, 0}), sigma, kNever),
             kNever);
  }
  void ballBallSameGravityIsStraight() {
    const Vec3 g(0, -9.81, 0);
    const double t = ballBallContactTime(path({0, 0, 0}, {2, 0, 0}, g),
                                         path({10, 0, 0}, {-2, 0, 0}, g), 2.0, kNever);
    QCOMPARE(t, 2.0);
  }
  void ballFallingOntoRestingBall() {
    // One ball rests (no acceleration), the other falls onto it from 3 above: gap 1 closes
    // under g = 2 in t = 1.
    const double t = ballBallContactTime(path({0, 3, 0}, {0, 0, 0}, {0, -2, 0}),
                                         path({0, 0, 0}, {0, 0, 0}), 2.0, kNever);
    QVERIFY(std::abs(t - 1.0) < 1e-14);
  }
  void cylinderHeadOnAndGrazing() {
    const CylinderShape vertical{Vec3::Zero(), Vec3::UnitY(), 1.0};
    QCOMPARE(ballCylinderContactTime(path({5, 7, 0}, {-1, 3, 0}), 1.0, vertical, kNever), 3.0);
    const double graze =
        ballCylinderContactTime(path({-5, 0, 2.0 * (1 - 1e-9)}, {1, 0, 0}), 1.0, vertical, kNever);
    QVERIFY(std::abs(graze - 5.0) < 1e-3);
    QCOMPARE(
        ballCylinderContactTime(path({-5, 0, 2.0 * (1 + 1e-12)}, {1, 0, 0}), 1.0, vertical, kNever),
        kNever);
  }
  void parallelToAxisNeverHits() {
    const CylinderShape vertical{Vec3::Zero(), Vec3::UnitY(), 1.0};
    // Touching and moving along the axis (with gravity along it too): no contact, no stall.
    QCOMPARE(
        ballCylinderContactTime(path({2, 0, 0}, {0, 5, 0}, {0, -9.81, 0}), 1.0, vertical, kNever),
        kNever);
    QCOMPARE(ballCylinderContactTime(path({3, 0, 0}, {0, -5, 0}), 1.0, vertical, kNever), kNever);
  }
  void tiltedCylinderUnderGravityIsQuartic() {
    // Axis along (0,1,1): a ball dropped beside it falls onto it; check the distance at the
    // returned time against the geometry.
    const CylinderShape tilted{Vec3::Zero(), Vec3(0, 1, 1).normalized(), 0.3};
    const Vec3 p0(0.1, 2.0, -1.0), v0(0.2, 0.0, 0.3), g(0, -9.81, 0);
    const double t = ballCylinderContactTime(path(p0, v0, g), 0.2, tilted, kNever);
    QVERIFY(std::isfinite(t) && t > 0);
    auto distance = [&](double s) {
      const Vec3 p = p0 + v0 * s + 0.5 * g * s * s;
      return tilted.perpendicular(p).norm();
    };
    QVERIFY(std::abs(distance(t) - 0.5) < 1e-12);
    for (int k = 0; k < 1000; ++k) QVERIFY(distance(t * k / 1000.0) >= 0.5 - 1e-12);
  }
  void crossingBoundaries() {
    QCOMPARE(boundaryCrossingTime(0.0, 2.0, 0.0, 4.0, true, kNever), 2.0);
    QCOMPARE(boundaryCrossingTime(0.0, 2.0, 0.0, -4.0, false, kNever), kNever);
    // Thrown up at 2 under -2: back down through -3 when t^2 - 2t - 3 = 0, t = 3.
    QVERIFY(std::abs(boundaryCrossingTime(0.0, 2.0, -2.0, -3.0, false, kNever) - 3.0) < 1e-14);
    QCOMPARE(boundaryCrossingTime(0.0, 2.0, 0.0, kNever, true, kNever), kNever);
  }
};

QTEST_APPLESS_MAIN(TestContactTime)
#include "test_contact_time.moc"
