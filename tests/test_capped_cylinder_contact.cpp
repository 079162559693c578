// Contact times of a ball against a capped cylinder: closed forms for its side, caps and rims,
// and random throws against the sampled reference of tests/contact_reference.h.

#include "tests/contact_reference.h"

#include <Eigen/Geometry>
#include <QTest>

#include <cmath>
#include <limits>
#include <random>

using namespace carom;
using carom::testing::at;

namespace {
constexpr double kNever = std::numeric_limits<double>::infinity();
constexpr double kG = 9.81;
const Vec3 kGravity(0, -kG, 0);

CylinderShape makeCylinder(const Vec3& point, const Vec3& axis, double radius, double length) {
  return {point, axis.normalized(), radius, 0.5 * length};
}

// The gap between ball and cylinder surfaces from the closest point of the solid, clamped along
// the axis and across it (and for a centre inside, the nearer of side and cap).
double cylinderGap(const Vec3& c, double radius, const CylinderShape& cylinder) {
  const Vec3 w = c - cylinder.point;
  const double z = w.dot(cylinder.axis);
  const Vec3 across = w - z * cylinder.axis;
  const double rho = across.norm();
  if (rho <= cylinder.radius && std::abs(z) <= cylinder.halfLength)
    return -std::min(cylinder.radius - rho, cylinder.halfLength - std::abs(z)) - radius;
  const double clampedZ = std::clamp(z, -cylinder.halfLength, cylinder.halfLength);
  const Vec3 clampedAcross =
      rho > cylinder.radius ? Vec3(across * (cylinder.radius / rho)) : across;
  return (w - clampedZ * cylinder.axis - clampedAcross).norm() - radius;
}

void expectNear(double t, double expected, double tolerance = 1e-12) {
  QVERIFY2(std::abs(t - expected) <= tolerance * std::max(1.0, expected),
           qPrintable(QString("got %1, expected %2").arg(t, 0, 'g', 17).arg(expected, 0, 'g', 17)));
}
}  // namespace

class TestCappedCylinderContact : public QObject {
  Q_OBJECT
 private slots:
  void droppedOntoTheCap() {
    // Upright, 2 m long: the top cap at y = 1.
    const CylinderShape cylinder = makeCylinder(Vec3::Zero(), Vec3::UnitY(), 0.5, 2.0);
    const double r = 0.1;
    const BallPath ball{{0.3, 3, 0.1}, Vec3::Zero(), kGravity};
    const double t = ballCylinderContactTime(ball, r, cylinder, kNever);
    expectNear(t, std::sqrt(2 * (3 - 1.1) / kG));
    const CylinderShape::Contact c = cylinder.contact(at(ball, t), r);
    QVERIFY(std::abs(c.gap) < 1e-12 && (c.normal - Vec3::UnitY()).norm() < 1e-12);
  }

  void droppedOntoTheSide() {
    // Lying along x, 4 m long: its side's top at y = 0.5.
    const CylinderShape cylinder = makeCylinder(Vec3::Zero(), Vec3::UnitX(), 0.5, 4.0);
    const double r = 0.2;
    const BallPath ball{{1.9, 2, 0}, Vec3::Zero(), kGravity};
    const double t = ballCylinderContactTime(ball, r, cylinder, kNever);
    expectNear(t, std::sqrt(2 * (2 - 0.7) / kG));
    // Beyond the end (x > 2 + r) it falls past.
    QCOMPARE(
        ballCylinderContactTime({{2.2 + 1e-9, 2, 0}, Vec3::Zero(), kGravity}, r, cylinder, kNever),
        kNever);
  }

