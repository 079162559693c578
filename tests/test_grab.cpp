// The held ball (sim/grab.h) and copies of a running simulation: a copy goes on bit for bit as
// the original; a held ball moves as steered, pushes balls as an unlimited mass, slides along
// walls, stops where it would crush a ball, and is thrown when released.

#include "scene_helpers.h"
#include "sim/model/scene_builders.h"
#include "sim/simulation.h"

#include <QTest>

#include <cmath>

using namespace carom;
using namespace carom::testing;

namespace {

bool sameState(const Simulation& a, const Simulation& b) {
  const std::vector<BallState> x = a.state(), y = b.state();
  if (x.size() != y.size() || a.time() != b.time()) return false;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (x[i].position != y[i].position || x[i].velocity != y[i].velocity ||
        x[i].resting != y[i].resting)
      return false;
  return true;
}

double minimumGapToBall(const Simulation& sim, int ball) {
  const std::vector<Vec3> p = sim.positions();
  double gap = std::numeric_limits<double>::infinity();
  for (int k = 0; k < sim.ballCount(); ++k)
    if (k != ball)
      gap = std::min(gap,
                     (p[k] - p[ball]).norm() - sim.bodies().radius[k] - sim.bodies().radius[ball]);
  return gap;
}

}  // namespace

class GrabTest : public QObject {
  Q_OBJECT

 private slots:
  void copyGoesOnBitForBit_data() {
    addMethodRows({Method::Exact, Method::Swept, Method::Discrete});
  }
  void copyGoesOnBitForBit() {
    QFETCH(int, method);
    Simulation original(elasticGasRoom(200, Method(method)));
    for (int k = 0; k < 60; ++k) original.step();
    Simulation copy(original);
    QVERIFY(sameState(original, copy));
    // Steered the same way, a grab included, both go on identically.
    for (Simulation* sim : {&original, &copy}) {
      sim->grab(7);
      for (int k = 0; k < 30; ++k) {
        sim->steerGrab(Vec3(std::cos(0.2 * k), 0.5 * std::sin(0.3 * k), 0.0));
        sim->step();
      }
      sim->releaseGrab(Vec3(1.0, 2.0, 0.0));
      for (int k = 0; k < 120; ++k) sim->step();
    }
    QVERIFY(sameState(original, copy));
    QCOMPARE(original.stats().events, copy.stats().events);
    QCOMPARE(original.stats().collisions.total(), copy.stats().collisions.total());
    QVERIFY(copy.memoryBytes() > 200 * sizeof(BallState));
  }

  // Held, a ball feels no gravity and follows its steering exactly.
  void heldBallFollowsItsSteering_data() {
    addMethodRows({Method::Exact, Method::Swept, Method::Discrete});
  }
  void heldBallFollowsItsSteering() {
    QFETCH(int, method);
    Scene s = elasticSceneWithGravity();
    s.world.method = Method(method);
    s.balls = {makeBall({0, 1, 0}, {3, 0, 0})};
    Simulation sim(s);
    sim.grab(0);
    const Vec3 v(0.25, 0.5, -0.125);
    sim.steerGrab(v);
    for (int k = 0; k < 60; ++k) sim.step();
    const double t = sim.time();
    QVERIFY((sim.positions()[0] - (Vec3(0, 1, 0) + t * v)).norm() < 1e-12);
    QVERIFY((sim.velocities()[0] - v).norm() < 1e-12);
    // Thrown, it flies on a parabola from where it was let go.
    const Vec3 from = sim.positions()[0];
    const Vec3 throwVelocity(1, 2, 0);
    sim.releaseGrab(throwVelocity);
    const double t0 = sim.time();
    for (int k = 0; k < 30; ++k) sim.step();
    const double dt = sim.time() - t0;
    const Vec3 expected = from + dt * throwVelocity + 0.5 * dt * dt * s.world.gravity;
    // `swept` and `discrete` integrate the parabola: their error is a step's.
    const double tolerance = method == int(Method::Exact) ? 1e-12 : 0.5 * 9.81 * dt / 60.0;
    QVERIFY2((sim.positions()[0] - expected).norm() < tolerance,
             qPrintable(QString::number((sim.positions()[0] - expected).norm())));
  }

