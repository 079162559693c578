#include "app/window_benchmarks.h"

#include "sim/model/scene_builders.h"
#include "ui/editor/outline_dock.h"
#include "ui/editor/properties_dock.h"
#include "ui/editor/scene_document.h"
#include "ui/main_window.h"
#include "ui/render/scene_view.h"
#include "ui/run/run_session.h"
#include "ui/run/simulation_snapshot.h"
#include "ui/sound_thread.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QItemSelectionModel>
#include <QLineEdit>
#include <QTimer>
#include <QTreeView>

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <vector>

namespace carom::app {
namespace {

using ui::MainWindow;

constexpr QSize kBenchViewSize(1280, 720);
constexpr int kBenchWarmUpMs = 1000;  // scene upload, first frames, the worker's first batches
constexpr int kRenderRunMs = 5000;
constexpr int kStallProbeMs = 5;
constexpr int kStressReportSeconds = 10;
// The stress gas: its balls' speeds are scaled up until collisions come at about 10,000 a second.
constexpr int kStressBalls = 1000;
constexpr double kStressSpeedScale = 2.2;
// Resident memory swings by tens of MiB from second to second here (Mesa's buffers, explosions);
// it is flat when the highest sample of the second half of the run is within 10 % + 4 MiB of the
// highest of the first half.
constexpr double kFlatFraction = 0.10;
constexpr double kFlatSlackMiB = 4.0;

// A nested loop rather than polling processEvents, which would keep a core busy.
void processEventsFor(int milliseconds) {
  QEventLoop loop;
  QTimer::singleShot(milliseconds, Qt::PreciseTimer, &loop, &QEventLoop::quit);
  loop.exec();
}

double percentile(const std::vector<double>& sorted, double fraction) {
  if (sorted.empty()) return 0.0;
  const auto index = static_cast<std::size_t>(fraction * static_cast<double>(sorted.size() - 1));
  return sorted[index];
}

double mean(const std::vector<double>& values) {
  return values.empty() ? 0.0 : std::accumulate(values.begin(), values.end(), 0.0) / values.size();
}

// Resident memory of this process, MiB.
double residentMiB() {
  QFile statm(QStringLiteral("/proc/self/statm"));
  if (!statm.open(QIODevice::ReadOnly)) return 0.0;
  const QList<QByteArray> fields = statm.readAll().split(' ');
  return fields.size() > 1 ? fields[1].toDouble() * 4096.0 / (1024.0 * 1024.0) : 0.0;
}

// A busy GUI thread delays every timer: the gaps between this timer's ticks beyond its period are
// the stalls, the time the window could not have answered the user.
class StallProbe {
 public:
  explicit StallProbe(QObject* context) {
    timer_.setTimerType(Qt::PreciseTimer);
    QObject::connect(&timer_, &QTimer::timeout, context, [this] {
      if (clock_.isValid()) gaps_.push_back(clock_.nsecsElapsed() * 1e-6);
      clock_.start();
    });
    timer_.start(kStallProbeMs);
  }
  // Gaps since the last call, ms, sorted.
  std::vector<double> takeGaps() {
    std::vector<double> gaps = std::move(gaps_);
    gaps_.clear();
    std::sort(gaps.begin(), gaps.end());
    return gaps;
  }

 private:
  QTimer timer_;
  QElapsedTimer clock_;
  std::vector<double> gaps_;
};

// Shows `window` grown until its view alone is 1280x720: the toolbar, status bar and docks
// take their share.
render::SceneView* showWithBenchViewSize(MainWindow& window) {
  auto* view = qobject_cast<render::SceneView*>(window.view());
  if (!view) return nullptr;
  window.show();
  processEventsFor(300);
  window.resize(window.size() + kBenchViewSize - view->size());
  processEventsFor(300);
  return view;
}

void printView(const render::SceneView& view) {
  const QSize shown = view.size();
  std::printf("view: %dx%d (device pixel ratio %.2f)%s\n", shown.width(), shown.height(),
              view.devicePixelRatioF(),
              shown == kBenchViewSize ? "" : "  -- smaller than the 1280x720 asked for");
  std::printf("antialiasing: %s (%s renderer)\n", view.antialiasing() ? "4x" : "off",
              view.softwareRenderer() ? "software" : "hardware");
}

// Frame figures of one scene, measured over kRenderRunMs after a warm-up.
struct FrameFigures {
  std::size_t frames = 0;
  double seconds = 0.0;
  std::vector<double> intervals;  // between consecutive frames, ms, sorted
  double meanPaintMs = 0.0;       // paintGL with glFinish
  double longestStallMs = 0.0;

