// The event engine with balls of very different sizes (a grid per size class) and balls that
// spread far beyond where they started (grids built again): no contact is missed at radius
// ratios up to 1e3, under `exact` and `swept`, and energy is kept. Scenes at the ends of what
// validation accepts run under every method.

#include "sim/model/scene_builders.h"
#include "sim/simulation.h"
#include "sim/validation/validation.h"
#include "tests/scene_helpers.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

using namespace carom;
using carom::testing::addMethodRows;
using carom::testing::makeBall;
using carom::testing::makeBox;
using carom::testing::makeCylinder;

namespace {

// The deepest overlap of any two balls, by testing every pair.
double deepestOverlap(const Simulation& sim, const Scene& scene) {
  const std::vector<Vec3> at = sim.positions();
  double deepest = 0.0;
  for (std::size_t i = 0; i < at.size(); ++i)
    for (std::size_t j = i + 1; j < at.size(); ++j) {
      const double gap = (at[i] - at[j]).norm() - scene.balls[i].radius - scene.balls[j].radius;
      deepest = std::max(deepest, -gap);
    }
  return deepest;
}

std::string gridNote(const Simulation& sim) {
  for (const std::string& note : sim.modelNotes())
    if (note.starts_with("cell grid")) return note;
  return {};
}

// A gas of 1 cm balls with two balls `ratio` times larger driven through it from either side,
// and two more beside them, in a closed room.
Scene gasWithBigBalls(double ratio, Method method) {
  const double r = 0.01, big = ratio * r;
  Scene scene = makeGasInBox(300, 0.2, Vec3::Zero(), 11, r);
  const double side = scene.planes[1].point.x() - scene.planes[0].point.x();
  scene.planes.clear();
  addBoxWalls(scene, 0.5 * side + 3.0 * big + 0.1);
  const double reach = 0.5 * side + big + 0.001;
  for (const Vec3& place : {Vec3(-reach, 0.01, 0.0), Vec3(reach, -0.01, 0.0),
                            Vec3(0.0, 0.0, -2.0 * reach), Vec3(0.0, 0.0, 2.0 * reach)})
    scene.balls.push_back(makeBall(place, -2.0 * place.normalized(), big, std::pow(ratio, 3.0)));
  scene.world.method = method;
  scene.world.timeStep = 0.01;
  return scene;
}

// A scene at the ends of the accepted range (tiny balls, huge distances and shapes) and its
// first contact, known in closed form.
struct ExtremeScene {
  Scene scene;
  int contacts = 0;  // by contactTime's end
  double contactTime = 0.0;
  double timeTolerance = 0.0;  // the rounding of positions so far out
  double end = 0.0;            // where the run stops
};

ExtremeScene extremeScene(const std::string& name) {
  ExtremeScene e;
  Scene& s = e.scene;
  s.world.gravity = Vec3::Zero();
  if (name == "micro pair 1 km apart") {
    // Issue 33's first scene: head-on along the diagonal, 1000 sqrt(3) m to close at sqrt(3) m/s.
    const double r = 1e-6;
    s.balls.push_back(makeBall(Vec3::Zero(), Vec3(1, 1, 1), r));
    s.balls.push_back(makeBall(Vec3(1000, 1000, 1000), Vec3::Zero(), r));
    e.contacts = 1;
    e.contactTime = 1000.0 - 2.0 * r / std::sqrt(3.0);
    e.timeTolerance = 1e-9;
  } else if (name == "pico balls by a huge box" || name == "pico balls by a huge cylinder") {
    // A 1e-12 m ball 1 m from the side of a shape 1e12 m across, heading for it at 1 m/s.
    const double r = 1e-12, half = 5e11;
    if (name.ends_with("box"))
      s.boxes.push_back(makeBox(Vec3::Zero(), Vec3::Constant(half)));
    else
      s.cylinders.push_back(makeCylinder(Vec3::Zero(), Vec3::UnitY(), half, 2.0 * half));
    s.balls.push_back(makeBall(Vec3(half + 1.0, 0, 0), Vec3(-1, 0, 0), r));
    s.balls.push_back(makeBall(Vec3(half + 1.0, 1.0, 0), Vec3::Zero(), r));
    e.contacts = 1;
    e.contactTime = 1.0 - r;
    e.timeTolerance = 1e-3;  // positions near 5e11 m round to 6e-5 m
  } else if (name == "pico pair 1e9 m apart") {
    const double r = 1e-12;
    s.balls.push_back(makeBall(Vec3::Zero(), Vec3(1, 0, 0), r));
    s.balls.push_back(makeBall(Vec3(1e9, 0, 0), Vec3(-1, 0, 0), r));
    e.contacts = 1;
    e.contactTime = 0.5 * (1e9 - 2.0 * r);
    e.timeTolerance = 1e-6;  // positions near 1e9 m round to 1e-7 m
  } else {
    // "burst flying far": a cluster of micro balls flying apart at 1e12 m/s for 1e6 s, to
    // 1e18 m, far beyond any grid built around them, which is built again and again.
    const double r = 1e-6;
    for (int k = 0; k < 512; ++k) {
      const Vec3 at(k % 8 - 3.5, (k / 8) % 8 - 3.5, k / 64 - 3.5);
      const Vec3 out = at.normalized();
      s.balls.push_back(makeBall(4.0 * r * at, 1e12 * out, r));
    }
    e.contactTime = 1e6;
  }
  e.end = e.contacts ? 1.5 * e.contactTime : e.contactTime;
  // Swept and discrete steps of about a tenth of the run, within the accepted range.
  s.world.timeStep = std::min(e.end / 10.0, 1e6);
  return e;
}

}  // namespace

