#include "app/window_arguments.h"
#include "app/window_benchmarks.h"
#include "sim/io/atomic_file.h"
#include "sim/io/file_names.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/render/scene_view.h"

#include <QApplication>
#include <QBuffer>
#include <QCommandLineParser>
#include <QIcon>
#include <QTimer>

#include <cstdio>
#include <vector>

namespace {

// The reverse-DNS name of the desktop entry, the icon and the AppStream metainfo.
constexpr const char* kApplicationId = "io.github.carom_sim.Carom";

void setIdentity() {
  QCoreApplication::setOrganizationName("Carom");
  QCoreApplication::setApplicationName("Carom");
  QCoreApplication::setApplicationVersion(QStringLiteral(PROJECT_VERSION));
}

// Help, version or a refusal, as QCommandLineParser::process() printed them.
int answerWithoutWindow(const carom::app::WindowArguments& arguments) {
  if (!arguments.error.isEmpty()) {
    std::fprintf(stderr, "carom: %s\n", qPrintable(arguments.error));
    return arguments.errorExitCode;
  }
  if (arguments.version) {
    std::printf("%s %s\n", qPrintable(QCoreApplication::applicationName()),
                qPrintable(QCoreApplication::applicationVersion()));
  } else {
    std::fputs(qPrintable(carom::app::windowHelpText()), stdout);
  }
  return 0;
}

// The command line with file names as the bytes given (sim/io/file_names.h); not
// QApplication::arguments(), which turns bytes that are not UTF-8 into U+FFFD.
QStringList decodedArguments(int argc, char** argv) {
  QStringList arguments;
  for (int i = 0; i < argc; ++i) arguments << carom::io::decodeFileName(argv[i]);
  return arguments;
}

}  // namespace

int main(int argc, char** argv) {
  const QStringList commandLine = decodedArguments(argc, argv);
  const carom::app::WindowArguments early = carom::app::parseWindowArguments(commandLine);
  // Answered without a window, so without a display (a terminal over ssh, a package build).
  // A refusal waits for QApplication when Qt's own options are there, which it removes first.
  if (early.version || early.help ||
      (!early.error.isEmpty() && !carom::app::mentionsQtOption(commandLine))) {
    QCoreApplication app(argc, argv);
    setIdentity();
    carom::ui::installTranslation(app, carom::ui::chosenLanguage(QCoreApplication::arguments()));
    return answerWithoutWindow(early);
  }

  // --help-all lists the options of QApplication too, which only an instance of it adds; the
  // offscreen platform needs no display for that.
  std::vector<char*> qtArgv(argv, argv + argc);
  char platformOption[] = "-platform";
  char offscreenPlatform[] = "offscreen";
  if (early.helpAll && !carom::app::mentionsQtOption(commandLine))
    qtArgv.insert(qtArgv.begin() + 1, {platformOption, offscreenPlatform});
  int qtArgc = static_cast<int>(qtArgv.size());
  qtArgv.push_back(nullptr);

  carom::render::SceneView::setDefaultFormat();
  QApplication app(qtArgc, qtArgv.data());
  setIdentity();
  // Lets Wayland compositors and docks match the window to the installed desktop entry.
  QGuiApplication::setDesktopFileName(kApplicationId);
  QIcon icon;
  for (int size : {16, 24, 32, 48, 64, 128, 256})
    icon.addFile(QString(":/icons/%1x%1/%2.png").arg(size).arg(kApplicationId), QSize(size, size));
  QApplication::setWindowIcon(icon);
  // Before any text is made: --lang, else View > Language's saved choice, else the system's.
  carom::ui::installTranslation(app, carom::ui::chosenLanguage(QApplication::arguments()));

  // Parsed again now that QApplication has taken out its own options.
  const carom::app::WindowArguments arguments =
      carom::app::parseWindowArguments(decodedArguments(qtArgc, qtArgv.data()));
  if (arguments.version || arguments.help || !arguments.error.isEmpty())
    return answerWithoutWindow(arguments);
  if (arguments.helpAll) {
    QCommandLineParser parser;
    carom::app::addWindowOptions(parser);
    parser.process(app);  // prints the help with Qt's options and exits
  }

  if (arguments.benchRenderBalls) return carom::app::benchmarkRender(*arguments.benchRenderBalls);
  if (arguments.benchStressSeconds)
    return carom::app::benchmarkStress(*arguments.benchStressSeconds);
  if (arguments.benchOpen) return carom::app::benchmarkOpen(arguments.scenePath);

  carom::ui::MainWindow window;
  window.openExample("magic-room", false);
  // A broken file gets a dialog with the loader's message; the magic room stays open.
  if (!arguments.scenePath.isEmpty()) window.openFile(arguments.scenePath, false);
  window.show();
  if (!arguments.screenshotPath) window.offerRecovery();
  if (arguments.screenshotPath) {
    // For the pictures of the README and the user guide: run a while in real time, then save
    // what the window shows.
    const QString path = *arguments.screenshotPath;
    const double seconds = arguments.runForSeconds;
    window.setRunning(seconds > 0);
    QTimer::singleShot(static_cast<int>(seconds * 1000) + 500, &window, [&window, path] {
      // A PNG written whole or not at all.
      QBuffer png;
      png.open(QIODevice::WriteOnly);
      QString error;
      const bool saved = window.grab().save(&png, "png") &&
                         carom::io::writeFileAtomically(path, png.data(), &error);
      if (!saved)
        std::fprintf(stderr, "carom: cannot save %s: %s\n", qPrintable(path), qPrintable(error));
      QApplication::exit(saved ? 0 : 1);
    });
  }
  return app.exec();
}
