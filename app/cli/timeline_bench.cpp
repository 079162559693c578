#include "app/cli/timeline_bench.h"

#include "app/cli/exit_code.h"
#include "sim/io/scene_file.h"
#include "sim/measure/run_recording.h"
#include "sim/model/scene_builders.h"
#include "sim/simulation.h"

#include <QElapsedTimer>

#include <algorithm>
#include <memory>
#include <vector>

namespace carom::cli {
namespace {

struct TimelineCase {
  QString name;
  Scene scene;
  double seconds;  // simulated
};

// Frames shown one after another, as a user scrubbing around does: spread over the whole run,
// and in its newest tenth.
constexpr int kScrubs = 16;

}  // namespace

int runTimelineBench(const BenchOptions& options, QTextStream& out, QTextStream& err) {
  const bool quick = options.quick;
  std::vector<TimelineCase> cases;
  io::SceneLoadResult room = io::loadSceneFile(":/scenes/magic-room.json");
  if (!room.scene) {
    err << "carom-cli: " << room.error << "\n";
    return kInternalError;
  }
  cases.push_back({"magic room", *room.scene, quick ? 60.0 : 3600.0});
  const int gasBalls = quick ? 1000 : 10000;
  // The bench's gas (carom-cli bench): elastic balls in a box, no gravity.
  const Scene gas = makeGasInBox(gasBalls, 0.25, Vec3::Zero(), 2007);
  cases.push_back({QString("gas of %1").arg(gasBalls), gas, quick ? 5.0 : 60.0});

  out << "scene            simulated s    frames  record s  keyframes  memory MiB  "
         "scrub ms (mean, max)  newest ms (mean, max)\n";
  out.flush();
  for (const TimelineCase& bench : cases) {
    err << "bench: timeline of the " << bench.name << " for " << bench.seconds << " s...\n";
    err.flush();
    Simulation live(bench.scene);
    RunRecording recording(live);
    QElapsedTimer clock;
    clock.start();
    while (live.time() < bench.seconds) recording.step(live);
    const double recordSeconds = clock.nsecsElapsed() * 1e-9;
    const std::uint64_t frames = recording.frameCount();
    const auto scrub = [&](std::uint64_t first, std::uint64_t last, double& mean, double& max) {
      mean = max = 0.0;
      for (int k = 0; k < kScrubs; ++k) {
        const std::uint64_t frame = first + (last - first) * (2 * k + 1) / (2 * kScrubs);
        clock.restart();
        const std::unique_ptr<Simulation> shown = recording.reproduce(frame);
        const double ms = clock.nsecsElapsed() * 1e-6;
        mean += ms / kScrubs;
        max = std::max(max, ms);
      }
    };
    double mean = 0.0, max = 0.0, newestMean = 0.0, newestMax = 0.0;
    scrub(0, frames, mean, max);
    scrub(frames - frames / 10, frames, newestMean, newestMax);
    out << QString("%1  %2  %3  %4  %5  %6  %7, %8  %9, %10\n")
               .arg(bench.name, -15)
               .arg(live.time(), 11, 'f', 1)
               .arg(frames, 8)
               .arg(recordSeconds, 8, 'f', 1)
               .arg(recording.keyframeCount(), 9)
               .arg(double(recording.memoryBytes()) / (1 << 20), 10, 'f', 1)
               .arg(mean, 10, 'f', 1)
               .arg(max, 8, 'f', 1)
               .arg(newestMean, 11, 'f', 1)
               .arg(newestMax, 8, 'f', 1);
    out.flush();
  }
  return kOk;
}

}  // namespace carom::cli