  void droppedOntoTheRim() {
    // Upright, rim of radius 0.5 at y = 1; dropped 0.6 m from the axis with r = 0.2, the centre
    // meets the torus where (0.6 - 0.5)^2 + (y - 1)^2 = 0.2^2, and leaves along that line.
    const CylinderShape cylinder = makeCylinder(Vec3::Zero(), Vec3::UnitY(), 0.5, 2.0);
    const double r = 0.2;
    const BallPath ball{{0.6, 3, 0}, Vec3::Zero(), kGravity};
    const double t = ballCylinderContactTime(ball, r, cylinder, kNever);
    const double y = 1 + std::sqrt(0.04 - 0.01);
    expectNear(t, std::sqrt(2 * (3 - y) / kG));
    const CylinderShape::Contact c = cylinder.contact(at(ball, t), r);
    QVERIFY(std::abs(c.gap) < 1e-12);
    QVERIFY((c.normal - Vec3(0.1, y - 1, 0) / 0.2).norm() < 1e-9);
    // The same on a straight path (a quartic), and on a parabola thrown in sideways (degree 8).
    expectNear(
        ballCylinderContactTime({{0.6, 3, 0}, {0, -2, 0}, Vec3::Zero()}, r, cylinder, kNever),
        (3 - y) / 2);
    const BallPath thrown{{-0.6, 2, 0}, {1.2, 0, 0}, kGravity};
    // At x = 0.6 after 1 s it would be far below; it meets the rim first, on the way across.
    const double tThrown = ballCylinderContactTime(thrown, r, cylinder, kNever);
    QVERIFY(tThrown < kNever);
    QVERIFY(std::abs(cylinderGap(at(thrown, tThrown), r, cylinder)) < 1e-9);
    // Just outside the grown rim: never.
    QCOMPARE(
        ballCylinderContactTime({{0.7 + 1e-9, 3, 0}, Vec3::Zero(), kGravity}, r, cylinder, kNever),
        kNever);
  }

  // The same rim met along a straight path from 1e11 m away: the torus's quartic from there
  // has terms of 1e44 whose differences the root depends on, and it missed the contact (found
  // by fuzz_valid_scenes: a ball 1e12 m out went into a tiny cylinder and rattled inside it).
  void rimFromFarAway() {
    const CylinderShape cylinder = makeCylinder(Vec3::Zero(), Vec3::UnitY(), 0.5, 2.0);
    const double r = 0.2, height = 1e11, speed = 1e11;
    const double y = 1 + std::sqrt(0.04 - 0.01);
    expectNear(ballCylinderContactTime({{0.6, height, 0}, {0, -speed, 0}, Vec3::Zero()}, r,
                                       cylinder, kNever),
               (height - y) / speed);
    // Just outside the grown rim: never.
    QCOMPARE(ballCylinderContactTime({{0.7 + 1e-6, height, 0}, {0, -speed, 0}, Vec3::Zero()}, r,
                                     cylinder, kNever),
             kNever);
  }

  // A rod far thinner than the ball (a spindle torus around each rim): the torus is entered
  // where the nearest rim point comes within r, and left again for the quartic when the
  // farthest does, 2 R l / (r v) later: at 1e12 m/s, 1e-23 s, below the time's resolution, and
  // the ball went through the rod (found by fuzz_valid_scenes).
  void thinRodMetAtSpeed() {
    const double R = 1e-7, length = 5e-8, r = 1.4, offset = 4e-5, height = 1e12, speed = 1e12;
    const CylinderShape rod = makeCylinder(Vec3::Zero(), Vec3::UnitY(), R, length);
    const double y = 0.5 * length + std::sqrt(r * r - (offset - R) * (offset - R));
    expectNear(ballCylinderContactTime({{offset, height, 0}, {0, -speed, 0}, Vec3::Zero()}, r, rod,
                                       kNever),
               (height - y) / speed, 1e-15);
  }

