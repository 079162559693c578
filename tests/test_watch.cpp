// The run watch (sim/run_watch.h): each check fires on a run that goes wrong in its way, naming
// the ball and a time; none fires on the bundled scenes run correctly; checks turned off stay
// silent; the energy check stands aside when a restitution above 1 lets energy rise.

#include "sim/io/scene_file.h"
#include "sim/measure/run_watch.h"
#include "sim/simulation.h"
#include "sim/validation/validation.h"
#include "tests/scene_helpers.h"

#include <QDir>
#include <QTest>

#include <cmath>
#include <limits>
#include <optional>

using namespace carom;
using carom::testing::makeBall;
using carom::testing::makeBox;
using carom::testing::makePlane;

namespace {

// Steps `sim` for `duration` simulated seconds, checking after each step; the first event.
std::optional<WatchEvent> runWatched(Simulation& sim, RunWatch& watch, double duration) {
  if (auto event = watch.check(sim)) return event;
  while (sim.time() < duration) {
    sim.step();
    if (auto event = watch.check(sim)) return event;
  }
  return std::nullopt;
}

// A ball dropped from 2 m onto a floor, bouncing elastically, under `method` and `integrator`.
Scene bouncingBall(Method method, Integrator integrator) {
  Scene s = carom::testing::elasticSceneWithGravity();
  s.world.method = method;
  s.world.integrator = integrator;
  s.planes.push_back(makePlane(Vec3::Zero(), Vec3::UnitY()));
  // Ball 0, light, lies on the floor far away; ball 1 bounces.
  s.balls.push_back(makeBall(Vec3(-5, 0.1, 0), Vec3::Zero(), 0.1, 0.01));
  s.balls.push_back(makeBall(Vec3(0, 2, 0), Vec3::Zero()));
  return s;
}

// A heavy ball at a step too long for it crushes a light ball against a thick box: the push
// apart of the pair drives the light ball's centre into the box.
Scene crushAgainstBox() {
  Scene s;
  s.world.gravity = Vec3::Zero();
  s.world.method = Method::Discrete;
  s.world.timeStep = 0.1;
  s.boxes.push_back(makeBox(Vec3(1, 0, 0), Vec3(0.5, 1, 1)));
  s.balls.push_back(makeBall(Vec3(-0.5, 0, 0), Vec3(8, 0, 0), 0.3, 1000.0));  // heavy
  s.balls.push_back(makeBall(Vec3(0.39, 0, 0), Vec3::Zero(), 0.1, 0.001));    // light
  return s;
}

// Three balls in a row, numbered so that the discrete step resolves the heavy ball's hit on the
// middle one after the middle and the last ones, and leaves those two overlapping.
Scene crushInARow() {
  Scene s;
  s.world.gravity = Vec3::Zero();
  s.world.method = Method::Discrete;
  s.world.timeStep = 0.1;
  s.balls.push_back(makeBall(Vec3(0, 0, 0), Vec3::Zero(), 0.1, 0.001));        // middle
  s.balls.push_back(makeBall(Vec3(-0.2001, 0, 0), Vec3::Zero(), 0.1, 0.001));  // last
  s.balls.push_back(makeBall(Vec3(0.9, 0, 0), Vec3(-8, 0, 0), 0.1, 1000.0));   // heavy, fast
  return s;
}

WatchSettings onlyOff(WatchKind kind) {
  WatchSettings settings;
  switch (kind) {
    case WatchKind::NonFinite:
      settings.nonFinite = false;
      break;
    case WatchKind::EnergyRise:
      settings.energyRise = false;
      break;
    case WatchKind::Escape:
      settings.escape = false;
      break;
    case WatchKind::Penetration:
      settings.penetration = false;
      break;
  }
  return settings;
}

WatchSettings allOff() {
  WatchSettings settings;
  settings.nonFinite = settings.energyRise = settings.escape = settings.penetration = false;
  return settings;
}

}  // namespace

class TestWatch : public QObject {
  Q_OBJECT
 private slots:
  void examplesStaySilent_data();
  void examplesStaySilent();
  void nonFiniteFires();
  void energyRiseFires();
  void energyRiseSkippedAboveOne();
  void escapeFires();
  void penetrationFires();
  void discreteGaltonBoardGoesWrong();
  void offChecksStaySilent();
  void resumedRunGoesOn();
  void rebaseTakesNewEnergy();
  void settingsValidated();
};

