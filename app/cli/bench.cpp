#include "app/cli/bench.h"

#include "app/cli/exit_code.h"
#include "sim/measure/measures.h"
#include "sim/model/scene_builders.h"
#include "sim/simulation.h"

#include <QElapsedTimer>

#include <algorithm>
#include <cmath>
#include <vector>

namespace carom::cli {
namespace {

// The gases fill a box of six planes; the Galton board (makeGaltonBoard) pours its balls through
// a funnel and pegs into bins, inelastic.
// The rough gas is the gas of perfectly rough spheres (β = 1 and a μ that never binds, so that
// it keeps its energy): it measures what Walton's impacts cost against the plain gas's
// frictionless ones.
enum class BenchScene { Gas, RoughGas, GravityGas, GaltonBoard, MixedSizes };

QString sceneName(BenchScene scene) {
  switch (scene) {
    case BenchScene::Gas:
      return "gas";
    case BenchScene::RoughGas:
      return "rough-gas";
    case BenchScene::GravityGas:
      return "gravity-gas";
    case BenchScene::GaltonBoard:
      return "galton";
    case BenchScene::MixedSizes:
      return "mixed";
  }
  return {};
}

struct BenchCase {
  Method method;
  int balls;
  BenchScene scene;
  double targetCollisions;  // exact, unless `duration` is given: run until this many
  int steps;                // swept and discrete: this many steps
  double duration;          // exact: this much simulated time, when positive
};

struct BenchRow {
  BenchCase bench;
  double simulated = 0.0;
  double collisions = 0.0;
  double events = 0.0;     // exact: every event processed, collisions and cell crossings alike
  double crossings = 0.0;  // exact: balls moving to the next grid cell
  double ballSteps = 0.0;
  double wall = 0.0;
  double drift = 0.0;
};

constexpr double kPackingFraction = 0.25;
constexpr double kPileWallLimit = 120.0;

// The gas under gravity: 5 cm balls at 3 m/s per component in a 1.28 m box (for 1,000 balls),
// so the 9.81 m/s^2 scale height (about 0.9 m) is the size of the box.
Scene gravityGas(int balls) {
  Scene scene = makeGasInBox(balls, kPackingFraction, Vec3(0.0, -9.81, 0.0), 2007, 0.05);
  for (Ball& ball : scene.balls) ball.velocity *= 3.0;
  return scene;
}

// Issue 15's cannonballs among marbles: a gas of 1 cm balls (as the plain gas, scaled) with four
// balls of 10 m rolling in from above, in a box that holds them all. One grid sized by the large
// balls put every small ball in one of a few cells.
Scene mixedSizes(int balls) {
  Scene scene = makeGasInBox(balls, kPackingFraction, Vec3::Zero(), 2007, 0.01);
  scene.planes.clear();
  addBoxWalls(scene, 60.0);
  for (int k = 0; k < 4; ++k) {
    Ball cannonball;
    cannonball.radius = 10.0;
    cannonball.mass = 1e6;
    cannonball.position = Vec3(-45.0 + 30.0 * k, 40.0, 0.0);
    cannonball.velocity = Vec3(0.0, -1.0, 0.0);
    scene.balls.push_back(cannonball);
  }
  return scene;
}

// Each ball spinning at up to 20 rad/s about each axis.
Scene roughGas(int balls) {
  Scene scene = makeGasInBox(balls, kPackingFraction, Vec3::Zero(), 2007);
  scene.world.friction = 1e6;
  scene.world.tangentialRestitution = 1.0;
  for (std::size_t i = 0; i < scene.balls.size(); ++i)
    scene.balls[i].angularVelocity =
        20.0 * Vec3(std::sin(1.0 * i), std::cos(1.7 * i), std::sin(2.3 * i + 0.5));
  return scene;
}

Scene makeScene(const BenchCase& bench) {
  switch (bench.scene) {
    case BenchScene::Gas:
      return makeGasInBox(bench.balls, kPackingFraction, Vec3::Zero(), 2007);
    case BenchScene::RoughGas:
      return roughGas(bench.balls);
    case BenchScene::GravityGas:
      return gravityGas(bench.balls);
    case BenchScene::GaltonBoard:
      return makeGaltonBoard(bench.balls, 2007);
    case BenchScene::MixedSizes:
      return mixedSizes(bench.balls);
  }
  return {};
}

BenchRow measure(const BenchCase& bench) {
  Scene scene = makeScene(bench);
  scene.world.method = bench.method;
  scene.world.timeStep = bench.method == Method::Exact ? 1.0 : 0.01;
  Simulation sim(scene);
  const double initial = sim.totalEnergy();
  QElapsedTimer timer;
  timer.start();
  if (bench.method != Method::Exact) {
    for (int s = 0; s < bench.steps; ++s) sim.step();
  } else if (bench.duration > 0.0) {
    sim.advance(bench.duration);
  } else {
    // Short slices: a Galton board makes thousands of collisions in a millisecond.
    const double slice = bench.scene == BenchScene::Gas ? 1.0 : 0.01;
    while (double(sim.stats().collisions.total()) < bench.targetCollisions) sim.advance(slice);
  }
  BenchRow row{bench};
  row.wall = timer.nsecsElapsed() * 1e-9;
  row.simulated = sim.time();
  row.collisions = double(sim.stats().collisions.total());
  if (bench.method == Method::Exact) {
    row.events = double(sim.stats().events);
    row.crossings = double(sim.stats().cellCrossings);
  }
  row.ballSteps = double(sim.stats().ballSteps);
  // An inelastic scene loses energy by design: no drift to report.
  row.drift = scene.world.restitution < 1.0
                  ? std::nan("")
                  : std::abs(sim.totalEnergy() - initial) / std::abs(initial);
  return row;
}

QString rate(double count, double seconds) {
  return count > 0.0 ? QString::number(count / seconds / 1e6, 'f', 3) : QString("-");
}

}  // namespace

int runBench(const BenchOptions& options, QTextStream& out, QTextStream& err) {
  const bool quick = options.quick;
  std::vector<BenchCase> cases;
  for (int n : quick ? std::vector<int>{500, 1000, 2000} : std::vector<int>{4000, 32000, 108000})
    cases.push_back({Method::Exact, n, BenchScene::Gas, quick ? 1e5 : 3e6, 0, 0.0});
  cases.push_back(
      {Method::Exact, quick ? 1000 : 10000, BenchScene::RoughGas, quick ? 1e5 : 3e6, 0, 0.0});
  const int stepBalls = quick ? 1000 : 10000;
  cases.push_back({Method::Swept, stepBalls, BenchScene::Gas, 0, quick ? 20 : 200, 0.0});
  cases.push_back({Method::Discrete, stepBalls, BenchScene::Gas, 0, quick ? 50 : 1000, 0.0});
  // Mixed sizes under discrete: a grid per size class (sim/broad_phase.h).
  cases.push_back(
      {Method::Discrete, quick ? 2000 : 20000, BenchScene::MixedSizes, 0, quick ? 20 : 60, 0.0});
  cases.push_back(
      {Method::Exact, quick ? 200 : 1000, BenchScene::GravityGas, 0, 0, quick ? 1.0 : 10.0});
  // The Galton board against a gas of as many balls under gravity, and its cost per collision
  // from 1,000 to 100,000 balls.
  const double boardCollisions = quick ? 2e4 : 2e6;
  cases.push_back(
      {Method::Exact, quick ? 500 : 10000, BenchScene::GravityGas, boardCollisions, 0, 0.0});
  for (int n : quick ? std::vector<int>{500} : std::vector<int>{1000, 10000, 100000})
    cases.push_back({Method::Exact, n, BenchScene::GaltonBoard, boardCollisions, 0, 0.0});

  // Events are what an exact run's cost goes by: a free-falling block crosses cells without
  // colliding, so collisions alone make a large board look slow per collision.
  out << "method    balls  scene        simulated s  collisions  Mcoll/s  Mevents/s  crossings  "
         "Mball-steps/s  energy drift  wall s\n";
  out.flush();
  for (const BenchCase& bench : cases) {
    err << "bench: " << QString::fromUtf8(methodName(bench.method).data()) << ", "
        << sceneName(bench.scene) << " of " << bench.balls << " balls...\n";
    err.flush();
    const BenchRow row = measure(bench);
    const QString crossingShare =
        row.events > 0.0 ? QString::number(100.0 * row.crossings / row.events, 'f', 1) + "%"
                         : QString("-");
    out << QString("%1 %2  %3  %4  %5  %6  %7  %8  %9  %10  %11\n")
               .arg(QString::fromUtf8(methodName(bench.method).data()), -8)
               .arg(bench.balls, 6)
               .arg(sceneName(bench.scene), -11)
               .arg(row.simulated, 11, 'g', 4)
               .arg(row.collisions, 10, 'f', 0)
               .arg(rate(row.collisions, row.wall), 7)
               .arg(rate(row.events, row.wall), 9)
               .arg(crossingShare, 9)
               .arg(rate(row.ballSteps, row.wall), 13)
               .arg(std::isnan(row.drift) ? QString("-") : QString::number(row.drift, 'e', 2), 12)
               .arg(row.wall, 6, 'f', 2);
    out.flush();
  }

  // The poured pile (issue 36): how fast it settles, smooth and rough. A pile that churned
  // instead of resting showed as rests and wakes per simulated second that never fell.
  out << "\npile        balls  friction  simulated s  events/sim s  rests/sim s  wakes/sim s  "
         "resting  wall s\n";
  out.flush();
  for (const double friction : {0.0, 0.5}) {
    const int balls = quick ? 60 : 200;
    const double duration = quick ? 2.0 : 20.0;
    err << "bench: exact, pile of " << balls << " balls, friction " << friction << "...\n";
    err.flush();
    Simulation sim(makePouredPile(balls, friction, 7));
    QElapsedTimer timer;
    timer.start();
    // A pile that churns could take hours: the row stops after kPileWallLimit seconds of
    // computing and shows the simulated time reached.
    while (sim.time() < duration && timer.nsecsElapsed() * 1e-9 < kPileWallLimit)
      sim.advanceTo(std::min(duration, sim.time() + 0.5));
    const double wall = timer.nsecsElapsed() * 1e-9;
    const double simulated = sim.time();
    const RunStats& stats = sim.stats();
    out << QString("%1 %2  %3  %4  %5  %6  %7  %8  %9\n")
               .arg(friction > 0.0 ? "rough-pile" : "pile", -10)
               .arg(balls, 6)
               .arg(friction, 8, 'g', 3)
               .arg(simulated, 11, 'g', 4)
               .arg(double(stats.events) / simulated, 12, 'f', 0)
               .arg(double(stats.restings) / simulated, 11, 'f', 1)
               .arg(double(stats.wakes) / simulated, 11, 'f', 1)
               .arg(QString("%1/%2").arg(restingCount(sim.state())).arg(balls), 7)
               .arg(wall, 6, 'f', 2);
    out.flush();
  }
  return kOk;
}

}  // namespace carom::cli
