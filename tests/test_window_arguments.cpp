// The window program's command line: the parser on its own, then the real `carom` answering
// --help, --version and bad arguments with no display to connect to.

#include "app/window_arguments.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using carom::app::parseWindowArguments;
using carom::app::WindowArguments;

namespace {

WindowArguments parse(const QStringList& options) {
  return parseWindowArguments(QStringList{"carom"} + options);
}

struct CaromRun {
  bool finished = false;
  int exitCode = -1;
  QString out;
  QString err;
  QString describe() const {
    return QString("finished %1, exit code %2\nstdout: %3\nstderr: %4")
        .arg(finished)
        .arg(exitCode)
        .arg(out.left(2000), err.left(2000));
  }
};

// carom with no display of any kind, a settings folder of its own (no saved language) and the
// C locale, so that it speaks English unless told otherwise.
CaromRun runWithoutDisplay(const QStringList& arguments) {
  QTemporaryDir home;
  QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
  for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM", "LANGUAGE", "LC_ALL",
                           "LC_MESSAGES", "LANG", "XDG_CONFIG_HOME"})
    environment.remove(name);
  environment.insert("HOME", home.path());
  environment.insert("LC_ALL", "C.UTF-8");
  QProcess process;
  process.setProcessEnvironment(environment);
  process.setStandardInputFile(QProcess::nullDevice());
  process.start(QStringLiteral(CAROM_PATH), arguments);
  CaromRun run;
  run.finished = process.waitForFinished(60000);
  if (!run.finished) {
    process.kill();
    process.waitForFinished(5000);
  }
  run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
  run.out = QString::fromUtf8(process.readAllStandardOutput());
  run.err = QString::fromUtf8(process.readAllStandardError());
  return run;
}

}  // namespace

class TestWindowArguments : public QObject {
  Q_OBJECT

 private slots:
  void noArgumentsOpenTheMagicRoom() {
    const WindowArguments a = parse({});
    QVERIFY(a.error.isEmpty());
    QVERIFY(a.scenePath.isEmpty());
    QVERIFY(!a.screenshotPath);
    QCOMPARE(a.runForSeconds, 0.0);
    QVERIFY(!a.language);
    QVERIFY(!a.benchRenderBalls);
    QVERIFY(!a.benchStressSeconds);
    QVERIFY(!a.help && !a.helpAll && !a.version);
  }

  void everyValueIsRead() {
    const WindowArguments a =
        parse({"scenes/pile.carom", "--screenshot", "out.png", "--run-for", "2.5", "--lang", "de",
               "--bench-render", "1000", "--bench-stress=60"});
    QVERIFY2(a.error.isEmpty(), qPrintable(a.error));
    QCOMPARE(a.scenePath, QString("scenes/pile.carom"));
    QCOMPARE(a.screenshotPath.value_or(""), QString("out.png"));
    QCOMPARE(a.runForSeconds, 2.5);
    QCOMPARE(a.language.value_or(""), QString("de"));
    QCOMPARE(a.benchRenderBalls.value_or(-1), 1000);
    QCOMPARE(a.benchStressSeconds.value_or(-1), 60);
  }

  void firstSceneIsOpened() {
    QCOMPARE(parse({"a.carom", "b.carom"}).scenePath, QString("a.carom"));
  }

  void helpAndVersion_data() {
    QTest::addColumn<QStringList>("options");
    QTest::addColumn<bool>("help");
    QTest::addColumn<bool>("helpAll");
    QTest::addColumn<bool>("version");
    QTest::newRow("-h") << QStringList{"-h"} << true << false << false;
    QTest::newRow("--help") << QStringList{"--help"} << true << false << false;
    QTest::newRow("--help-all") << QStringList{"--help-all"} << false << true << false;
    QTest::newRow("-v") << QStringList{"-v"} << false << false << true;
    QTest::newRow("--version") << QStringList{"--version"} << false << false << true;
    // As QCommandLineParser::process() did: help and version come before the values' checks.
    QTest::newRow("--help with a bad value")
        << QStringList{"--bench-render", "0", "--help"} << true << false << false;
  }
  void helpAndVersion() {
    QFETCH(QStringList, options);
    const WindowArguments a = parse(options);
    QFETCH(bool, help);
    QFETCH(bool, helpAll);
    QFETCH(bool, version);
    QVERIFY2(a.error.isEmpty(), qPrintable(a.error));
    QCOMPARE(a.help, help);
    QCOMPARE(a.helpAll, helpAll);
    QCOMPARE(a.version, version);
  }