  double fps() const { return seconds > 0.0 ? frames / seconds : 0.0; }
  double meanIntervalMs() const { return mean(intervals); }
};

FrameFigures measureFrames(MainWindow& window, render::SceneView& view) {
  FrameFigures figures;
  std::vector<double> paintTimes;
  QElapsedTimer frameClock;
  bool measuring = false;
  const QMetaObject::Connection counting =
      QObject::connect(&view, &render::SceneView::frameRendered, &window, [&](double paintMs) {
        if (!measuring) return;
        if (frameClock.isValid()) figures.intervals.push_back(frameClock.nsecsElapsed() * 1e-6);
        paintTimes.push_back(paintMs);
        frameClock.start();
      });
  StallProbe probe(&window);
  window.setRunning(true);
  processEventsFor(kBenchWarmUpMs);
  probe.takeGaps();
  measuring = true;
  QElapsedTimer run;
  run.start();
  processEventsFor(kRenderRunMs);
  figures.seconds = run.nsecsElapsed() * 1e-9;
  measuring = false;
  window.setRunning(false);
  QObject::disconnect(counting);
  const std::vector<double> gaps = probe.takeGaps();
  std::sort(figures.intervals.begin(), figures.intervals.end());
  figures.frames = paintTimes.size();
  figures.meanPaintMs = mean(paintTimes);
  figures.longestStallMs = gaps.empty() ? 0.0 : gaps.back();
  return figures;
}

void printFigures(const char* name, const FrameFigures& figures, const FrameFigures* floor) {
  const auto ratio = [](double value, double base) { return base > 0.0 ? value / base : 0.0; };
  std::printf("%s: %zu frames in %.2f s, %.1f fps\n", name, figures.frames, figures.seconds,
              figures.fps());
  std::printf("  frame interval ms: mean %.2f  median %.2f  p95 %.2f  max %.2f\n",
              figures.meanIntervalMs(), percentile(figures.intervals, 0.5),
              percentile(figures.intervals, 0.95),
              figures.intervals.empty() ? 0.0 : figures.intervals.back());
  std::printf("  paintGL ms (incl. glFinish): mean %.2f\n", figures.meanPaintMs);
  std::printf("  longest GUI stall ms: %.2f\n", figures.longestStallMs);
  if (floor)
    std::printf("  to the floor: frame interval x%.2f (median x%.2f), paintGL x%.2f\n",
                ratio(figures.meanIntervalMs(), floor->meanIntervalMs()),
                ratio(percentile(figures.intervals, 0.5), percentile(floor->intervals, 0.5)),
                ratio(figures.meanPaintMs, floor->meanPaintMs));
}

}  // namespace

int benchmarkRender(int ballCount) {
  const Scene gas = makeGasInBox(ballCount, 0.25, Vec3::Zero(), 2007);
  Scene box = gas;
  box.balls.clear();
  MainWindow window;
  window.openScene(box, {}, QStringLiteral("empty box"));
  render::SceneView* view = showWithBenchViewSize(window);
  if (!view) return 1;
  std::printf("balls: %d\n", ballCount);
  printView(*view);
  // The same window and box without balls: what composing the window costs whatever is drawn.
  const FrameFigures floor = measureFrames(window, *view);
  printFigures("floor (no balls)", floor, nullptr);
  window.openScene(gas, {}, QStringLiteral("gas of %1 balls").arg(ballCount));
  const FrameFigures balls = measureFrames(window, *view);
  printFigures(qPrintable(QStringLiteral("%1 balls").arg(ballCount)), balls, &floor);
  std::fflush(stdout);
  return 0;
}

int benchmarkOpen(const QString& fileName) {
  MainWindow window;
  render::SceneView* view = showWithBenchViewSize(window);
  if (!view) return 1;
  bool framed = false;
  QObject::connect(view, &render::SceneView::frameRendered, &window,
                   [&](double) { framed = true; });
  // Until the view has the scene `before` is not (huge scenes come to it after the document
  // has them) and has drawn a whole picture of it.
  const auto waitForPictureOfNewScene =
      [&](const std::shared_ptr<const render::RenderScene>& before, const QElapsedTimer& clock) {
        while (view->scene() == before && clock.elapsed() < 600000) processEventsFor(10);
        framed = false;
        while (!framed && clock.elapsed() < 600000) processEventsFor(10);
      };
  QElapsedTimer clock;
  clock.start();
  const auto sceneBefore = view->scene();
  if (!window.openFile(fileName, false)) return 1;
  const double openSeconds = clock.nsecsElapsed() * 1e-9;
  waitForPictureOfNewScene(sceneBefore, clock);
  const double shownSeconds = clock.nsecsElapsed() * 1e-9;
  const int balls = static_cast<int>(window.document()->scene().balls.size());
  std::printf("scene: %s, %d balls\n", qPrintable(fileName), balls);
  printView(*view);
  std::printf("open (load, validate, document): %.2f s\n", openSeconds);
  std::printf("first frame of it: %.2f s after the open began\n", shownSeconds);
  std::printf("resident memory: %.0f MiB\n", residentMiB());

  // Running: when the first step arrives, and how far the run gets in kRenderRunMs.
  int frames = 0;
  QObject::connect(view, &render::SceneView::frameRendered, &window, [&](double) { ++frames; });
  const auto simulatedTime = [&] {
    const auto snapshot = window.simulation().latest();
    return snapshot ? snapshot->time : 0.0;
  };
  StallProbe probe(&window);
  clock.restart();
  window.setRunning(true);
  while (simulatedTime() <= 0.0 && clock.elapsed() < 600000) processEventsFor(10);
  const double firstStepSeconds = clock.nsecsElapsed() * 1e-9;
  frames = 0;
  probe.takeGaps();
  const double simulatedBefore = simulatedTime();
  clock.restart();
  processEventsFor(kRenderRunMs);
  const double runSeconds = clock.nsecsElapsed() * 1e-9;
  const std::vector<double> gaps = probe.takeGaps();
  std::printf(
      "run: first step shown %.2f s after Run; then %.3f s simulated in %.1f s, %.1f fps, "
      "longest GUI stall %.0f ms\n",
      firstStepSeconds, simulatedTime() - simulatedBefore, runSeconds, frames / runSeconds,
      gaps.empty() ? 0.0 : gaps.back());

  // The outline and the properties while it runs: the last ball selected in the tree.
  editor::OutlineDock* outline = window.outlineDock();
  QElapsedTimer action;
  action.start();
  outline->tree()->expand(outline->model()->groupIndex(editor::ObjectKind::Ball));
  processEventsFor(0);
  const double expandMs = action.nsecsElapsed() * 1e-6;
  action.restart();
  const QModelIndex last = outline->model()->indexOf({editor::ObjectKind::Ball, balls - 1});
  outline->tree()->selectionModel()->select(
      last, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
  outline->tree()->scrollTo(last);
  processEventsFor(0);
  const double selectMs = action.nsecsElapsed() * 1e-6;
  std::printf(
      "outline: the balls' group opened in %.0f ms; the last ball selected and shown in "
      "%.0f ms (properties: \"%s\")\n",
      expandMs, selectMs, qPrintable(window.propertiesDock()->heading()));

  // Properties: the last ball's mass typed in while it runs, which restarts the run.
  auto* mass = window.propertiesDock()->findChild<QLineEdit*>(QStringLiteral("mass"));
  if (!mass) {
    std::printf("properties: no mass field\n");
    return 1;
  }
  probe.takeGaps();
  const auto sceneBeforeEdit = view->scene();
  action.restart();
  mass->setText(QStringLiteral("2"));
  mass->setModified(true);  // as typing leaves it
  emit mass->editingFinished();
  const double editMs = action.nsecsElapsed() * 1e-6;
  waitForPictureOfNewScene(sceneBeforeEdit, action);
  const double editShownMs = action.nsecsElapsed() * 1e-6;
  processEventsFor(kRenderRunMs);
  const std::vector<double> editGaps = probe.takeGaps();
  std::printf(
      "properties: the last ball's mass typed in and taken in %.0f ms (mass now %g), the "
      "restarted run's first picture %.0f ms after; longest GUI stall in the %.1f s after it "
      "%.0f ms\n",
      editMs, window.document()->scene().balls.back().mass, editShownMs, kRenderRunMs * 1e-3,
      editGaps.empty() ? 0.0 : editGaps.back());
  window.setRunning(false);
  std::printf("resident memory: %.0f MiB\n", residentMiB());
  std::fflush(stdout);
  return 0;
}

int benchmarkStress(int seconds) {
  Scene gas = makeGasInBox(kStressBalls, 0.25, Vec3::Zero(), 2007);
  for (Ball& ball : gas.balls) ball.velocity *= kStressSpeedScale;
  MainWindow window;
  window.openScene(gas, {}, QStringLiteral("stress gas"));
  render::SceneView* view = showWithBenchViewSize(window);
  if (!view) return 1;
  view->setExplosionsEnabled(true);
  window.sound().setMuted(false);

  int frames = 0;
  QObject::connect(view, &render::SceneView::frameRendered, &window, [&](double) { ++frames; });
  StallProbe probe(&window);
  window.setRunning(true);
  processEventsFor(kBenchWarmUpMs);
  probe.takeGaps();

  std::printf("stress: %d balls, %d s, sound %s\n", kStressBalls, seconds,
              window.sound().available() ? "on" : "unavailable");
  printView(*view);
  std::printf("%6s %13s %6s %16s %16s %9s %11s %14s %14s\n", "t s", "collisions/s", "fps",
              "longest stall ms", "p99 stall ms", "RSS MiB", "explosions", "sounds played",
              "sounds dropped");
  const auto collisionsSoFar = [&] {
    const auto snapshot = window.simulation().latest();
    return snapshot ? snapshot->stats.collisions.total() : std::uint64_t{0};
  };
  std::vector<double> memory;  // one sample a second
  std::vector<double> allGaps;
  const std::uint64_t firstCollisions = collisionsSoFar();
  std::uint64_t collisions = firstCollisions;
  int played = window.sound().playedCount();
  int dropped = window.sound().droppedCount();
  int mostExplosions = 0;
  QElapsedTimer run;
  // The sound server going and coming back (scripts/faults.sh kills and restarts it), on the
  // table's clock.
  QObject::connect(
      &window.sound(), &ui::SoundThread::availabilityChanged, &window, [&run](bool available) {
        std::printf("sound %s at %.1f s\n", available ? "back" : "lost", run.nsecsElapsed() * 1e-9);
        std::fflush(stdout);
      });
  run.start();
  for (int elapsed = 0; elapsed < seconds; elapsed += kStressReportSeconds) {
    const int slice = std::min(kStressReportSeconds, seconds - elapsed);
    const int framesBefore = frames;
    int explosions = 0;
    // Sampled each second: how many explosions are alive in the view.
    for (int s = 0; s < slice; ++s) {
      processEventsFor(1000);
      explosions = std::max(explosions, view->liveExplosions());
      memory.push_back(residentMiB());
    }
    mostExplosions = std::max(mostExplosions, explosions);
    const std::uint64_t nowCollisions = collisionsSoFar();
    const std::vector<double> gaps = probe.takeGaps();
    allGaps.insert(allGaps.end(), gaps.begin(), gaps.end());
    std::printf("%6d %13.0f %6.1f %16.1f %16.1f %9.1f %11d %14d %14d\n", elapsed + slice,
                double(nowCollisions - collisions) / slice, double(frames - framesBefore) / slice,
                gaps.empty() ? 0.0 : gaps.back(), percentile(gaps, 0.99), memory.back(), explosions,
                window.sound().playedCount() - played, window.sound().droppedCount() - dropped);
    std::fflush(stdout);
    collisions = nowCollisions;
    played = window.sound().playedCount();
    dropped = window.sound().droppedCount();
  }
  const double runSeconds = run.nsecsElapsed() * 1e-9;
  window.setRunning(false);

  std::sort(allGaps.begin(), allGaps.end());
  const auto half = memory.begin() + static_cast<std::ptrdiff_t>(memory.size() / 2);
  const double firstHalf = *std::max_element(memory.begin(), half);
  const double secondHalf = *std::max_element(half, memory.end());
  const bool flat = secondHalf <= firstHalf * (1.0 + kFlatFraction) + kFlatSlackMiB;
  std::printf("collisions: %llu in %.1f s (%.0f a second)\n",
              static_cast<unsigned long long>(collisions - firstCollisions), runSeconds,
              double(collisions - firstCollisions) / runSeconds);
  std::printf("frames: %d (%.1f fps)\n", frames, frames / runSeconds);
  std::printf("GUI stalls ms: median %.1f  p99 %.1f  p99.9 %.1f  longest %.1f\n",
              percentile(allGaps, 0.5), percentile(allGaps, 0.99), percentile(allGaps, 0.999),
              allGaps.empty() ? 0.0 : allGaps.back());
  std::printf("most live explosions: %d (limit %d)\n", mostExplosions, view->explosionLimit());
  std::printf("sounds: %d played, %d dropped%s\n", window.sound().playedCount(),
              window.sound().droppedCount(), window.sound().available() ? "" : " (no sound)");
  std::printf("memory MiB: highest %.1f in the first half, %.1f in the second, lowest %.1f\n",
              firstHalf, secondHalf, *std::min_element(memory.begin(), memory.end()));
  std::printf("memory flat: %s\n", flat ? "yes" : "no");
  std::fflush(stdout);
  return 0;
}

}  // namespace carom::app