void TestWatch::examplesStaySilent_data() {
  QTest::addColumn<QString>("file");
  QTest::addColumn<int>("method");
  const QDir dir(qEnvironmentVariable("CAROM_SOURCE_DIR") + "/resources/scenes");
  const QStringList files = dir.entryList({"*.json"}, QDir::Files, QDir::Name);
  QVERIFY(!files.isEmpty());
  for (const QString& file : files)
    for (Method method : {Method::Exact, Method::Swept})
      QTest::newRow(qPrintable(file + " " + QString::fromUtf8(methodName(method))))
          << dir.filePath(file) << int(method);
}

void TestWatch::examplesStaySilent() {
  QFETCH(QString, file);
  QFETCH(int, method);
  io::SceneLoadResult loaded = io::loadSceneFile(file);
  QVERIFY2(loaded.scene, qPrintable(loaded.error));
  Scene scene = *loaded.scene;
  scene.world.method = Method(method);
  Simulation sim(scene);
  RunWatch watch;
  const std::optional<WatchEvent> event = runWatched(sim, watch, 20.0);
  QVERIFY2(!event, event ? event->text.c_str() : "");
  QVERIFY(sim.time() >= 20.0);
}

void TestWatch::nonFiniteFires() {
  // Discrete's constructor only stores the state; a NaN velocity of ball 1 is there to see.
  Scene s = bouncingBall(Method::Discrete, Integrator::SymplecticEuler);
  s.balls[1].velocity.x() = std::numeric_limits<double>::quiet_NaN();
  Simulation sim(s);
  RunWatch watch;
  const std::optional<WatchEvent> event = watch.check(sim);
  QVERIFY(event);
  QCOMPARE(event->kind, WatchKind::NonFinite);
  QCOMPARE(event->ball, 1);
  QCOMPARE(event->time, 0.0);
  QVERIFY(event->text.find("ball 1") != std::string::npos);
}

void TestWatch::energyRiseFires() {
  // Explicit Euler gains about m g² t dt / 2 a flight; at a tenth of a second a step, a third
  // of the fall, the bouncing ball soon has more than it started with.
  Scene s = bouncingBall(Method::Discrete, Integrator::ExplicitEuler);
  s.world.timeStep = 0.1;
  s.balls[1].position.y() = 0.5;
  Simulation sim(s);
  RunWatch watch;
  const double start = sim.totalEnergy();
  const std::optional<WatchEvent> event = runWatched(sim, watch, 30.0);
  QVERIFY(event);
  QCOMPARE(event->kind, WatchKind::EnergyRise);
  QCOMPARE(event->ball, 1);
  QVERIFY(event->time > 0.0);
  QCOMPARE(event->lastGoodTime, event->time - s.world.timeStep);
  QVERIFY(event->value > watch_default::kEnergyRise);
  QVERIFY(sim.totalEnergy() - start > watch_default::kEnergyRise * watch.energyScale());
}

void TestWatch::energyRiseSkippedAboveOne() {
  // A super-elastic floor gains energy at every bounce, as it should: no event.
  Scene s = bouncingBall(Method::Exact, Integrator::SymplecticEuler);
  s.world.restitution = 1.2;
  Simulation sim(s);
  RunWatch watch;
  const double start = sim.totalEnergy();
  QVERIFY(!runWatched(sim, watch, 5.0));
  QVERIFY(!watch.energyChecked());
  QVERIFY(sim.totalEnergy() - start > 0.5 * start);  // it did rise
  // The same at 1 keeps the check.
  s.world.restitution = 1.0;
  Simulation elastic(s);
  RunWatch watchElastic;
  QVERIFY(!runWatched(elastic, watchElastic, 5.0));
  QVERIFY(watchElastic.energyChecked());
}

void TestWatch::escapeFires() {
  Simulation sim(crushAgainstBox());
  RunWatch watch;
  const std::optional<WatchEvent> event = runWatched(sim, watch, 1.0);
  QVERIFY(event);
  QVERIFY2(event->kind == WatchKind::Escape, event->text.c_str());
  QCOMPARE(event->ball, 1);
  QCOMPARE(event->otherKind, WatchOther::Box);
  QCOMPARE(event->other, 0);
  QVERIFY(event->time > 0.0);
  QVERIFY(event->value > 0.0);
}

void TestWatch::penetrationFires() {
  Simulation sim(crushInARow());
  RunWatch watch;
  const std::optional<WatchEvent> event = runWatched(sim, watch, 1.0);
  QVERIFY(event);
  QVERIFY2(event->kind == WatchKind::Penetration, event->text.c_str());
  QCOMPARE(event->otherKind, WatchOther::Ball);
  QVERIFY((event->ball == 0 && event->other == 1) || (event->ball == 1 && event->other == 0));
  QVERIFY(event->value > watch_default::kPenetration);
  QVERIFY(event->time > 0.0);
}