  void valuesInRange_data() {
    QTest::addColumn<QStringList>("options");
    QTest::newRow("run-for 0") << QStringList{"--run-for", "0"};
    QTest::newRow("run-for 600") << QStringList{"--run-for", "600"};
    QTest::newRow("bench-render 1") << QStringList{"--bench-render", "1"};
    QTest::newRow("bench-render 1000000") << QStringList{"--bench-render", "1000000"};
    QTest::newRow("bench-stress 10") << QStringList{"--bench-stress", "10"};
    QTest::newRow("bench-stress 86400") << QStringList{"--bench-stress", "86400"};
  }
  void valuesInRange() {
    QFETCH(QStringList, options);
    const WindowArguments a = parse(options);
    QVERIFY2(a.error.isEmpty(), qPrintable(a.error));
    QCOMPARE(a.errorExitCode, 0);
  }

  void valuesOutOfRange_data() {
    QTest::addColumn<QStringList>("options");
    QTest::addColumn<QString>("message");
    const QString runFor = "--run-for takes seconds from 0 to 600";
    const QString render = "--bench-render takes a number of balls from 1 to 1000000";
    const QString stress = "--bench-stress takes seconds from 10 to 86400";
    QTest::newRow("run-for -1") << QStringList{"--run-for", "-1"} << runFor;
    QTest::newRow("run-for 600.5") << QStringList{"--run-for", "600.5"} << runFor;
    QTest::newRow("run-for abc") << QStringList{"--run-for", "abc"} << runFor;
    QTest::newRow("run-for nan") << QStringList{"--run-for", "nan"} << runFor;
    QTest::newRow("run-for inf") << QStringList{"--run-for=inf"} << runFor;
    QTest::newRow("bench-render 0") << QStringList{"--bench-render", "0"} << render;
    QTest::newRow("bench-render 1000001") << QStringList{"--bench-render", "1000001"} << render;
    QTest::newRow("bench-render 2.5") << QStringList{"--bench-render", "2.5"} << render;
    QTest::newRow("bench-stress 9") << QStringList{"--bench-stress", "9"} << stress;
    QTest::newRow("bench-stress 86401") << QStringList{"--bench-stress", "86401"} << stress;
    QTest::newRow("bench-stress empty") << QStringList{"--bench-stress", ""} << stress;
  }
  void valuesOutOfRange() {
    QFETCH(QStringList, options);
    QFETCH(QString, message);
    const WindowArguments a = parse(options);
    QCOMPARE(a.error, message);
    QCOMPARE(a.errorExitCode, 2);
  }

  void parserRefusals_data() {
    QTest::addColumn<QStringList>("options");
    QTest::addColumn<QString>("named");
    QTest::newRow("unknown option") << QStringList{"--bogus"} << "bogus";
    QTest::newRow("missing value") << QStringList{"scene.carom", "--screenshot"} << "screenshot";
  }
  void parserRefusals() {
    QFETCH(QStringList, options);
    QFETCH(QString, named);
    const WindowArguments a = parse(options);
    QVERIFY2(a.error.contains(named), qPrintable(a.error));
    QCOMPARE(a.errorExitCode, 1);
  }

