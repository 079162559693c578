#include "app/cli/bench.h"

#include "app/cli/cli.h"
#include "sim/scene_builders.h"
#include "sim/simulation.h"

#include <QElapsedTimer>

#include <cmath>
#include <vector>

namespace carom::cli {
namespace {

struct BenchCase {
  Method method;
  int balls;
  bool gravity;
  double targetCollisions;  // exact without gravity: run until this many
  int steps;                // swept and discrete: this many steps
  double duration;          // exact with gravity: this much simulated time
};

struct BenchRow {
  BenchCase bench;
  double simulated = 0.0;
  double collisions = 0.0;
  double ballSteps = 0.0;
  double wall = 0.0;
  double drift = 0.0;
};

constexpr double kPackingFraction = 0.25;

// The gas under gravity: 5 cm balls at 3 m/s per component in a 1.28 m box (for 1,000 balls),
// so the 9.81 m/s^2 scale height (about 0.9 m) is the size of the box.
Scene gravityGas(int balls) {
  Scene scene = makeGasInBox(balls, kPackingFraction, Vec3(0.0, -9.81, 0.0), 2007, 0.05);
  for (Ball& ball : scene.balls) ball.velocity *= 3.0;
  return scene;
}

BenchRow measure(const BenchCase& bench) {
  Scene scene = bench.gravity ? gravityGas(bench.balls)
                              : makeGasInBox(bench.balls, kPackingFraction, Vec3::Zero(), 2007);
  scene.world.method = bench.method;
  scene.world.timeStep = bench.method == Method::Exact ? 1.0 : 0.01;
  Simulation sim(scene);
  const double initial = sim.totalEnergy();
  QElapsedTimer timer;
  timer.start();
  if (bench.method != Method::Exact) {
    for (int s = 0; s < bench.steps; ++s) sim.step();
  } else if (bench.gravity) {
    sim.advance(bench.duration);
  } else {
    while (double(sim.stats().collisions.total()) < bench.targetCollisions) sim.advance(1.0);
  }
  BenchRow row{bench};
  row.wall = timer.nsecsElapsed() * 1e-9;
  row.simulated = sim.time();
  row.collisions = double(sim.stats().collisions.total());
  row.ballSteps = double(sim.stats().ballSteps);
  row.drift = std::abs(sim.totalEnergy() - initial) / std::abs(initial);
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
    cases.push_back({Method::Exact, n, false, quick ? 1e5 : 3e6, 0, 0.0});
  const int stepBalls = quick ? 1000 : 10000;
  cases.push_back({Method::Swept, stepBalls, false, 0, quick ? 20 : 200, 0.0});
  cases.push_back({Method::Discrete, stepBalls, false, 0, quick ? 50 : 1000, 0.0});
  cases.push_back({Method::Exact, quick ? 200 : 1000, true, 0, 0, quick ? 1.0 : 10.0});

  out << "method    balls  gravity  simulated s  collisions  Mcoll/s  Mball-steps/s  energy drift  "
         "wall s\n";
  out.flush();
  for (const BenchCase& bench : cases) {
    err << "bench: " << QString::fromUtf8(methodName(bench.method).data()) << " with "
        << bench.balls << " balls" << (bench.gravity ? " under gravity" : "") << "...\n";
    err.flush();
    const BenchRow row = measure(bench);
    out << QString("%1 %2  %3  %4  %5  %6  %7  %8  %9\n")
               .arg(QString::fromUtf8(methodName(bench.method).data()), -8)
               .arg(bench.balls, 6)
               .arg(bench.gravity ? "yes" : "no", -7)
               .arg(row.simulated, 11, 'g', 4)
               .arg(row.collisions, 10, 'f', 0)
               .arg(rate(row.collisions, row.wall), 7)
               .arg(rate(row.ballSteps, row.wall), 13)
               .arg(row.drift, 12, 'e', 2)
               .arg(row.wall, 6, 'f', 2);
    out.flush();
  }
  return kOk;
}

}  // namespace carom::cli