class TestSizeClasses : public QObject {
  Q_OBJECT
 private slots:
  void noContactMissedAcrossSizes_data() {
    QTest::addColumn<int>("method");
    QTest::addColumn<double>("ratio");
    for (Method method : {Method::Exact, Method::Swept})
      for (double ratio : {3.0, 10.0, 100.0, 1000.0})
        QTest::newRow((std::string(methodName(method)) + " " + std::to_string(int(ratio))).c_str())
            << int(method) << ratio;
  }
  void noContactMissedAcrossSizes() {
    QFETCH(int, method);
    QFETCH(double, ratio);
    const Scene scene = gasWithBigBalls(ratio, Method(method));
    Simulation sim(scene);
    QVERIFY2(gridNote(sim).starts_with("cell grids"), gridNote(sim).c_str());
    const double initial = sim.totalEnergy();
    std::uint64_t bigCollisions = 0;
    for (int sample = 0; sample < 40; ++sample) {
      sim.advance(0.005);
      const double overlap = deepestOverlap(sim, scene);
      QVERIFY2(overlap < 1e-9 * 0.01,
               qPrintable(QString("t %1: overlap %2 m").arg(sim.time()).arg(overlap)));
    }
    bigCollisions = sim.stats().collisions.total();
    // The big balls went through the gas: many more collisions than the gas makes alone.
    QVERIFY2(bigCollisions > 1000, qPrintable(QString::number(bigCollisions)));
    QVERIFY2(std::abs(sim.totalEnergy() - initial) <= 1e-9 * initial,
             qPrintable(QString("energy %1 -> %2").arg(initial).arg(sim.totalEnergy())));
  }