  void touchingFiresOnlyWhenApproaching() {
    const CylinderShape cylinder = makeCylinder(Vec3::Zero(), Vec3::UnitY(), 0.5, 2.0);
    const double r = 0.1;
    // On the cap, pressed by gravity, sliding: at once.
    QCOMPARE(ballCylinderContactTime({{0.2, 1.1, 0}, {0.3, 0, 0}, kGravity}, r, cylinder, kNever),
             0.0);
    // Sliding across the cap towards its middle without gravity: no contact.
    QCOMPARE(
        ballCylinderContactTime({{0.2, 1.1, 0}, {-0.3, 0, 0}, Vec3::Zero()}, r, cylinder, kNever),
        kNever);
    // Bouncing up from the cap at 4 m/s: back on it after 2 v / g.
    expectNear(ballCylinderContactTime({{0, 1.1, 0}, {0, 4, 0}, kGravity}, r, cylinder, kNever),
               8 / kG);
    // Touching the side and moving out: never.
    QCOMPARE(ballCylinderContactTime({{0.6, 0, 0}, {1, 0, 0}, Vec3::Zero()}, r, cylinder, kNever),
             kNever);
    // Touching the rim and leaving along its normal: never.
    const Vec3 out = Vec3(1, 1, 0).normalized();
    QCOMPARE(ballCylinderContactTime({Vec3(0.5, 1, 0) + r * out, out, Vec3::Zero()}, r, cylinder,
                                     kNever),
             kNever);
  }

  // Random capped cylinders (any axis, length and radius), radii and throws, with and without
  // gravity, against the reference; counts which part each contact was on.
  void randomThrowsMatchTheReference_data() {
    QTest::addColumn<bool>("gravity");
    QTest::newRow("straight") << false;
    QTest::newRow("under gravity") << true;
  }
  void randomThrowsMatchTheReference() {
    QFETCH(bool, gravity);
    std::mt19937_64 engine(gravity ? 21 : 22);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const auto vec = [&] { return Vec3(unit(engine), unit(engine), unit(engine)); };
    testing::ThrowTally tally;
    int parts[3] = {0, 0, 0};  // side, caps, rims
    constexpr int kThrows = 3000;
    constexpr double kHorizon = 3.0;
    for (int n = 0; n < kThrows; ++n) {
      const CylinderShape cylinder = makeCylinder(vec(), vec(), 0.1 + 1.2 * std::abs(unit(engine)),
                                                  0.2 + 3.0 * std::abs(unit(engine)));
      const double r = 0.05 + 0.5 * std::abs(unit(engine));
      BallPath ball{Vec3::Zero(), Vec3::Zero(), gravity ? kGravity : Vec3::Zero()};
      do {
        ball.position = cylinder.point + 4.0 * vec();
      } while (cylinderGap(ball.position, r, cylinder) <= 0.0);
      // Aimed near the cylinder's ends, so that many throws meet a cap or a rim.
      const Vec3 target = cylinder.point +
                          cylinder.axis * (cylinder.halfLength * 1.2 * unit(engine)) +
                          cylinder.radius * 1.3 * vec();
      ball.velocity = (target - ball.position) * (0.5 + std::abs(unit(engine))) +
                      (gravity ? Vec3(0, 0.5 * kG * 1.0, 0) : Vec3::Zero());
      const double solved = ballCylinderContactTime(ball, r, cylinder, kHorizon);
      if (solved < kNever) {
        const Vec3 w = at(ball, solved) - cylinder.point;
        const double z = std::abs(w.dot(cylinder.axis)) - cylinder.halfLength;
        const double rho = (w - w.dot(cylinder.axis) * cylinder.axis).norm() - cylinder.radius;
        ++parts[z > 1e-9 && rho > 1e-9 ? 2 : (z > 1e-9 ? 1 : 0)];
      }
      const testing::GapOf gap = [&](const Vec3& c) { return cylinderGap(c, r, cylinder); };
      testing::compareWithReference(ball, gap, solved, kHorizon, 20000, n, tally);
      if (QTest::currentTestFailed()) return;
    }
    qDebug("%d of %d throws hit (%d sides, %d caps, %d rims), %d found finer", tally.hits, kThrows,
           parts[0], parts[1], parts[2], tally.finer);
    QVERIFY2(tally.hits > kThrows / 2, qPrintable(QString::number(tally.hits)));
    QVERIFY(parts[0] > kThrows / 10 && parts[1] > kThrows / 20 && parts[2] > kThrows / 50);
    QVERIFY2(tally.finer < kThrows / 50, qPrintable(QString::number(tally.finer)));
  }
};

QTEST_APPLESS_MAIN(TestCappedCylinderContact)

#include "test_capped_cylinder_contact.moc"