  // Head-on, a ball at rest takes (1 + e) times the held ball's speed, which keeps its own.
  void pushAsAnUnlimitedMass_data() {
    QTest::addColumn<int>("method");
    QTest::addColumn<double>("restitution");
    for (const Method m : {Method::Exact, Method::Swept})
      for (const double e : {1.0, 0.5, 0.0})
        QTest::newRow(qPrintable(QString("%1 e=%2").arg(methodName(m).data()).arg(e)))
            << int(m) << e;
  }
  void pushAsAnUnlimitedMass() {
    QFETCH(int, method);
    QFETCH(double, restitution);
    Scene s;
    s.world.gravity = Vec3::Zero();
    s.world.restitution = restitution;
    s.world.method = Method(method);
    s.balls = {makeBall({0, 0, 0}, {0, 0, 0}, 0.1, 1e-6), makeBall({1, 0, 0}, {0, 0, 0}, 0.1, 1e6)};
    Simulation sim(s);
    sim.grab(0);
    sim.steerGrab(Vec3(2, 0, 0));
    sim.advanceTo(1.0);
    QCOMPARE(sim.takeGrabStop().has_value(), false);
    const std::vector<Vec3> v = sim.velocities();
    QVERIFY((v[0] - Vec3(2, 0, 0)).norm() < 1e-12);
    // The minimum separation of an inelastic contact is round-off here (no gravity).
    QVERIFY2(std::abs(v[1].x() - 2.0 * (1.0 + restitution)) < 1e-9,
             qPrintable(QString::number(v[1].x(), 'g', 17)));
    QVERIFY(minimumGapToBall(sim, 0) >= -1e-12);
  }

  // Pushed head-on into a wall, a ball is never crushed through it: the grab stops with the
  // ball between, and says which ball it would have crushed.
  void crushStopsTheGrab_data() {
    QTest::addColumn<int>("method");
    QTest::addColumn<double>("speed");  // in radii a second
    QTest::addColumn<double>("scale");  // the radius, m
    // Not `discrete` at 50 m/s: half a radius a step, the ball it bounces back tunnels through
    // the held ball, as through any other (the method's notes say it can tunnel).
    for (const Method m : {Method::Exact, Method::Swept, Method::Discrete})
      for (const double speed : {5.0, 500.0})
        if (m != Method::Discrete || speed < 10.0)
          QTest::newRow(qPrintable(QString("%1 %2 r/s").arg(methodName(m).data()).arg(speed)))
              << int(m) << speed << 0.1;
    // The crush tolerances are fractions of the radius: the same at any scale.
    for (const Method m : {Method::Exact, Method::Swept})
      for (const double scale : {1e-7, 1e5})
        QTest::newRow(qPrintable(QString("%1 r = %2 m").arg(methodName(m).data()).arg(scale)))
            << int(m) << 50.0 << scale;
  }
  void crushStopsTheGrab() {
    QFETCH(int, method);
    QFETCH(double, speed);
    QFETCH(double, scale);
    const double r = scale;
    speed *= r;
    Scene s;
    s.world.gravity = Vec3::Zero();
    s.world.restitution = 0.8;
    s.world.method = Method(method);
    s.world.timeStep = 1e-3;
    s.planes = {makePlane({10 * r, 0, 0}, {-1, 0, 0})};
    s.balls = {makeBall({0, 0, 0}, {0, 0, 0}, r), makeBall({5 * r, 0, 0}, {0, 0, 0}, r)};
    Simulation sim(s);
    sim.grab(0);
    sim.steerGrab(Vec3(speed, 0, 0));
    // `discrete` finds overlaps after a step: by then the ball may be a step's travel in.
    const double slack =
        method == int(Method::Discrete) ? 2.0 * speed * s.world.timeStep : 1e-9 * r;
    const double wall = 9 * r;  // where ball 1's centre touches it
    std::optional<GrabStop> stop;
    for (int k = 0; k < 4000 && !stop; ++k) {
      sim.step();
      stop = sim.takeGrabStop();
      QVERIFY2(sim.positions()[1].x() <= wall + slack,
               qPrintable(QString("step %1: %2").arg(k).arg(sim.positions()[1].x(), 0, 'g', 17)));
    }
    QVERIFY(stop.has_value());
    QCOMPARE(stop->held, 0);
    QCOMPARE(stop->other, 1);
    QVERIFY(sim.grabStopped());
    // It stands where it stopped, steering or not, and the ball stays between it and the wall.
    sim.steerGrab(Vec3(speed, 0, 0));
    const Vec3 at = sim.positions()[0];
    for (int k = 0; k < 200; ++k) sim.step();
    QVERIFY((sim.positions()[0] - at).norm() < 1e-12 * r);
    QVERIFY(sim.positions()[1].x() <= wall + slack);
    QVERIFY(sim.positions()[1].x() > sim.positions()[0].x());
  }

  // A ball pushed sideways along a floor slides off as it should: no crush.
  void pushAlongTheFloorIsNoCrush() {
    Scene s = elasticSceneWithGravity();
    s.world.restitution = 0.5;
    s.planes = {makePlane({0, 0, 0}, {0, 1, 0})};
    s.balls = {makeBall({0, 0.12, 0}, {0, 0, 0}), makeBall({0.5, 0.1, 0}, {0, 0, 0})};
    Simulation sim(s);
    sim.advanceTo(1.0);  // ball 1 rests on the floor
    sim.grab(0);
    sim.steerGrab(Vec3(1, 0, 0));
    sim.advanceTo(2.0);
    QVERIFY(!sim.takeGrabStop().has_value());
    QVERIFY(sim.positions()[1].x() > 1.0);
    QVERIFY(sim.positions()[1].y() >= 0.1 - 1e-9);
  }