  void qtOptionsAreRecognised() {
    using carom::app::mentionsQtOption;
    QVERIFY(mentionsQtOption({"carom", "-platform", "offscreen"}));
    QVERIFY(mentionsQtOption({"carom", "scene.carom", "--style=fusion"}));
    QVERIFY(mentionsQtOption({"carom", "-display", ":1"}));
    QVERIFY(!mentionsQtOption({"carom", "--screenshot", "a.png", "--lang", "de", "x.carom"}));
    QVERIFY(!mentionsQtOption({"carom", "platform"}));  // a file of that name
    QVERIFY(!mentionsQtOption({"-platform"}));          // the program itself
  }

  void helpTextListsEveryOption() {
    const QString help = carom::app::windowHelpText();
    for (const char* expected : {"Collision physics sandbox", "[scene]", "Scene file to open",
                                 "--screenshot <file.png>", "--run-for <seconds>", "--lang <code>",
                                 "--bench-render <N>", "--bench-stress <S>", "--help", "--version"})
      QVERIFY2(help.contains(expected), qPrintable(expected + QString(" missing in:\n") + help));
  }

  // The built program, with no display: answered at once instead of "could not connect".
  void helpWithoutDisplay() {
    const CaromRun run = runWithoutDisplay({"--help"});
    QVERIFY2(run.finished && run.exitCode == 0, qPrintable(run.describe()));
    // Qt names the program as it was started, here by its full path.
    QVERIFY2(run.out.startsWith("Usage: /") && run.out.contains("/carom [options] [scene]\n"),
             qPrintable(run.describe()));
    QVERIFY2(run.out.contains("--bench-stress <S>"), qPrintable(run.describe()));
  }

  void versionWithoutDisplay() {
    const CaromRun run = runWithoutDisplay({"--version"});
    QVERIFY2(run.finished && run.exitCode == 0, qPrintable(run.describe()));
    QCOMPARE(run.out, QString("Carom " CAROM_VERSION "\n"));
  }

  void translatedHelpWithoutDisplay() {
    const CaromRun run = runWithoutDisplay({"--lang", "de", "--help"});
    QVERIFY2(run.finished && run.exitCode == 0, qPrintable(run.describe()));
    QVERIFY2(run.out.contains(QString::fromUtf8("Sandbox für Kollisionsphysik")),
             qPrintable(run.describe()));
  }

  void helpAllWithoutDisplay() {
    const CaromRun run = runWithoutDisplay({"--help-all"});
    QVERIFY2(run.finished && run.exitCode == 0, qPrintable(run.describe()));
    QVERIFY2(run.out.contains("--screenshot <file.png>"), qPrintable(run.describe()));
    // Qt's own options, which only a QGuiApplication adds.
    QVERIFY2(run.out.contains("--platform"), qPrintable(run.describe()));
  }

  void badValueWithoutDisplay() {
    const CaromRun run = runWithoutDisplay({"--bench-render", "0"});
    QVERIFY2(run.finished && run.exitCode == 2, qPrintable(run.describe()));
    QVERIFY2(run.out.isEmpty(), qPrintable(run.describe()));
    QCOMPARE(run.err, QString("carom: --bench-render takes a number of balls from 1 to 1000000\n"));
  }

  void unknownOptionWithoutDisplay() {
    const CaromRun run = runWithoutDisplay({"--bogus"});
    QVERIFY2(run.finished && run.exitCode == 1, qPrintable(run.describe()));
    QVERIFY2(run.err.startsWith("carom: ") && run.err.contains("bogus"),
             qPrintable(run.describe()));
  }

  // Qt's own options are taken out by QApplication before carom's parser sees the rest.
  void qtOptionBeforeVersion() {
    const CaromRun run = runWithoutDisplay({"-platform", "offscreen", "--version"});
    QVERIFY2(run.finished && run.exitCode == 0, qPrintable(run.describe()));
    QCOMPARE(run.out, QString("Carom " CAROM_VERSION "\n"));
  }
};

QTEST_GUILESS_MAIN(TestWindowArguments)
#include "test_window_arguments.moc"
