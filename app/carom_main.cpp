#include "language.h"
#include "main_window.h"
#include "scene_builders.h"
#include "scene_file.h"
#include "scene_view.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <vector>

namespace {

constexpr QSize kBenchViewSize(1280, 720);
constexpr int kBenchWarmUpMs = 1000;  // scene upload, first frames, the worker's first batches
constexpr int kBenchRunMs = 5000;
constexpr int kStallProbeMs = 5;

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

// --bench-render: a gas of `ballCount` balls running in the real window, its view at 1280x720;
// frame intervals and the longest stall of the GUI thread over 5 s, printed to stdout.
int benchmarkRender(int ballCount) {
  carom::ui::MainWindow window;
  window.openScene(carom::makeGasInBox(ballCount, 0.25, carom::Vec3::Zero(), 2007), {},
                   QStringLiteral("gas of %1 balls").arg(ballCount));
  auto* view = qobject_cast<carom::render::SceneView*>(window.view());
  if (!view) return 1;
  window.show();
  processEventsFor(300);
  // The toolbar, status bar and docks take their share: grow the window until the view alone
  // has the size asked for.
  window.resize(window.size() + kBenchViewSize - view->size());
  processEventsFor(300);

  std::vector<double> intervals;  // between consecutive frames, ms
  std::vector<double> paintTimes;
  QElapsedTimer frameClock;
  bool measuring = false;
  QObject::connect(view, &carom::render::SceneView::frameRendered, &window, [&](double paintMs) {
    if (!measuring) return;
    if (frameClock.isValid()) intervals.push_back(frameClock.nsecsElapsed() * 1e-6);
    paintTimes.push_back(paintMs);
    frameClock.start();
  });
  // A busy GUI thread delays every timer; the largest gap between these ticks is its longest
  // stall.
  QTimer probe;
  probe.setTimerType(Qt::PreciseTimer);
  QElapsedTimer probeClock;
  double longestStall = 0.0;
  QObject::connect(&probe, &QTimer::timeout, &window, [&] {
    if (measuring && probeClock.isValid())
      longestStall = std::max(longestStall, probeClock.nsecsElapsed() * 1e-6);
    probeClock.start();
  });
  probe.start(kStallProbeMs);

  window.setRunning(true);
  processEventsFor(kBenchWarmUpMs);
  measuring = true;
  probeClock.start();
  QElapsedTimer run;
  run.start();
  processEventsFor(kBenchRunMs);
  const double seconds = run.nsecsElapsed() * 1e-9;
  measuring = false;
  window.setRunning(false);

  std::vector<double> sorted = intervals;
  std::sort(sorted.begin(), sorted.end());
  const auto mean = [](const std::vector<double>& v) {
    return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / v.size();
  };
  const QSize shown = view->size();
  std::printf("balls: %d\n", ballCount);
  std::printf("view: %dx%d (device pixel ratio %.2f)%s\n", shown.width(), shown.height(),
              view->devicePixelRatioF(),
              shown == kBenchViewSize ? "" : "  -- smaller than the 1280x720 asked for");
  std::printf("antialiasing: %s (%s renderer)\n", view->antialiasing() ? "4x" : "off",
              view->softwareRenderer() ? "software" : "hardware");
  std::printf("run: %.2f s\n", seconds);
  std::printf("frames: %zu\n", paintTimes.size());
  std::printf("mean fps: %.1f\n", paintTimes.size() / seconds);
  std::printf("frame interval ms: mean %.2f  median %.2f  p95 %.2f  max %.2f\n", mean(sorted),
              percentile(sorted, 0.5), percentile(sorted, 0.95),
              sorted.empty() ? 0.0 : sorted.back());
  std::printf("paintGL ms (incl. glFinish): mean %.2f\n", mean(paintTimes));
  std::printf("longest GUI stall ms: %.2f\n", longestStall);
  std::fflush(stdout);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  carom::render::SceneView::setDefaultFormat();
  QApplication app(argc, argv);
  QApplication::setOrganizationName("Carom");
  QApplication::setApplicationName("Carom");
  QApplication::setApplicationVersion(QStringLiteral(PROJECT_VERSION));
  // Before any text is made: --lang, else View > Language's saved choice, else the system's.
  carom::ui::installTranslation(app, carom::ui::chosenLanguage(QApplication::arguments()));

  QCommandLineParser parser;
  parser.setApplicationDescription(QApplication::translate("main", "Collision physics sandbox"));
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument("scene", QApplication::translate("main", "Scene file to open"),
                               "[scene]");
  const QCommandLineOption screenshot(
      "screenshot", QApplication::translate("main", "Save a picture of the window and quit."),
      QApplication::translate("main", "file.png"));
  const QCommandLineOption runFor(
      "run-for",
      QApplication::translate("main", "Run the simulation this long before --screenshot."),
      QApplication::translate("main", "seconds"), "0");
  const QCommandLineOption language(
      "lang", QApplication::translate("main", "Language of the program (en, ru, de)."),
      QApplication::translate("main", "code"));
  const QCommandLineOption benchRender(
      "bench-render",
      QApplication::translate("main",
                              "Run a gas of N balls for 5 s with the view at 1280x720, print frame "
                              "times and the longest GUI stall, and quit."),
      "N");
  parser.addOptions({screenshot, runFor, language, benchRender});
  parser.process(app);

  if (parser.isSet(benchRender)) {
    bool ok = false;
    const int balls = parser.value(benchRender).toInt(&ok);
    if (!ok || balls < 1 || balls > 1000000) {
      std::fprintf(stderr, "carom: --bench-render takes a number of balls from 1 to 1000000\n");
      return 2;
    }
    return benchmarkRender(balls);
  }

  carom::ui::MainWindow window;
  const carom::SceneLoadResult magicRoom = carom::loadSceneFile(":/scenes/magic-room.json");
  window.openScene(*magicRoom.scene, {}, "magic-room");
  // A broken file gets a dialog with the loader's message; the magic room stays open.
  if (!parser.positionalArguments().isEmpty())
    window.openFile(parser.positionalArguments().first(), false);
  window.show();
  if (!parser.isSet(screenshot)) window.offerRecovery();
  if (parser.isSet(screenshot)) {
    // For the README's pictures: run a while in real time, then save what the window shows.
    bool ok = false;
    const double seconds = parser.value(runFor).toDouble(&ok);
    if (!ok || seconds < 0 || seconds > 600) {
      std::fprintf(stderr, "carom: --run-for takes seconds from 0 to 600\n");
      return 2;
    }
    window.setRunning(seconds > 0);
    QTimer::singleShot(static_cast<int>(seconds * 1000) + 500, &window, [&] {
      const bool saved = window.grab().save(parser.value(screenshot));
      if (!saved)
        std::fprintf(stderr, "carom: cannot save %s\n", qPrintable(parser.value(screenshot)));
      QApplication::exit(saved ? 0 : 1);
    });
  }
  return app.exec();
}
