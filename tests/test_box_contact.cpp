// Contact times of a ball against a solid box: closed forms for its faces, edges and corners,
// and random throws against an independent reference that samples the true gap finely and
// bisects (written here, sharing nothing with the solver but the box's closest point).

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

BoxShape makeBox(const Vec3& center, const Vec3& half,
                 const Eigen::Matrix3d& axes = Eigen::Matrix3d::Identity()) {
  return {center, axes, half};
}

// The gap between ball and box surfaces, from the closest point alone.
double boxGap(const Vec3& c, double radius, const BoxShape& box) {
  const Vec3 local = box.toLocal(c);
  const Vec3 clamped = local.cwiseMax(-box.half).cwiseMin(box.half);
  const double outside = (local - clamped).norm();
  if (outside > 0.0) return outside - radius;
  return (local.cwiseAbs() - box.half).maxCoeff() - radius;
}
}  // namespace

class TestBoxContact : public QObject {
  Q_OBJECT
 private slots:
  void droppedOntoAFace() {
    const BoxShape box = makeBox(Vec3::Zero(), {1, 0.5, 2});
    const double r = 0.25;
    const BallPath ball{{0.3, 3, -0.4}, Vec3::Zero(), kGravity};
    const double t = ballBoxContactTime(ball, r, box, kNever);
    const double expected = std::sqrt(2 * (3 - 0.75) / kG);
    QVERIFY2(std::abs(t - expected) < 1e-14, qPrintable(QString::number(t - expected)));
    QVERIFY(t <= expected);
    const BoxShape::Contact c = box.contact(at(ball, expected), r);
    QVERIFY((c.normal - Vec3::UnitY()).norm() < 1e-12);
  }

  void droppedOntoAnEdge() {
    // Falling past the face at x = 1 by d < r: the ball meets the edge (y = 0.5) when its centre
    // is sqrt(r^2 - d^2) above it, and bounces along the line from the edge to the centre.
    const BoxShape box = makeBox(Vec3::Zero(), {1, 0.5, 2});
    const double r = 0.25, d = 0.15;
    const BallPath ball{{1 + d, 3, 0.7}, Vec3::Zero(), kGravity};
    const double t = ballBoxContactTime(ball, r, box, kNever);
    const double height = 0.5 + std::sqrt(r * r - d * d);
    const double expected = std::sqrt(2 * (3 - height) / kG);
    QVERIFY2(std::abs(t - expected) < 1e-13, qPrintable(QString::number(t - expected)));
    const BoxShape::Contact c = box.contact(at(ball, expected), r);
    QVERIFY((c.normal - Vec3(d, height - 0.5, 0) / r).norm() < 1e-9);
    QVERIFY(std::abs(c.gap) < 1e-12);
  }

  void droppedOntoACorner() {
    const BoxShape box = makeBox(Vec3(5, -1, 2), {1, 0.5, 2});
    const double r = 0.3, dx = 0.1, dz = 0.2;
    const Vec3 corner(6, -0.5, 4);
    const BallPath ball{corner + Vec3(dx, 4, dz), Vec3::Zero(), kGravity};
    const double t = ballBoxContactTime(ball, r, box, kNever);
    const double rise = std::sqrt(r * r - dx * dx - dz * dz);
    const double expected = std::sqrt(2 * (4 - rise) / kG);
    QVERIFY2(std::abs(t - expected) < 1e-13, qPrintable(QString::number(t - expected)));
    const BoxShape::Contact c = box.contact(at(ball, expected), r);
    QVERIFY((c.normal - Vec3(dx, rise, dz) / r).norm() < 1e-9);
  }

  void rotatedBoxMeetsItsRidge() {
    // A unit cube turned 45 degrees about z stands on an edge; its top edge is a ridge at
    // y = sqrt(2) along z. A ball falling onto it at x = 0 touches when its centre is r above.
    const Eigen::Matrix3d axes =
        Eigen::AngleAxisd(std::numbers::pi / 4, Vec3::UnitZ()).toRotationMatrix();
    const BoxShape box = makeBox(Vec3::Zero(), {1, 1, 1}, axes);
    const double r = 0.2;
    const BallPath ball{{0, 3, 0.5}, Vec3::Zero(), kGravity};
    const double t = ballBoxContactTime(ball, r, box, kNever);
    const double expected = std::sqrt(2 * (3 - std::sqrt(2.0) - r) / kG);
    QVERIFY2(std::abs(t - expected) < 1e-13, qPrintable(QString::number(t - expected)));
  }

  void missesBesideAndGrazes() {
    const BoxShape box = makeBox(Vec3::Zero(), {1, 0.5, 2});
    const double r = 0.25;
    // Falling just outside the grown box's side: never.
    QCOMPARE(ballBoxContactTime({{1 + r + 1e-9, 3, 0}, Vec3::Zero(), kGravity}, r, box, kNever),
             kNever);
    // Moving away, and out of reach within the horizon.
    QCOMPARE(ballBoxContactTime({{0, 3, 0}, {0, 1, 0}, Vec3::Zero()}, r, box, kNever), kNever);
    QCOMPARE(ballBoxContactTime({{0, 3, 0}, {0, -1, 0}, Vec3::Zero()}, r, box, 2.0), kNever);
    QCOMPARE(ballBoxContactTime({{0, 3, 0}, {0, -1, 0}, Vec3::Zero()}, r, box, 2.25), 2.25);
  }