  // A marble fired at a boulder a thousand times its radius: one elastic collision, at the
  // time and with the rebound a head-on collision of these masses has.
  void marbleOffABoulder_data() { addMethodRows({Method::Exact, Method::Swept}); }
  void marbleOffABoulder() {
    QFETCH(int, method);
    const double r = 0.001, big = 1.0, gap = 0.3, speed = 2.0;
    const double m = 1.0, M = 1e9;
    Scene scene;
    scene.world.gravity = Vec3::Zero();
    scene.world.method = Method(method);
    scene.world.timeStep = 0.01;
    scene.balls.push_back(makeBall(Vec3(0.2, big + r + gap, 0.1), Vec3(0, -speed, 0), r, m));
    // Off the boulder's axis: it meets the sphere where its surface is at height sqrt(R^2-x^2).
    scene.balls.push_back(makeBall(Vec3::Zero(), Vec3::Zero(), big, M));
    Simulation sim(scene);
    const Vec3 c = scene.balls[0].position;
    const double surface = std::sqrt((big + r) * (big + r) - c.x() * c.x() - c.z() * c.z());
    const double tHit = (c.y() - surface) / speed;
    sim.advance(tHit * 0.999);
    QCOMPARE(sim.stats().collisions.total(), std::uint64_t(0));
    sim.advance(tHit * 0.002);
    QCOMPARE(sim.stats().collisions.total(), std::uint64_t(1));
    // The marble's velocity along the normal reverses (scaled by the masses), the rest stays.
    const Vec3 n = Vec3(c.x(), surface, c.z()).normalized();
    const Vec3 v0(0, -speed, 0);
    const double vn = v0.dot(n);
    const Vec3 expected = v0 - vn * n + vn * (m - M) / (m + M) * n;
    QVERIFY2((sim.velocities()[0] - expected).norm() < 1e-9 * speed,
             qPrintable(QString("off by %1").arg((sim.velocities()[0] - expected).norm())));
  }

  // Radii over 30 doublings, more than the engine gives classes of their own: classes then span
  // several doublings, and contacts across them are still all found. Pairs of neighbours in a
  // row, each ball twice the last one's radius, fly at each other.
  void radiiOverManyDoublings_data() { addMethodRows({Method::Exact, Method::Swept}); }
  void radiiOverManyDoublings() {
    QFETCH(int, method);
    Scene scene;
    scene.world.gravity = Vec3::Zero();
    scene.world.method = Method(method);
    scene.world.timeStep = 0.01;
    double x = 0.0;
    for (int k = 0; k < 31; ++k) {
      const double r = 1e-6 * std::pow(2.0, k);
      x += r;
      scene.balls.push_back(makeBall(Vec3(x, 0.0, 0.0), Vec3(k % 2 ? -1.0 : 1.0, 0.1, 0.0) * r, r,
                                     std::pow(2.0, 3 * k)));
      x += 2.0 * r;  // a gap of a radius to the next
    }
    Simulation sim(scene);
    QVERIFY2(gridNote(sim).find("ball size classes") != std::string::npos, gridNote(sim).c_str());
    const double initial = sim.totalEnergy();
    for (int sample = 0; sample < 20; ++sample) {
      sim.advance(0.1);
      const double overlap = deepestOverlap(sim, scene);
      QVERIFY2(overlap < 1e-9 * 1e-6,
               qPrintable(QString("t %1: overlap %2 m").arg(sim.time()).arg(overlap)));
    }
    // Every ball meets its partner: 15 pairs.
    QVERIFY2(sim.stats().collisions.ballBall >= 15,
             qPrintable(QString::number(sim.stats().collisions.ballBall)));
    QVERIFY2(std::abs(sim.totalEnergy() - initial) <= 1e-9 * initial,
             qPrintable(QString("energy %1 -> %2").arg(initial).arg(sim.totalEnergy())));
  }

