#include "language.h"
#include "main_window.h"
#include "scene_file.h"
#include "scene_view.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QFileInfo>
#include <QMessageBox>
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
  parser.addOptions({screenshot, runFor, language});
  parser.process(app);

  carom::ui::MainWindow window;
  const carom::SceneLoadResult magicRoom = carom::loadSceneFile(":/scenes/magic-room.json");
  window.openScene(*magicRoom.scene, "magic-room");
  if (!parser.positionalArguments().isEmpty()) {
    const QString file = parser.positionalArguments().first();
    const carom::SceneLoadResult loaded = carom::loadSceneFile(file);
    if (loaded.scene)
      window.openScene(*loaded.scene, QFileInfo(file).completeBaseName());
    else
      QMessageBox::warning(&window, QApplication::translate("main", "Cannot open scene"),
                           loaded.error);
  }
  window.show();
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
