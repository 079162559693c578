#include "app/cli/run_report.h"

#include "app/cli/method_report.h"

#include "app/cli/exit_code.h"
#include "sim/io/atomic_file.h"
#include "sim/measure/measures.h"
#include "sim/measure/run_watch.h"
#include "sim/simulation.h"

#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <optional>

#include <unistd.h>

namespace carom::cli {
namespace {

// Overlaps are measured over the whole state this many times during a run, besides at every
// contact, so that a missed collision shows up in the report.
constexpr int kOverlapCheckpoints = 100;
// Runs that would take more steps than this (or trajectory rows, a row a step) are refused: at a
// hundred million steps a second it would take three hours, and 1e24 would never end.
constexpr double kMaxSteps = 1e12;
// A run goes in slices between which it checks for Ctrl+C and shows progress; slices grow or
// shrink by whole steps to take about this long.
constexpr double kSliceSeconds = 0.05;
// Progress on a terminal: a bar redrawn this often once the run has taken the first interval.
constexpr double kBarDelaySeconds = 0.5;
constexpr double kBarIntervalSeconds = 0.2;
// Progress elsewhere (a log, a pipe): a plain line this often, so short runs print none.
constexpr double kLineIntervalSeconds = 10.0;

// Set by SIGINT (Ctrl+C); the run loop stops at its next slice.
std::atomic<bool> interruptRequested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

void requestInterrupt(int) {
  interruptRequested.store(true);
}

// Catches Ctrl+C for the length of a run. The handler resets itself, so a second Ctrl+C ends
// the process at once as usual.
class InterruptCatcher {
 public:
  InterruptCatcher() {
    interruptRequested.store(false);
    struct sigaction action {};
    action.sa_handler = requestInterrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;
    installed_ = sigaction(SIGINT, &action, &previous_) == 0;
  }
  ~InterruptCatcher() {
    if (installed_) sigaction(SIGINT, &previous_, nullptr);
  }
  InterruptCatcher(const InterruptCatcher&) = delete;
  InterruptCatcher& operator=(const InterruptCatcher&) = delete;

 private:
  struct sigaction previous_ {};
  bool installed_ = false;
};

// "42 s", "7 min", "3.5 h", "12 days", "3e+05 years": an estimate, two digits at most.
QString roughDuration(double seconds) {
  const auto figure = [](double x, const char* unit) {
    return QString::number(x, 'g', x < 10 ? 2 : (x < 1e5 ? int(std::log10(x)) + 1 : 2)) + ' ' +
           unit;
  };
  if (seconds < 90) return figure(std::max(0.0, std::round(seconds)), "s");
  if (seconds < 90 * 60) return figure(std::round(seconds / 60), "min");
  if (seconds < 48 * 3600) return figure(seconds / 3600, "h");
  if (seconds < 730 * 86400) return figure(std::round(seconds / 86400), "days");
  return figure(seconds / (365.25 * 86400), "years");
}

// Progress of a run on standard error: on a terminal a bar with an estimate of the time left,
// redrawn in place and erased at the end; otherwise a plain line every kLineIntervalSeconds.
class Progress {
 public:
  Progress(QTextStream& err, double duration)
      : err_(err),
        duration_(duration),
        terminal_(err.device() != nullptr && isatty(STDERR_FILENO) == 1) {
    timer_.start();
  }

  bool terminal() const { return terminal_; }

  void update(double simulated) {
    const double wall = timer_.nsecsElapsed() * 1e-9;
    const double fraction = duration_ > 0.0 ? std::clamp(simulated / duration_, 0.0, 1.0) : 1.0;
    const QString left =
        fraction > 0.0 ? "about " + roughDuration(wall * (1.0 - fraction) / fraction) + " left"
                       : QString("time left not known yet");
    const QString figures = QString("%1 of %2 s simulated (%3%) in %4, %5")
                                .arg(QString::number(simulated, 'g', 4))
                                .arg(QString::number(duration_, 'g', 4))
                                .arg(QString::number(100.0 * fraction, 'f', 1))
                                .arg(roughDuration(wall))
                                .arg(left);
    if (terminal_) {
      if (wall < kBarDelaySeconds || wall - shownAt_ < kBarIntervalSeconds) return;
      constexpr int kWidth = 24;
      const int filled = static_cast<int>(fraction * kWidth);
      const QString bar =
          '[' + QString(filled, '#') + QString(kWidth - filled, '.') + "] " + figures;
      // Spaces cover the rest of a longer previous bar.
      err_ << '\r' << bar << QString(std::max<qsizetype>(0, shownWidth_ - bar.size()), ' ');
      shownWidth_ = bar.size();
    } else {
      if (wall - shownAt_ < kLineIntervalSeconds) return;
      err_ << "carom-cli: progress: " << figures << '\n';
    }
    shownAt_ = wall;
    err_.flush();
  }