  // A tight cluster let loose in a room a hundred times its size: its grid, built around it,
  // is built again as the balls spread, and no contact is lost on the way.
  void gridsFollowSpreadingBalls_data() { addMethodRows({Method::Exact, Method::Swept}); }
  void gridsFollowSpreadingBalls() {
    QFETCH(int, method);
    Scene scene = makeGasInBox(400, 0.3, Vec3::Zero(), 5, 0.01);
    const double side = scene.planes[1].point.x() - scene.planes[0].point.x();
    scene.planes.clear();
    addBoxWalls(scene, 50.0 * side);
    for (Ball& ball : scene.balls) ball.velocity *= 5.0;
    scene.world.method = Method(method);
    scene.world.timeStep = 0.01;
    Simulation sim(scene);
    const std::string before = gridNote(sim);
    const double initial = sim.totalEnergy();
    for (int sample = 0; sample < 20; ++sample) {
      sim.advance(0.05);
      const double overlap = deepestOverlap(sim, scene);
      QVERIFY2(overlap < 1e-9 * 0.01,
               qPrintable(QString("t %1: overlap %2 m").arg(sim.time()).arg(overlap)));
    }
    QVERIFY2(gridNote(sim) != before, before.c_str());
    QVERIFY2(sim.stats().collisions.ballBall > 400,
             qPrintable(QString::number(sim.stats().collisions.ballBall)));
    QVERIFY2(std::abs(sim.totalEnergy() - initial) <= 1e-9 * initial,
             qPrintable(QString("energy %1 -> %2").arg(initial).arg(sim.totalEnergy())));
  }

  // Scenes that validation accepts at the ends of its range crashed the grids (issue 33):
  // counts of cells overflowed. Each runs under every method: the event-driven ones to past
  // the contact, at its closed-form time; discrete a few steps (its steps would jump over balls
  // this small). Energy is kept and every number stays finite.
  void extremeScalesRun_data() {
    QTest::addColumn<QString>("scene");
    QTest::addColumn<int>("method");
    QTest::addColumn<int>("integrator");
    for (const char* scene :
         {"micro pair 1 km apart", "pico balls by a huge box", "pico balls by a huge cylinder",
          "pico pair 1e9 m apart", "burst flying far"}) {
      for (Method method : {Method::Exact, Method::Swept})
        QTest::newRow((std::string(scene) + ", " + std::string(methodName(method))).c_str())
            << QString(scene) << int(method) << int(Integrator::SymplecticEuler);
      for (Integrator integrator :
           {Integrator::ExplicitEuler, Integrator::SymplecticEuler, Integrator::VelocityVerlet})
        QTest::newRow(
            (std::string(scene) + ", discrete " + std::string(integratorName(integrator))).c_str())
            << QString(scene) << int(Method::Discrete) << int(integrator);
    }
  }
  void extremeScalesRun() {
    QFETCH(QString, scene);
    QFETCH(int, method);
    QFETCH(int, integrator);
    ExtremeScene e = extremeScene(scene.toStdString());
    e.scene.world.method = Method(method);
    e.scene.world.integrator = Integrator(integrator);
    const std::vector<ValidationError> errors = validateScene(e.scene);
    QVERIFY2(errors.empty(), errors.empty() ? "" : errors[0].text().c_str());
    Simulation sim(e.scene);
    sim.setCollisionLog(true);
    const double initial = sim.totalEnergy();
    if (Method(method) == Method::Discrete) {
      for (int step = 0; step < 5; ++step) sim.step();
    } else {
      sim.advanceTo(e.end);
      const std::vector<CollisionRecord> hits = sim.takeCollisions();
      QCOMPARE(int(hits.size()), e.contacts);
      if (e.contacts > 0)
        QVERIFY2(std::abs(hits[0].time - e.contactTime) <= e.timeTolerance,
                 qPrintable(QString("contact at %1 s, expected %2 s")
                                .arg(hits[0].time, 0, 'g', 17)
                                .arg(e.contactTime, 0, 'g', 17)));
    }
    for (const BallState& ball : sim.state())
      QVERIFY(ball.position.allFinite() && ball.velocity.allFinite());
    QVERIFY2(std::abs(sim.totalEnergy() - initial) <= 1e-12 * initial,
             qPrintable(QString("energy %1 -> %2").arg(initial).arg(sim.totalEnergy())));
    if (e.contacts == 0) {
      // Straight out, untouched.
      const std::vector<Vec3> at = sim.positions();
      for (std::size_t i = 0; i < at.size(); ++i) {
        const Ball& ball = e.scene.balls[i];
        const Vec3 expected = ball.position + sim.time() * ball.velocity;
        QVERIFY2((at[i] - expected).norm() <= 1e-12 * expected.norm(),
                 qPrintable(QString("ball %1 off by %2 m").arg(i).arg((at[i] - expected).norm())));
      }
    }
  }