void TestWatch::discreteGaltonBoardGoesWrong() {
  // The board's 1 cm balls fall several radii a step at its time step: under `discrete` they
  // end up deep in each other, which `exact` and `swept` never let happen (examplesStaySilent).
  io::SceneLoadResult loaded = io::loadSceneFile(qEnvironmentVariable("CAROM_SOURCE_DIR") +
                                                 "/resources/scenes/galton-board.json");
  QVERIFY2(loaded.scene, qPrintable(loaded.error));
  Scene scene = *loaded.scene;
  scene.world.method = Method::Discrete;
  Simulation sim(scene);
  RunWatch watch;
  const std::optional<WatchEvent> event = runWatched(sim, watch, 20.0);
  QVERIFY(event);
  QVERIFY2(event->kind == WatchKind::Penetration || event->kind == WatchKind::Escape,
           event->text.c_str());
  QVERIFY(event->ball >= 0 && event->ball < int(scene.balls.size()));
  QVERIFY(event->value > event->tolerance);
}

void TestWatch::offChecksStaySilent() {
  // Each going-wrong run with its own check off: no event of that kind.
  Scene nan = bouncingBall(Method::Discrete, Integrator::SymplecticEuler);
  nan.balls[1].velocity.x() = std::numeric_limits<double>::quiet_NaN();
  {
    Simulation sim(nan);
    RunWatch watch(onlyOff(WatchKind::NonFinite));
    QVERIFY(!watch.check(sim));
  }
  {
    Scene s = bouncingBall(Method::Discrete, Integrator::ExplicitEuler);
    s.world.timeStep = 0.1;
    s.balls[1].position.y() = 0.5;
    Simulation sim(s);
    RunWatch watch(onlyOff(WatchKind::EnergyRise));
    QVERIFY(!runWatched(sim, watch, 30.0));
  }
  {
    // Without the escape check, the centre in the box is still an overlap of two radii.
    Simulation sim(crushAgainstBox());
    RunWatch watch(onlyOff(WatchKind::Escape));
    const std::optional<WatchEvent> event = runWatched(sim, watch, 1.0);
    QVERIFY(event);
    QCOMPARE(event->kind, WatchKind::Penetration);
    QCOMPARE(event->ball, 1);
    Simulation quiet(crushAgainstBox());
    RunWatch off(allOff());
    QVERIFY(!runWatched(quiet, off, 1.0));
  }
  {
    Simulation sim(crushInARow());
    RunWatch watch(onlyOff(WatchKind::Penetration));
    QVERIFY(!runWatched(sim, watch, 1.0));
  }
}

void TestWatch::resumedRunGoesOn() {
  // After an event the same problem is not reported again while it lasts, so a resumed run
  // goes on; the event carries the last good step's time.
  Simulation sim(crushAgainstBox());
  RunWatch watch;
  const std::optional<WatchEvent> first = runWatched(sim, watch, 1.0);
  QVERIFY(first);
  QVERIFY(first->lastGoodTime < first->time);
  std::optional<WatchEvent> again;
  for (int i = 0; i < 5 && !again; ++i) {
    sim.step();
    again = watch.check(sim);
  }
  QVERIFY(!again || again->ball != first->ball || again->kind != first->kind);
}

void TestWatch::rebaseTakesNewEnergy() {
  // Stronger gravity does work on the balls: measured against the old baseline, energy would
  // have "risen"; rebased, it has not.
  Scene s = bouncingBall(Method::Exact, Integrator::SymplecticEuler);
  Simulation sim(s);
  RunWatch watch;
  QVERIFY(!watch.check(sim));
  World world = s.world;
  world.gravity = Vec3(0, -30, 0);  // the balls' height is worth three times what it was
  sim.setWorld(world);
  sim.step();
  QVERIFY(watch.check(sim));  // without a rebase the work done looks like a rise
  Simulation again(s);
  RunWatch rebased;
  QVERIFY(!rebased.check(again));
  again.setWorld(world);
  rebased.rebase(again);
  again.step();
  QVERIFY(!rebased.check(again));
}

void TestWatch::settingsValidated() {
  QVERIFY(validateWatchSettings(WatchSettings{}).empty());
  WatchSettings bad;
  bad.penetrationTolerance = -0.1;
  bad.energyRiseTolerance = std::numeric_limits<double>::quiet_NaN();
  const std::vector<ValidationError> errors = validateWatchSettings(bad);
  QCOMPARE(errors.size(), std::size_t(2));
  QCOMPARE(errors[0].path, std::string("watch.energyRise"));
  QCOMPARE(errors[1].path, std::string("watch.penetration"));
  QVERIFY(errors[1].message.find("-0.1") != std::string::npos);
}

QTEST_APPLESS_MAIN(TestWatch)
#include "test_watch.moc"
