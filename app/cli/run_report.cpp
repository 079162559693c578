#include "app/cli/run_report.h"

#include "app/cli/cli.h"
#include "sim/measures.h"
#include "sim/simulation.h"

#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cmath>

namespace carom::cli {
namespace {

// Overlaps are measured over the whole state this many times during a run, besides at every
// contact, so that a missed collision shows up in the report.
constexpr int kOverlapCheckpoints = 100;

QJsonArray vectorJson(const Vec3& v) {
  return {v.x(), v.y(), v.z()};
}

struct RunResult {
  double initialEnergy = 0.0;
  double finalEnergy = 0.0;
  double wallSeconds = 0.0;
  double maxPenetration = 0.0;
  int escaped = 0;
  int resting = 0;
};

bool writeTrajectoryRows(QFile& file, double time, const std::vector<BallState>& state) {
  QByteArray rows;
  for (int i = 0; i < static_cast<int>(state.size()); ++i) {
    const Vec3& p = state[i].position;
    const Vec3& v = state[i].velocity;
    rows += QByteArray::number(time, 'g', 17) + ',' + QByteArray::number(i);
    for (double x : {p.x(), p.y(), p.z(), v.x(), v.y(), v.z()})
      rows += ',' + QByteArray::number(x, 'g', 17);
    rows += '\n';
  }
  return file.write(rows) == rows.size();
}

int trajectoryFailed(const QFile& file, QTextStream& err) {
  err << "carom-cli: writing " << file.fileName() << " failed: " << file.errorString() << "\n";
  return kInternalError;
}

QJsonObject reportJson(const Simulation& sim, const RunResult& result) {
  const RunStats& stats = sim.stats();
  QJsonObject collisions{{"ballBall", double(stats.collisions.ballBall)},
                         {"ballPlane", double(stats.collisions.ballPlane)},
                         {"ballCylinder", double(stats.collisions.ballCylinder)}};
  QJsonArray balls;
  for (const BallState& s : sim.state())
    balls.append(QJsonObject{{"position", vectorJson(s.position)},
                             {"velocity", vectorJson(s.velocity)},
                             {"resting", s.resting}});
  QJsonArray model;
  for (const std::string& note : sim.modelNotes()) model.append(QString::fromStdString(note));
  const World& world = sim.world();
  return QJsonObject{
      {"method", QString::fromUtf8(methodName(world.method))},
      {"integrator", QString::fromUtf8(integratorName(world.integrator))},
      {"timeStep", world.timeStep},
      {"simulatedTime", sim.time()},
      {"wallSeconds", result.wallSeconds},
      {"collisions", collisions},
      {"energy", QJsonObject{{"initial", result.initialEnergy}, {"final", result.finalEnergy}}},
      {"maxPenetration", result.maxPenetration},
      {"escaped", result.escaped},
      {"events", double(stats.events)},
      {"cellCrossings", double(stats.cellCrossings)},
      {"staleEvents", double(stats.staleEvents)},
      {"steps", double(stats.steps)},
      {"restings", double(stats.restings)},
      {"wakes", double(stats.wakes)},
      {"minimumBounces", double(stats.minimumBounces)},
      {"restingAtEnd", result.resting},
      {"model", model},
      {"balls", balls},
  };
}

void printText(QTextStream& out, const Simulation& sim, const RunResult& result) {
  const RunStats& stats = sim.stats();
  const World& world = sim.world();
  out << "method: " << QString::fromUtf8(methodName(world.method));
  if (world.method != Method::Exact)
    out << " (" << QString::fromUtf8(integratorName(world.integrator)) << ", dt " << world.timeStep
        << " s)";
  out << "\nsimulated: " << sim.time() << " s in " << result.wallSeconds << " s wall\n";
  out << "collisions: ball-ball " << stats.collisions.ballBall << ", ball-plane "
      << stats.collisions.ballPlane << ", ball-cylinder " << stats.collisions.ballCylinder << "\n";
  const double drift = result.initialEnergy != 0.0 ? (result.finalEnergy - result.initialEnergy) /
                                                         std::abs(result.initialEnergy)
                                                   : result.finalEnergy - result.initialEnergy;
  out << "energy: initial " << QString::number(result.initialEnergy, 'g', 12) << ", final "
      << QString::number(result.finalEnergy, 'g', 12) << " (relative change "
      << QString::number(drift, 'g', 3) << ")\n";
  out << "max penetration: " << QString::number(result.maxPenetration, 'g', 3)
      << ", escaped: " << result.escaped << ", resting at end: " << result.resting << "\n";
  out << "events: " << stats.events << " (cell crossings " << stats.cellCrossings << ", stale "
      << stats.staleEvents << "), steps: " << stats.steps << "\n";
  out << "rest policy: " << stats.restings << " rests, " << stats.wakes << " wakes, "
      << stats.minimumBounces << " minimum bounces\n";
  for (const std::string& note : sim.modelNotes())
    out << "model: " << QString::fromStdString(note) << "\n";
}

}  // namespace

int runScene(const Scene& scene, const RunOptions& options, QTextStream& out, QTextStream& err) {
  QFile trajectory;
  if (options.trajectoryPath) {
    trajectory.setFileName(*options.trajectoryPath);
    if (!trajectory.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text)) {
      err << "carom-cli: cannot write trajectory file " << *options.trajectoryPath << ": "
          << trajectory.errorString() << "\n";
      return kBadInput;
    }
  }