  // Erases the bar, so that what follows starts on a clean line.
  void finish() {
    if (!terminal_ || shownWidth_ == 0) return;
    err_ << '\r' << QString(shownWidth_, ' ') << '\r';
    err_.flush();
    shownWidth_ = 0;
  }

 private:
  QTextStream& err_;
  double duration_;
  bool terminal_;
  QElapsedTimer timer_;
  double shownAt_ = 0.0;
  qsizetype shownWidth_ = 0;
};

QJsonArray vectorJson(const Vec3& v) {
  return {v.x(), v.y(), v.z()};
}

struct RunResult {
  double initialEnergy = 0.0;
  double finalEnergy = 0.0;
  double wallSeconds = 0.0;     // all the work, from before loading the scene to the report
  double setupSeconds = 0.0;    // loading, checking, building the simulation, first prediction
  double runSeconds = 0.0;      // advancing the simulation
  double measureSeconds = 0.0;  // overlap checks, energies and trajectory rows
  bool interrupted = false;     // stopped by Ctrl+C before the duration asked for
  double durationAsked = 0.0;
  double maxPenetration = 0.0;
  int escaped = 0;
  int resting = 0;
  bool watched = false;                  // --stop-on-divergence
  std::optional<WatchEvent> divergence;  // what stopped the run, when the watch did
  QString divergedBallName;              // the ball's name in the scene, if it has one
};

// "ball 3" or "ball 3 ("cue")".
QString ballText(int ball, const QString& name) {
  QString text = QString("ball %1").arg(ball);
  if (!name.isEmpty()) text += QString(" (\"%1\")").arg(name);
  return text;
}

bool writeTrajectoryRows(io::AtomicFile& file, double time, const std::vector<BallState>& state) {
  QByteArray rows;
  for (int i = 0; i < static_cast<int>(state.size()); ++i) {
    const Vec3& p = state[i].position;
    const Vec3& v = state[i].velocity;
    const Vec3& w = state[i].angularVelocity;
    rows += QByteArray::number(time, 'g', 17) + ',' + QByteArray::number(i);
    for (double x : {p.x(), p.y(), p.z(), v.x(), v.y(), v.z(), w.x(), w.y(), w.z()})
      rows += ',' + QByteArray::number(x, 'g', 17);
    rows += '\n';
  }
  return file.write(rows);
}

int trajectoryFailed(const io::AtomicFile& file, QTextStream& err) {
  err << "carom-cli: writing the trajectory " << file.fileName()
      << " failed: " << file.errorString() << "; no file was written (one there before is kept)\n";
  return kInternalError;
}

// Absent without --stop-on-divergence, null when the watch saw nothing.
QJsonValue divergenceJson(const RunResult& result) {
  if (!result.watched) return QJsonValue::Undefined;
  if (!result.divergence) return QJsonValue::Null;
  const WatchEvent& e = *result.divergence;
  const std::string_view kind = watchKindName(e.kind);
  return QJsonObject{{"kind", QString::fromUtf8(kind.data(), kind.size())},
                     {"ball", e.ball},
                     {"ballName", result.divergedBallName},
                     {"time", e.time},
                     {"lastGoodTime", e.lastGoodTime},
                     {"value", e.value},
                     {"tolerance", e.tolerance},
                     {"text", QString::fromStdString(e.text)}};
}

QJsonObject reportJson(const Simulation& sim, const RunResult& result) {
  const RunStats& stats = sim.stats();
  QJsonObject collisions{{"ballBall", double(stats.collisions.ballBall)},
                         {"ballPlane", double(stats.collisions.ballPlane)},
                         {"ballCylinder", double(stats.collisions.ballCylinder)},
                         {"ballBox", double(stats.collisions.ballBox)}};
  QJsonArray balls;
  for (const BallState& s : sim.state())
    balls.append(QJsonObject{{"position", vectorJson(s.position)},
                             {"velocity", vectorJson(s.velocity)},
                             {"angularVelocity", vectorJson(s.angularVelocity)},
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
      {"setupSeconds", result.setupSeconds},
      {"runSeconds", result.runSeconds},
      {"measureSeconds", result.measureSeconds},
      {"interrupted", result.interrupted},
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
      {"facePhases", double(stats.facePhases)},
      {"minimumBounces", double(stats.minimumBounces)},
      {"restingAtEnd", result.resting},
      {"divergence", divergenceJson(result)},
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
  if (result.interrupted)
    out << "interrupted: by Ctrl+C at " << sim.time() << " of " << result.durationAsked << " s\n";
  if (const std::optional<WatchEvent>& e = result.divergence) {
    const std::string_view kind = watchKindName(e->kind);
    out << "diverged: " << QString::fromUtf8(kind.data(), kind.size()) << ", "
        << ballText(e->ball, result.divergedBallName) << ", at "
        << QString::number(e->time, 'g', 12) << " s (last good step "
        << QString::number(e->lastGoodTime, 'g', 12) << " s): " << QString::fromStdString(e->text)
        << "\n";
  }
  out << "wall: " << result.wallSeconds << " s: set-up " << result.setupSeconds << " s, run "
      << result.runSeconds << " s, measurements " << result.measureSeconds << " s\n";
  out << "collisions: ball-ball " << stats.collisions.ballBall << ", ball-plane "
      << stats.collisions.ballPlane << ", ball-cylinder " << stats.collisions.ballCylinder
      << ", ball-box " << stats.collisions.ballBox << "\n";
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
  if (stats.facePhases > 0)
    out << "friction: " << stats.facePhases
        << " face phases ended (a turning path's segments each count)\n";
  for (const std::string& note : sim.modelNotes())
    out << "model: " << QString::fromStdString(note) << "\n";
}

}  // namespace

int runScene(const Scene& scene, const RunOptions& options, const QElapsedTimer& started,
             QTextStream& out, QTextStream& err, const MethodChoice* choice) {
  // `swept` and `discrete` take a step, and a trajectory writes a row, every time step. `exact`
  // without a trajectory takes none: its run is cut at ticks no shorter than the time step and
  // no more than kMaxSteps of them.
  const double dt = scene.world.timeStep;
  const double stepsAsked = options.duration / dt;
  if ((scene.world.method != Method::Exact || options.trajectoryPath) && stepsAsked > kMaxSteps) {
    err << "carom-cli: --duration " << options.duration << " s at a time step of " << dt << " s is "
        << stepsAsked << " steps, more than the " << kMaxSteps
        << " a run may take; give a shorter duration or a longer --dt\n";
    return kBadInput;
  }
  const double tick = std::max(dt, options.duration / kMaxSteps);
  const std::uint64_t ticks =
      options.duration > 0.0
          ? std::max<std::uint64_t>(1, std::uint64_t(std::ceil(options.duration / tick - 1e-9)))
          : 0;

  // Written to a new file renamed into place at the end: a run that fails leaves no half file.
  io::AtomicFile trajectory(options.trajectoryPath.value_or(QString()));
  if (options.trajectoryPath && !trajectory.open()) {
    err << "carom-cli: cannot write trajectory file " << *options.trajectoryPath << ": "
        << trajectory.errorString() << "\n";
    return kBadInput;
  }

  const InterruptCatcher interruptCatcher;
  Progress progress(err, options.duration);
  if (progress.terminal() && scene.balls.size() > 1000) {
    err << "carom-cli: setting up " << scene.balls.size() << " balls...";
    err.flush();
  }
  Simulation sim(scene);  // builds the grid and predicts every ball's first event
  if (progress.terminal() && scene.balls.size() > 1000) {
    err << "\r\x1b[K";
    err.flush();
  }
  RunResult result;
  result.durationAsked = options.duration;
  result.setupSeconds = started.nsecsElapsed() * 1e-9;

  QElapsedTimer measuring;
  measuring.start();
  result.initialEnergy = sim.totalEnergy();
  if (trajectory.isOpen() &&
      (!trajectory.write(QByteArray("time,ball,x,y,z,vx,vy,vz,wx,wy,wz\n")) ||
       !writeTrajectoryRows(trajectory, 0.0, sim.state())))
    return trajectoryFailed(trajectory, err);
  result.measureSeconds += measuring.nsecsElapsed() * 1e-9;

  // Every piece of the run ends on a whole tick, counted by index (k * tick, never a sum), so
  // that the stepping methods take the same whole steps however the run is cut: with or without
  // a trajectory, and whatever the slices. The last piece ends on the duration itself.
  const auto tickTime = [&](std::uint64_t k) {
    return k >= ticks ? options.duration : static_cast<double>(k) * tick;
  };
  const std::uint64_t checkpointTicks =
      trajectory.isOpen() ? 1
                          : std::max<std::uint64_t>(
                                1, std::uint64_t(std::ceil(double(ticks) / kOverlapCheckpoints)));
  // The watch looks after every tick: the runs it watches go a tick a slice (and keep one if a
  // tick takes longer than a slice).
  std::optional<RunWatch> watch;
  if (options.stopOnDivergence) {
    watch.emplace(options.watch);
    watch->rebase(sim);
    result.watched = true;
  }
  std::uint64_t done = 0;
  std::uint64_t sliceTicks = 1;
  while (done < ticks) {
    if (interruptRequested.load()) {
      result.interrupted = true;
      break;
    }
    const std::uint64_t nextCheckpoint =
        std::min(ticks, (done / checkpointTicks + 1) * checkpointTicks);
    const std::uint64_t next = std::min(nextCheckpoint, done + sliceTicks);
    QElapsedTimer slice;
    slice.start();
    sim.advanceTo(tickTime(next));
    const double sliceSeconds = slice.nsecsElapsed() * 1e-9;
    result.runSeconds += sliceSeconds;
    done = next;
    if (!watch && sliceSeconds < 0.5 * kSliceSeconds && sliceTicks < (std::uint64_t{1} << 62))
      sliceTicks *= 2;
    else if (sliceSeconds > 2.0 * kSliceSeconds && sliceTicks > 1)
      sliceTicks /= 2;
    if (done == nextCheckpoint) {
      measuring.restart();
      const OverlapReport overlaps = measureOverlaps(sim.bodies(), sim.positions());
      result.maxPenetration = std::max(result.maxPenetration, overlaps.maxPenetration);
      if (trajectory.isOpen() && !writeTrajectoryRows(trajectory, sim.time(), sim.state()))
        return trajectoryFailed(trajectory, err);
      result.measureSeconds += measuring.nsecsElapsed() * 1e-9;
    }
    // After the trajectory's row, so that the file ends with the state the watch stopped on.
    if (watch) {
      measuring.restart();
      result.divergence = watch->check(sim);
      result.measureSeconds += measuring.nsecsElapsed() * 1e-9;
      if (result.divergence) {
        const int ball = result.divergence->ball;
        if (ball >= 0 && ball < int(scene.balls.size()))
          result.divergedBallName = QString::fromStdString(scene.balls[ball].name);
        break;
      }
    }
    progress.update(sim.time());
  }
  progress.finish();

  measuring.restart();
  const OverlapReport final = measureOverlaps(sim.bodies(), sim.positions());
  result.maxPenetration =
      std::max({result.maxPenetration, final.maxPenetration, sim.stats().maxPenetration});
  result.escaped = final.escaped;
  result.finalEnergy = sim.totalEnergy();
  result.resting = restingCount(sim.state());
  // Also after Ctrl+C or the watch: the file holds the run so far, as the report does.
  if (trajectory.isOpen() && !trajectory.commit()) return trajectoryFailed(trajectory, err);
  result.measureSeconds += measuring.nsecsElapsed() * 1e-9;
  result.wallSeconds = started.nsecsElapsed() * 1e-9;

  if (options.json) {
    QJsonObject report = reportJson(sim, result);
    if (choice) {
      QJsonObject json = choiceJson(*choice, options.tolerance);
      json["pilotShare"] = result.runSeconds > 0.0 ? choice->pilotSeconds / result.runSeconds : 0.0;
      report["auto"] = json;
    }
    out << QJsonDocument(report).toJson(QJsonDocument::Compact) << "\n";
  } else {
    if (choice) {
      printChoice(out, *choice, options.tolerance);
      out << QString("auto: the pilot took %1 s, %2% of the run's %3 s of computing\n")
                 .arg(choice->pilotSeconds, 0, 'g', 3)
                 .arg(result.runSeconds > 0.0 ? 100.0 * choice->pilotSeconds / result.runSeconds
                                              : 0.0,
                      0, 'f', 1)
                 .arg(result.runSeconds, 0, 'g', 3);
    }
    printText(out, sim, result);
  }
  if (result.divergence) {
    err << "carom-cli: stopped by the watch at " << sim.time() << " of " << options.duration
        << " s: " << QString::fromStdString(result.divergence->text)
        << "; the report covers the run so far\n";
    return kDiverged;
  }
  if (!result.interrupted) return kOk;
  err << "carom-cli: interrupted at " << sim.time() << " of " << options.duration
      << " s; the report covers the run so far\n";
  return kInterrupted;
}

}  // namespace carom::cli
