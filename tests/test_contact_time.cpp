// Contact times of every shape pair against closed-form answers.

#include "sim/geometry/contact_time.h"

#include <QTest>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

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
  // Two touching balls whose relative velocity is along their common tangent to a few ulps:
  // not approaching. Predicted as a contact at once, it looped at one instant in a bin of a
  // Galton board (the response read the same rate as receding and changed nothing).
  void tangentWithinRoundOffIsNoContact() {
    const Vec3 offset = Vec3(0.0367, 0.0017, 0.0157).normalized() * 0.08;  // touching: 2 x 0.04
    Vec3 tangent = offset.cross(Vec3::UnitZ()).normalized() * 0.01;
    // Nudge until it moves into the other ball by less than round-off.
    for (int k = 0; k < 200 && !(offset.dot(tangent) < 0.0); ++k)
      tangent.x() = std::nextafter(tangent.x(), -1.0);
    QVERIFY(offset.dot(tangent) < 0.0 && offset.dot(tangent) > -1e-18);
    QCOMPARE(
        ballBallContactTime(path(Vec3::Zero(), -tangent), path(offset, Vec3::Zero()), 0.08, kNever),
        kNever);
    // A real approach, however slow against the speed, still fires at once.
    const Vec3 slowlyIn = tangent - 1e-9 * offset;
    QCOMPARE(ballBallContactTime(path(Vec3::Zero(), -slowlyIn), path(offset, Vec3::Zero()), 0.08,
                                 kNever),
             0.0);
  }
  // A horizon only cuts the search: every contact time up to it is the one found without it.
  // (A pair too far apart to meet within the horizon skips its quartic.)
  void horizonCutsOnlyTheSearch() {
    std::uint64_t state = 12345;
    const auto uniform = [&](double lo, double hi) {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      return lo + (hi - lo) * static_cast<double>(state >> 11) * 0x1.0p-53;
    };
    const auto vector = [&](double scale) {
      return Vec3(uniform(-scale, scale), uniform(-scale, scale), uniform(-scale, scale));
    };
    const BoxShape box{Vec3(0.1, -0.2, 0.3),
                       Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix(),
                       Vec3(0.5, 0.2, 1.0)};
    int found = 0;
    for (int k = 0; k < 16000; ++k) {
      const BallPath a = path(vector(2.0), vector(2.0), vector(3.0));
      const BallPath b = path(vector(2.0), vector(2.0), vector(3.0));
      const double horizon = uniform(0.0, 2.0);
      for (const auto& [unbounded, bounded] :
           {std::pair{ballBallContactTime(a, b, 0.3, kNever),
                      ballBallContactTime(a, b, 0.3, horizon)},
            std::pair{ballBoxContactTime(a, 0.15, box, kNever),
                      ballBoxContactTime(a, 0.15, box, horizon)}}) {
        if (unbounded <= horizon) {
          ++found;
          QCOMPARE(bounded, unbounded);
        } else {
          QCOMPARE(bounded, kNever);
        }
      }
    }
    QVERIFY2(found > 1000, qPrintable(QString::number(found)));
  }
};

QTEST_APPLESS_MAIN(TestContactTime)
#include "test_contact_time.moc"
