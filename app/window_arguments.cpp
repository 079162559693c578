#include "app/window_arguments.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QCoreApplication>

#include <cmath>

namespace carom::app {
namespace {

// The option names of carom itself; addWindowOptions() gives their descriptions.
constexpr const char* kScreenshot = "screenshot";
constexpr const char* kRunFor = "run-for";
constexpr const char* kLanguage = "lang";
constexpr const char* kBenchRender = "bench-render";
constexpr const char* kBenchStress = "bench-stress";
constexpr const char* kBenchOpen = "bench-open";

WindowArguments refused(const QString& message, int exitCode) {
  WindowArguments arguments;
  arguments.error = message;
  arguments.errorExitCode = exitCode;
  return arguments;
}

}  // namespace

void addWindowOptions(QCommandLineParser& parser) {
  // Context "main" and these source texts are what translations/*.ts hold for them.
  parser.setApplicationDescription(
      QCoreApplication::translate("main", "Collision physics sandbox"));
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument("scene", QCoreApplication::translate("main", "Scene file to open"),
                               "[scene]");
  parser.addOptions({
      {kScreenshot, QCoreApplication::translate("main", "Save a picture of the window and quit."),
       QCoreApplication::translate("main", "file.png")},
      {kRunFor,
       QCoreApplication::translate("main", "Run the simulation this long before --screenshot."),
       QCoreApplication::translate("main", "seconds"), "0"},
      {kLanguage, QCoreApplication::translate("main", "Language of the program (en, ru, de)."),
       QCoreApplication::translate("main", "code")},
      {kBenchRender,
       QCoreApplication::translate("main",
                                   "Run a gas of N balls for 5 s with the view at 1280x720, print "
                                   "frame times and the longest GUI stall, and quit."),
       "N"},
      {kBenchStress,
       QCoreApplication::translate("main",
                                   "Run a gas at about 10,000 collisions a second with explosions "
                                   "and sound for S seconds, print the collision rate, frame rate, "
                                   "GUI stalls and memory every 10 s, and quit."),
       "S"},
      {kBenchOpen,
       QCoreApplication::translate("main",
                                   "Open the scene file, run it for 5 s, select its last ball in "
                                   "the outline, print how long each took, and quit.")},
  });
}

WindowArguments parseWindowArguments(const QStringList& arguments) {
  QCommandLineParser parser;
  addWindowOptions(parser);
  if (!parser.parse(arguments)) return refused(parser.errorText(), 1);

  WindowArguments result;
  // The order QCommandLineParser::process() answers them in.
  result.version = parser.isSet("version");
  result.help = parser.isSet("help");
  result.helpAll = parser.isSet("help-all");
  if (result.version || result.help || result.helpAll) return result;

  if (!parser.positionalArguments().isEmpty()) result.scenePath = parser.positionalArguments()[0];
  if (parser.isSet(kScreenshot)) result.screenshotPath = parser.value(kScreenshot);
  if (parser.isSet(kLanguage)) result.language = parser.value(kLanguage);

  bool ok = false;
  const double runFor = parser.value(kRunFor).toDouble(&ok);
  // toDouble() takes "nan" and "inf", which no range check below would stop.
  if (!ok || !std::isfinite(runFor) || runFor < 0 || runFor > 600)
    return refused("--run-for takes seconds from 0 to 600", 2);
  result.runForSeconds = runFor;

  if (parser.isSet(kBenchRender)) {
    const int balls = parser.value(kBenchRender).toInt(&ok);
    if (!ok || balls < 1 || balls > 1000000)
      return refused("--bench-render takes a number of balls from 1 to 1000000", 2);
    result.benchRenderBalls = balls;
  }
  if (parser.isSet(kBenchStress)) {
    const int seconds = parser.value(kBenchStress).toInt(&ok);
    if (!ok || seconds < 10 || seconds > 86400)
      return refused("--bench-stress takes seconds from 10 to 86400", 2);
    result.benchStressSeconds = seconds;
  }
  if (parser.isSet(kBenchOpen)) {
    if (result.scenePath.isEmpty()) return refused("--bench-open needs a scene file", 2);
    result.benchOpen = true;
  }
  return result;
}

bool mentionsQtOption(const QStringList& arguments) {
  // What Qt 6's QCoreApplication, QGuiApplication, QApplication and the xcb platform take out
  // of the command line, each with one dash or two, some also as -name=value.
  static const QStringList kQtOptions =
      QString(
          "platform platformpluginpath platformtheme plugin qwindowgeometry qwindowicon "
          "qwindowtitle geometry title icon session reverse testability style stylesheet "
          "widgetcount qmljsdebugger display name visual nograb dograb sync")
          .split(' ');
  for (qsizetype i = 1; i < arguments.size(); ++i) {
    QString name = arguments[i];
    if (!name.startsWith('-')) continue;
    name.remove(0, name.startsWith("--") ? 2 : 1);
    name = name.section('=', 0, 0);
    if (kQtOptions.contains(name)) return true;
  }
  return false;
}

QString windowHelpText() {
  QCommandLineParser parser;
  addWindowOptions(parser);
  return parser.helpText();
}

}  // namespace carom::app