  void touchingFiresOnlyWhenApproaching() {
    const BoxShape box = makeBox(Vec3::Zero(), {1, 0.5, 2});
    const double r = 0.25;
    QCOMPARE(ballBoxContactTime({{0, 0.75, 0}, {1, -1e-9, 0}, Vec3::Zero()}, r, box, kNever), 0.0);
    // Resting on the top with gravity pressing it in.
    QCOMPARE(ballBoxContactTime({{0, 0.75, 0}, {0.5, 0, 0}, kGravity}, r, box, kNever), 0.0);
    // Leaving without gravity: no contact.
    QCOMPARE(ballBoxContactTime({{0, 0.75, 0}, {0, 1e-9, 0}, Vec3::Zero()}, r, box, kNever),
             kNever);
    // Bouncing up from the top at 4 m/s: back on it after 2 v / g, not at once.
    const double t = ballBoxContactTime({{0, 0.75, 0}, {0, 4, 0}, kGravity}, r, box, kNever);
    QVERIFY2(std::abs(t - 8 / kG) < 1e-13, qPrintable(QString::number(t)));
    // Off a corner, diagonally up: it does not fire at once either.
    const Vec3 corner(1, 0.5, 2);
    const Vec3 out = Vec3(1, 1, 1).normalized();
    QCOMPARE(ballBoxContactTime({corner + r * out, out, Vec3::Zero()}, r, box, kNever), kNever);
  }

  void thrownSidewaysAcrossTheTop() {
    // Thrown up and along above a long top face: it lands on the face where its parabola
    // comes down to touching height.
    const BoxShape box = makeBox(Vec3::Zero(), {3, 0.5, 1});
    const double r = 0.1;
    const BallPath ball{{-2.5, 1.6, 0}, {1, 2, 0}, kGravity};
    const double t = ballBoxContactTime(ball, r, box, kNever);
    // y(t) = 1.6 + 2 t - g t^2 / 2 = 0.6
    const double expected = (2 + std::sqrt(4 + 2 * kG * 1.0)) / kG;
    QVERIFY2(std::abs(t - expected) < 1e-13, qPrintable(QString::number(t - expected)));
  }

  // Random boxes (turned any way), radii and throws, with and without gravity: the contact time
  // agrees with the reference to 1e-9, and no contact the reference finds is missed. Where the
  // solver finds a contact the reference's samples stepped over, it must be a real dip.
  void randomThrowsMatchTheReference_data() {
    QTest::addColumn<bool>("gravity");
    QTest::newRow("straight") << false;
    QTest::newRow("under gravity") << true;
  }
  void randomThrowsMatchTheReference() {
    QFETCH(bool, gravity);
    std::mt19937_64 engine(gravity ? 11 : 12);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const auto vec = [&] { return Vec3(unit(engine), unit(engine), unit(engine)); };
    testing::ThrowTally tally;
    int pieces[3] = {0, 0, 0};  // faces, edges, corners met
    constexpr int kThrows = 3000;
    constexpr double kHorizon = 3.0;
    for (int n = 0; n < kThrows; ++n) {
      const Eigen::Matrix3d axes =
          Eigen::AngleAxisd(3.2 * unit(engine), vec().normalized()).toRotationMatrix();
      const BoxShape box = makeBox(vec(), vec().cwiseAbs() * 1.5 + Vec3::Constant(0.1), axes);
      const double r = 0.05 + 0.5 * std::abs(unit(engine));
      BallPath ball{Vec3::Zero(), Vec3::Zero(), gravity ? kGravity : Vec3::Zero()};
      do {
        ball.position = box.center + 4.0 * vec();
      } while (box.contact(ball.position, r).gap <= 0.0);
      // Aimed near the box, so that most throws hit a face, an edge or a corner.
      const Vec3 target = box.center + box.axes * box.half.cwiseProduct(1.3 * vec());
      ball.velocity = (target - ball.position) * (0.5 + std::abs(unit(engine))) +
                      (gravity ? Vec3(0, 0.5 * kG * 1.0, 0) : Vec3::Zero());
      const double solved = ballBoxContactTime(ball, r, box, kHorizon);
      if (solved < kNever) {
        // Which piece it met: the number of axes along which the centre lies beyond the box.
        const Vec3 local = box.toLocal(at(ball, solved));
        const int beyond = ((local.cwiseAbs() - box.half).array() > 1e-9).count();
        if (beyond >= 1) ++pieces[beyond - 1];
      }
      const testing::GapOf gap = [&](const Vec3& c) { return boxGap(c, r, box); };
      testing::compareWithReference(ball, gap, solved, kHorizon, 20000, n, tally);
      if (QTest::currentTestFailed()) return;
    }
    const int hits = tally.hits, finer = tally.finer;
    // The throws exercise the solver: most of them hit.
    QVERIFY2(hits > kThrows / 2, qPrintable(QString::number(hits)));
    qDebug("%d of %d throws hit (%d faces, %d edges, %d corners), %d found finer", hits, kThrows,
           pieces[0], pieces[1], pieces[2], finer);
    QVERIFY(pieces[0] > kThrows / 10 && pieces[1] > kThrows / 20 && pieces[2] > kThrows / 100);
    QVERIFY2(finer < kThrows / 50, qPrintable(QString::number(finer)));
  }
};

QTEST_APPLESS_MAIN(TestBoxContact)
#include "test_box_contact.moc"