  // A light pair touching at 1e11 m/s, one closing on the other by an ulp of its velocity,
  // in a scene that a heavy ball at rest dominates: the scene's collapse speed (1e-7 of its
  // mass-weighted speed) is far below an ulp of the pair's velocities, and their inelastic
  // contact changed nothing and came again at the same instant, for ever (found by
  // fuzz_valid_scenes). They part along the contact's normal, and the run ends.
  void fastPairPartsBeyondRoundOff_data() { addMethodRows({Method::Exact, Method::Swept}); }
  void fastPairPartsBeyondRoundOff() {
    QFETCH(int, method);
    Scene scene;
    scene.world.gravity = Vec3::Zero();
    scene.world.restitution = 0.0;
    scene.world.method = Method(method);
    scene.world.timeStep = 0.01;
    const double r = 1.0, speed = 7e10;
    const Vec3 n = Vec3(1, -1, 0).normalized();
    // Touching to 1e-10 of the radius; the first is an ulp faster along x.
    const Vec3 velocity(speed, speed, 0.0);
    const double ulp = std::nextafter(speed, 2.0 * speed) - speed;
    const Vec3 faster(speed + ulp, speed, 0.0);
    scene.balls.push_back(makeBall(Vec3::Zero(), faster, r, 1e-30));
    scene.balls.push_back(makeBall(2.0 * r * (1.0 - 1e-10) * n, velocity, r, 1e-30));
    scene.balls.push_back(makeBall(Vec3(0, -1e6, 0), Vec3::Zero(), r, 1e28));
    Simulation sim(scene);
    const double initial = sim.kineticEnergy();
    sim.advance(1.0);
    QCOMPARE(sim.stats().collisions.ballBall, std::uint64_t(1));
    const std::vector<Vec3> p = sim.positions(), v = sim.velocities();
    QVERIFY((p[1] - p[0]).dot(v[1] - v[0]) > 0.0);  // receding
    // Parted at twice kTangentRateFraction of the speed, which is energy's round-off.
    QVERIFY2(std::abs(sim.kineticEnergy() - initial) <= 1e-9 * initial,
             qPrintable(QString("energy %1 -> %2")
                            .arg(initial, 0, 'g', 17)
                            .arg(sim.kineticEnergy(), 0, 'g', 17)));
  }

  // At 5e53 s the time's resolution is 6e37 s. Gravity switched on there brings a ball back to
  // a cell face 1e49 m below it in 1e23 s, the same instant: crossing there, it found itself
  // beyond the face again, crossed back, and went to and fro for ever (found by
  // fuzz_valid_scenes). A crossing closer than the time's resolution comes an ulp later; the
  // run goes on.
  void crossingsBelowTheTimesResolution() {
    Scene scene;
    scene.world.gravity = Vec3::Zero();
    scene.balls.push_back(makeBall(Vec3(0, -8e11, 0), Vec3::Zero(), 1e-12));
    scene.balls.push_back(makeBall(Vec3::Zero(), Vec3::Constant(2.6e-4), 1e-12));
    Simulation sim(scene);
    sim.advanceTo(5e53);
    World world = scene.world;
    world.gravity = Vec3(-270, -270, 58);
    sim.setWorld(world);
    sim.advance(1e40);
    QCOMPARE(sim.stats().collisions.total(), std::uint64_t(0));
    QVERIFY2(sim.stats().events < 1000, qPrintable(QString::number(sim.stats().events)));
    for (const BallState& ball : sim.state())
      QVERIFY(ball.position.allFinite() && ball.velocity.allFinite());
  }
};

QTEST_GUILESS_MAIN(TestSizeClasses)
#include "test_size_classes.moc"
