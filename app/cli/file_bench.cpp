#include "app/cli/file_bench.h"

#include "app/cli/exit_code.h"
#include "sim/io/scene_file.h"
#include "sim/model/scene_builders.h"
#include "sim/simulation.h"

#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>

#include <optional>
#include <string>

namespace carom::cli {
namespace {

constexpr double kMiB = 1024.0 * 1024.0;

// Resident memory now and at its highest since resetPeak(), in bytes, from /proc (Linux);
// nothing elsewhere.
std::optional<double> statusBytes(const char* field) {
  QFile status("/proc/self/status");
  if (!status.open(QIODevice::ReadOnly)) return std::nullopt;
  for (const QByteArray& line : status.readAll().split('\n'))
    if (line.startsWith(field))
      return line.mid(qstrlen(field)).trimmed().split(' ')[0].toDouble() * 1024.0;
  return std::nullopt;
}

// Writing 5 to clear_refs starts the peak (VmHWM) again from the resident memory now.
void resetPeak() {
  QFile clear("/proc/self/clear_refs");
  if (clear.open(QIODevice::WriteOnly)) clear.write("5");
}

// Seconds and the most memory it added at its peak.
struct Phase {
  double seconds = 0.0;
  std::optional<double> peakAddedBytes;
};

template <typename Work>
Phase measure(Work&& work) {
  resetPeak();
  const std::optional<double> before = statusBytes("VmRSS:");
  QElapsedTimer clock;
  clock.start();
  work();
  Phase phase;
  phase.seconds = clock.nsecsElapsed() * 1e-9;
  const std::optional<double> peak = statusBytes("VmHWM:");
  if (before && peak) phase.peakAddedBytes = *peak - *before;
  return phase;
}

QString line(const QString& name, const Phase& phase, double fileBytes) {
  const QString memory = phase.peakAddedBytes
                             ? QString("%1 MiB (%2 x the file)")
                                   .arg(*phase.peakAddedBytes / kMiB, 0, 'f', 1)
                                   .arg(*phase.peakAddedBytes / fileBytes, 0, 'f', 2)
                             : QString("-");
  return QString("%1  %2 s  %3\n").arg(name, -28).arg(phase.seconds, 6, 'f', 2).arg(memory);
}

}  // namespace

int runFileBench(const BenchOptions& options, QTextStream& out, QTextStream& err) {
  const int balls = options.quick ? 100000 : 1000000;
  QTemporaryDir dir;
  if (!dir.isValid()) {
    err << "carom-cli: cannot make a temporary folder: " << dir.errorString() << "\n";
    return kInternalError;
  }
  const QString fileName = dir.filePath("balls.json");
  err << "bench: a gas of " << balls << " balls under gravity, saved, loaded and predicted...\n";
  err.flush();
  std::optional<Scene> scene = makeGasInBox(balls, 0.25, Vec3(0.0, -9.81, 0.0), 7, 0.01);
  QString error;
  bool saved = false;
  const Phase save = measure([&] { saved = io::saveSceneFile(*scene, fileName, &error); });
  if (!saved) {
    err << "carom-cli: " << error << "\n";
    return kInternalError;
  }
  scene.reset();  // what the load takes is measured from what the process held before it
  const double fileBytes = static_cast<double>(QFileInfo(fileName).size());
  io::SceneLoadResult loaded;
  const Phase load = measure([&] { loaded = io::loadSceneFile(fileName); });
  if (!loaded.scene) {
    err << "carom-cli: " << loaded.error << "\n";
    return kInternalError;
  }
  std::optional<Simulation> simulation;
  const Phase predict = measure([&] { simulation.emplace(*loaded.scene); });

  out << QString("scene file of %1 balls: %2 MiB\n").arg(balls).arg(fileBytes / kMiB, 0, 'f', 1);
  out << "phase                         time    most memory added\n";
  out << line("save (atomic)", save, fileBytes);
  out << line("load and validate", load, fileBytes);
  out << line("first prediction (exact)", predict, fileBytes);
  out.flush();
  return kOk;
}

}  // namespace carom::cli
