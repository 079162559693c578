#pragma once
// The command line of the window program, carom, parsed into plain values; nothing runs here.
// QtCore only, so that --help, --version and bad arguments are answered without a display.

#include <QString>
#include <QStringList>

#include <optional>

class QCommandLineParser;

namespace carom::app {

struct WindowArguments {
  QString scenePath;                      // empty: the magic room
  std::optional<QString> screenshotPath;  // --screenshot: save the window and quit
  double runForSeconds = 0;               // --run-for, before the screenshot
  std::optional<QString> language;        // --lang, as given
  std::optional<int> benchRenderBalls;    // --bench-render
  std::optional<int> benchStressSeconds;  // --bench-stress
  bool benchOpen = false;                 // --bench-open: of scenePath
  bool help = false;                      // -h, --help
  bool helpAll = false;                   // --help-all: also Qt's own options
  bool version = false;                   // -v, --version
  // When not empty the arguments are refused: what is wrong, without the program's name.
  QString error;
  // The exit code for `error`: 1 for what the parser refuses (an unknown option, a missing
  // value), as QCommandLineParser::process() did; 2 for a value out of range.
  int errorExitCode = 0;
};

// `arguments` as QCoreApplication::arguments() gives them: the program first.
WindowArguments parseWindowArguments(const QStringList& arguments);

// Whether `arguments` hold an option that QGuiApplication or QApplication take for themselves
// (-platform, -style, --display=..., ...). Until Qt has removed them, a refusal of such a
// command line may be wrong.
bool mentionsQtOption(const QStringList& arguments);

// The description, options and scene argument, in the installed translation.
void addWindowOptions(QCommandLineParser& parser);

// What --help prints (needs a QCoreApplication for the program's name).
QString windowHelpText();

}  // namespace carom::app
