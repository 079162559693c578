#include "app/cli/size_bench.h"

#include "app/cli/exit_code.h"
#include "sim/model/scene_builders.h"
#include "sim/simulation.h"

#include <QElapsedTimer>

#include <cmath>
#include <vector>

namespace carom::cli {
namespace {

constexpr double kSmallRadius = 0.01;

// Where the four big balls are: none; apart from the gas (they do not reach it in the run); or
// sweeping through it.
enum class BigBalls { None, Apart, Through };

QString placementName(BigBalls big) {
  switch (big) {
    case BigBalls::None:
      return "none";
    case BigBalls::Apart:
      return "apart";
    case BigBalls::Through:
      return "through";
  }
  return {};
}

// The gas of the plain bench scaled to 1 cm balls, in a room that also holds four balls of
// radius `bigRadius`, as dense as the gas balls, heading for it at 0.5 m/s: two from either side
// along x, two more along z, clear of them. The run is short enough that the gas spreads little
// into the room.
Scene sizesScene(int balls, double bigRadius, BigBalls big) {
  Scene scene = makeGasInBox(balls, 0.25, Vec3::Zero(), 2007, kSmallRadius);
  const double side = scene.planes[1].point.x() - scene.planes[0].point.x();
  scene.planes.clear();
  const double apart = 0.5 * side + bigRadius + 0.5;
  addBoxWalls(scene, std::sqrt(3.0) * apart + bigRadius + 0.2);
  if (big == BigBalls::None) return scene;
  const double reach = big == BigBalls::Apart ? apart : 0.5 * side + bigRadius + 0.01;
  const Vec3 places[] = {{-reach, 0.0, 0.0},
                         {reach, 0.0, 0.0},
                         {0.0, 0.0, -std::sqrt(3.0) * reach},
                         {0.0, 0.0, std::sqrt(3.0) * reach}};
  for (const Vec3& place : places) {
    Ball ball;
    ball.radius = bigRadius;
    ball.mass = std::pow(bigRadius / kSmallRadius, 3.0);
    ball.position = place;
    ball.velocity = -0.5 * place.normalized();
    scene.balls.push_back(ball);
  }
  return scene;
}

struct SizeRow {
  double collisions = 0.0;
  double events = 0.0;
  double simulated = 0.0;
  double wall = 0.0;
  std::string grid;
};

SizeRow measure(Scene scene, Method method, double duration) {
  scene.world.method = method;
  scene.world.timeStep = 1e-2;
  Simulation sim(scene);
  QElapsedTimer timer;
  timer.start();
  sim.advance(duration);
  SizeRow row;
  row.wall = timer.nsecsElapsed() * 1e-9;
  row.simulated = sim.time();
  row.collisions = double(sim.stats().collisions.total());
  row.events = double(sim.stats().events);
  for (const std::string& note : sim.modelNotes())
    if (note.starts_with("cell grid")) row.grid = note;
  return row;
}

QString perMillion(double count, double seconds) {
  return count > 0.0 ? QString::number(seconds / count * 1e6, 'f', 2) : QString("-");
}

}  // namespace

int runSizeBench(const BenchOptions& options, QTextStream& out, QTextStream& err) {
  const int balls = options.quick ? 2000 : 20000;
  const double duration = options.quick ? 0.05 : 0.1;
  out << "method    big balls  radius  ratio  balls  simulated s  collisions  events     "
         "us/collision  us/event  wall s  grid\n";
  out.flush();
  for (Method method : {Method::Exact, Method::Swept}) {
    for (double bigRadius : {0.1, 1.0, 10.0}) {
      for (BigBalls big : {BigBalls::None, BigBalls::Apart, BigBalls::Through}) {
        err << "bench --sizes: " << QString::fromUtf8(methodName(method).data()) << ", balls of "
            << bigRadius << " m " << placementName(big) << "...\n";
        err.flush();
        const SizeRow row = measure(sizesScene(balls, bigRadius, big), method, duration);
        const bool none = big == BigBalls::None;
        out << QString("%1 %2  %3  %4  %5  %6  %7  %8  %9  %10  %11  %12\n")
                   .arg(QString::fromUtf8(methodName(method).data()), -8)
                   .arg(placementName(big), -9)
                   .arg(QString::number(bigRadius) + " m", 6)
                   .arg(none ? QString("-") : QString::number(bigRadius / kSmallRadius), 5)
                   .arg(balls + (none ? 0 : 4), 6)
                   .arg(row.simulated, 11, 'g', 4)
                   .arg(row.collisions, 10, 'f', 0)
                   .arg(row.events, 9, 'f', 0)
                   .arg(perMillion(row.collisions, row.wall), 12)
                   .arg(perMillion(row.events, row.wall), 8)
                   .arg(row.wall, 6, 'f', 2)
                   .arg(QString::fromStdString(row.grid));
        out.flush();
      }
    }
  }
  return kOk;
}

}  // namespace carom::cli