  // The held ball slides along a wall it is steered into, and never enters it.
  void heldBallSlidesAlongWalls_data() {
    addMethodRows({Method::Exact, Method::Swept, Method::Discrete});
  }
  void heldBallSlidesAlongWalls() {
    QFETCH(int, method);
    Scene s = elasticSceneWithGravity();
    s.world.method = Method(method);
    s.planes = {makePlane({0, 0, 0}, {0, 1, 0})};
    s.boxes = {makeBox({2, 0.5, 0}, {0.5, 0.5, 0.5})};
    s.balls = {makeBall({0, 0.5, 0}, {0, 0, 0})};
    Simulation sim(s);
    sim.grab(0);
    sim.steerGrab(Vec3(1, -1, 0));
    for (int k = 0; k < 120; ++k) {
      sim.step();
      const Vec3 p = sim.positions()[0];
      const double slack = method == int(Method::Discrete) ? 1.0 / 60.0 * 1.5 : 1e-9;
      QVERIFY2(p.y() >= 0.1 - slack, qPrintable(QString::number(p.y(), 'g', 17)));
      QVERIFY2(p.x() <= 1.5 - 0.1 + slack, qPrintable(QString::number(p.x(), 'g', 17)));
    }
    // In the corner of floor and box it stands still.
    QVERIFY(sim.velocities()[0].norm() < 1e-9);
    QVERIFY(!sim.takeGrabStop().has_value());
  }

  // A held ball swept fast through a gas: every contact with it is solved, none overlaps it.
  void fastGrabThroughAGas_data() { addMethodRows({Method::Exact, Method::Swept}); }
  void fastGrabThroughAGas() {
    QFETCH(int, method);
    Simulation sim(elasticGasRoom(300, Method(method)));
    sim.grab(40);
    for (int k = 0; k < 240; ++k) {
      const double a = 0.05 * k;
      sim.steerGrab(30.0 * Vec3(std::cos(a), std::sin(1.3 * a), std::sin(0.7 * a)));
      sim.step();
      QVERIFY2(minimumGapToBall(sim, 40) >= -1e-9,
               qPrintable(QString::number(minimumGapToBall(sim, 40))));
      for (const Vec3& p : sim.positions())
        QVERIFY(p.cwiseAbs().maxCoeff() <= 2.0 && p.y() >= 0.05 - 1e-9 && p.y() <= 1.95 + 1e-9);
    }
  }

  // With no time passing, the held ball goes as far as it can towards the target.
  void moveGrabbedStopsAtTheFirstContact() {
    Scene s = elasticSceneWithGravity();
    s.planes = {makePlane({0, 0, 0}, {0, 1, 0})};
    s.balls = {makeBall({0, 1, 0}, {0, 0, 0}), makeBall({1, 1, 0}, {0, 0, 0}, 0.2)};
    Simulation sim(s);
    sim.grab(0);
    Vec3 at = sim.moveGrabbed(Vec3(0, 0.5, 0));
    QVERIFY((at - Vec3(0, 0.5, 0)).norm() < 1e-15);
    at = sim.moveGrabbed(Vec3(2, 0.5, 0));  // ball 1 (at height 1, radius 0.2) is not in the way
    QVERIFY((at - Vec3(2, 0.5, 0)).norm() < 1e-15);
    at = sim.moveGrabbed(Vec3(2, -1, 0));  // the floor is
    QVERIFY(std::abs(at.y() - 0.1) < 1e-12);
    at = sim.moveGrabbed(Vec3(2, 1, 0));
    QVERIFY((at - Vec3(2, 1, 0)).norm() < 1e-15);
    at = sim.moveGrabbed(Vec3(0, 1, 0));  // now ball 1 is in the way
    QVERIFY((at - Vec3(1.3, 1, 0)).norm() < 1e-12);
    QCOMPARE(sim.time(), 0.0);
    // Let go at a speed, it flies from there when time runs.
    sim.releaseGrab(Vec3(0, 1, 0));
    sim.advanceTo(0.05);
    QVERIFY(sim.positions()[0].y() > at.y());
  }

  // Grabbing the ball under a resting one lets that one fall when it moves away.
  void grabbingASupportWakesWhatRestsOnIt() {
    Scene s = elasticSceneWithGravity();
    s.world.restitution = 0.3;
    s.planes = {makePlane({0, 0, 0}, {0, 1, 0})};
    s.balls = {makeBall({0, 0.1, 0}, {0, 0, 0}), makeBall({0, 0.3, 0}, {0, 0, 0})};
    Simulation sim(s);
    sim.advanceTo(2.0);
    QVERIFY(sim.state()[1].resting);
    sim.grab(0);
    sim.steerGrab(Vec3(2, 0, 0));
    sim.advanceTo(2.5);
    QVERIFY(!sim.state()[1].resting || sim.positions()[1].y() < 0.2);
    QVERIFY(sim.positions()[1].y() < 0.2);
    QVERIFY(sim.positions()[1].y() >= 0.1 - 1e-9);
  }
};

QTEST_APPLESS_MAIN(GrabTest)
#include "test_grab.moc"