  Simulation sim(scene);
  RunResult result;
  result.initialEnergy = sim.totalEnergy();
  if (trajectory.isOpen() && (trajectory.write("time,ball,x,y,z,vx,vy,vz\n") < 0 ||
                              !writeTrajectoryRows(trajectory, 0.0, sim.state())))
    return trajectoryFailed(trajectory, err);

  // Chunks are whole time steps so that `swept` and `discrete` take the same steps as one call.
  const double dt = scene.world.timeStep;
  const double chunk =
      trajectory.isOpen()
          ? dt
          : std::max(dt, std::ceil(options.duration / kOverlapCheckpoints / dt) * dt);
  QElapsedTimer timer;
  timer.start();
  double measured = 0.0;
  // Chunk ends come from a counter, not a running sum, and a step that divides the duration up
  // to rounding gives no extra sliver of a chunk at the end.
  const double chunks = std::max(1.0, std::ceil(options.duration / chunk - 1e-9));
  for (double k = 1; sim.time() < options.duration; ++k) {
    sim.advance((k >= chunks ? options.duration : std::min(options.duration, k * chunk)) -
                sim.time());
    const double before = timer.nsecsElapsed() * 1e-9;
    const OverlapReport overlaps = measureOverlaps(sim.bodies(), sim.positions());
    result.maxPenetration = std::max(result.maxPenetration, overlaps.maxPenetration);
    if (trajectory.isOpen() && !writeTrajectoryRows(trajectory, sim.time(), sim.state()))
      return trajectoryFailed(trajectory, err);
    measured += timer.nsecsElapsed() * 1e-9 - before;
  }
  result.wallSeconds = timer.nsecsElapsed() * 1e-9 - measured;

  const OverlapReport final = measureOverlaps(sim.bodies(), sim.positions());
  result.maxPenetration =
      std::max({result.maxPenetration, final.maxPenetration, sim.stats().maxPenetration});
  result.escaped = final.escaped;
  result.finalEnergy = sim.totalEnergy();
  for (const BallState& s : sim.state()) result.resting += s.resting ? 1 : 0;

  if (trajectory.isOpen() && !trajectory.flush()) return trajectoryFailed(trajectory, err);
  if (options.json)
    out << QJsonDocument(reportJson(sim, result)).toJson(QJsonDocument::Compact) << "\n";
  else
    printText(out, sim, result);
  return kOk;
}

}  // namespace carom::cli
