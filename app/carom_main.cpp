#include "language.h"
#include "main_window.h"
#include "scene_file.h"
#include "scene_view.h"
#include "window_benchmarks.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QTimer>

#include <cstdio>

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
  const QCommandLineOption benchStress(
      "bench-stress",
      QApplication::translate("main",
                              "Run a gas at about 10,000 collisions a second with explosions and "
                              "sound for S seconds, print the collision rate, frame rate, GUI "
                              "stalls and memory every 10 s, and quit."),
      "S");
  parser.addOptions({screenshot, runFor, language, benchRender, benchStress});
  parser.process(app);

  if (parser.isSet(benchRender)) {
    bool ok = false;
    const int balls = parser.value(benchRender).toInt(&ok);
    if (!ok || balls < 1 || balls > 1000000) {
      std::fprintf(stderr, "carom: --bench-render takes a number of balls from 1 to 1000000\n");
      return 2;
    }
    return carom::ui::benchmarkRender(balls);
  }
  if (parser.isSet(benchStress)) {
    bool ok = false;
    const int seconds = parser.value(benchStress).toInt(&ok);
    if (!ok || seconds < 10 || seconds > 86400) {
      std::fprintf(stderr, "carom: --bench-stress takes seconds from 10 to 86400\n");
      return 2;
    }
    return carom::ui::benchmarkStress(seconds);
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
