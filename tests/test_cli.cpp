// carom-cli as a user runs it from a shell: the real executable under QProcess, judged by its
// exit code, stdout and stderr only.

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

#include <QElapsedTimer>
#include <QThread>

#include <algorithm>
#include <cmath>
#include <csignal>

#include "small_filesystem.h"

#include <fcntl.h>
#include <pty.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

// A run must end by itself, without crashing, with the given exit code.
#define VERIFY_EXIT(run, code)                                                                 \
  QVERIFY2((run).finished && (run).status == QProcess::NormalExit && (run).exitCode == (code), \
           qPrintable((run).describe()))

// Bad input: exit code 2, nothing on stdout, a message of one or two lines on stderr.
#define VERIFY_REFUSED(run)                                                 \
  do {                                                                      \
    VERIFY_EXIT(run, 2);                                                    \
    QVERIFY2((run).out.isEmpty(), qPrintable((run).describe()));            \
    QVERIFY2((run).err.endsWith('\n'), qPrintable((run).describe()));       \
    const qsizetype errLines = (run).err.count('\n');                       \
    QVERIFY2(errLines >= 1 && errLines <= 2, qPrintable((run).describe())); \
  } while (false)

namespace {

constexpr int kTimeoutMs = 60000;
// bench --quick runs several small benchmarks; a slow or busy machine gets plenty of room.
constexpr int kBenchTimeoutMs = 120000;

struct CliRun {
  QStringList arguments;
  bool finished = false;  // ended by itself within the timeout
  QProcess::ExitStatus status = QProcess::CrashExit;
  int exitCode = -1;
  QString processError;
  QByteArray out;
  QByteArray err;

  // What a failing check prints: enough to see what the CLI did without rerunning it.
  QString describe() const {
    return QString(
               "carom-cli %1\n  finished: %2, crashed: %3, exit code: %4 %5\n  stdout: %6\n"
               "  stderr: %7")
        .arg(arguments.join(' '))
        .arg(finished)
        .arg(status == QProcess::CrashExit)
        .arg(exitCode)
        .arg(processError)
        .arg(QString::fromUtf8(out.left(1500)))
        .arg(QString::fromUtf8(err.left(1500)));
  }
};

// Stdin is the null device so that a CLI waiting for input sees end of file instead of hanging.
CliRun runCli(const QStringList& arguments, int timeoutMs = kTimeoutMs,
              const QString& stdoutFile = QString()) {
  CliRun run;
  run.arguments = arguments;
  QProcess process;
  process.setProgram(QStringLiteral(CAROM_CLI_PATH));
  process.setArguments(arguments);
  process.setStandardInputFile(QProcess::nullDevice());
  if (!stdoutFile.isEmpty()) process.setStandardOutputFile(stdoutFile);
  process.start();
  run.finished = process.waitForFinished(timeoutMs);
  if (!run.finished) {
    run.processError = process.errorString();
    process.kill();
    process.waitForFinished(5000);
  }
  run.status = process.exitStatus();
  run.exitCode = process.exitCode();
  run.out = process.readAllStandardOutput();
  run.err = process.readAllStandardError();
  return run;
}

QString scenesDir() {
  return QStringLiteral(CAROM_SOURCE_DIR "/resources/scenes");
}
QString sceneFile(const QString& name) {
  return scenesDir() + '/' + name;
}
QString magicRoom() {
  return sceneFile("magic-room.json");
}

// A version-`version` scene whose top level holds `fields` besides format and version.
QByteArray sceneText(const QByteArray& fields, int version = 1) {
  return R"({"format": "carom-scene", "version": )" + QByteArray::number(version) +
         (fields.isEmpty() ? QByteArray() : ", " + fields) + "}\n";
}

QByteArray fileBytes(const QString& fileName) {
  QFile file(fileName);
  return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

QJsonObject readJsonObject(const QString& fileName) {
  QFile file(fileName);
  if (!file.open(QIODevice::ReadOnly)) return {};
  return QJsonDocument::fromJson(file.readAll()).object();
}

bool isVector(const QJsonValue& value) {
  const QJsonArray array = value.toArray();
  if (!value.isArray() || array.size() != 3) return false;
  for (const QJsonValue& x : array)
    if (!x.isDouble() || !std::isfinite(x.toDouble())) return false;
  return true;
}

bool isCount(const QJsonValue& value) {
  const double x = value.toDouble(-1.0);
  return value.isDouble() && x >= 0.0 && x == std::floor(x);
}

// The bytes of the array that follows `"key":` in compact JSON. The arrays looked at here hold
// only numbers, booleans and objects of those, so brackets are never inside strings.
QByteArray rawArray(const QByteArray& json, const QByteArray& key) {
  const qsizetype start = json.indexOf('"' + key + "\":[");
  if (start < 0) return {};
  const qsizetype open = json.indexOf('[', start);
  int depth = 0;
  for (qsizetype i = open; i < json.size(); ++i) {
    if (json[i] == '[') ++depth;
    if (json[i] == ']' && --depth == 0) return json.mid(open, i - open + 1);
  }
  return {};
}

// Significant digits of a number written in JSON, such as 4 for "-0.01234e5".
int significantDigits(QByteArray number) {
  const qsizetype e = number.indexOf('e') >= 0 ? number.indexOf('e') : number.indexOf('E');
  if (e >= 0) number.truncate(e);
  number.replace("-", "").replace(".", "");
  while (number.startsWith('0')) number.remove(0, 1);
  return static_cast<int>(number.size());
}

QList<QByteArray> nonEmptyLines(const QByteArray& text) {
  QList<QByteArray> lines;
  for (const QByteArray& line : text.split('\n'))
    if (!line.trimmed().isEmpty()) lines << line;
  return lines;
}

// A run stopped with Ctrl+C: the process is started, given `waitMs` to get going, sent SIGINT
// and then given `timeoutMs` to print its report and end. When `terminal` is set, its standard
// error is a pseudo-terminal, read into `err`, as in an interactive shell.
CliRun interruptCli(const QStringList& arguments, int waitMs, bool terminal = false) {
  CliRun run;
  run.arguments = arguments;
  int master = -1;
  int slave = -1;
  if (terminal && ::openpty(&master, &slave, nullptr, nullptr, nullptr) != 0) {
    run.processError = "openpty failed";
    return run;
  }
  QProcess process;
  process.setProgram(QStringLiteral(CAROM_CLI_PATH));
  process.setArguments(arguments);
  process.setStandardInputFile(QProcess::nullDevice());
  if (terminal) process.setChildProcessModifier([slave] { ::dup2(slave, STDERR_FILENO); });
  process.start();
  if (terminal) {
    ::close(slave);
    ::fcntl(master, F_SETFL, ::fcntl(master, F_GETFL) | O_NONBLOCK);
  }
  const auto readTerminal = [&] {
    char buffer[4096];
    ssize_t n = 0;
    while (terminal && (n = ::read(master, buffer, sizeof buffer)) > 0) run.err.append(buffer, n);
  };
  QElapsedTimer waited;
  waited.start();
  while (waited.elapsed() < waitMs && process.state() != QProcess::NotRunning) {
    process.waitForFinished(50);
    readTerminal();
  }
  if (process.state() != QProcess::NotRunning) ::kill(pid_t(process.processId()), SIGINT);
  QElapsedTimer ending;
  ending.start();
  while (!(run.finished = process.waitForFinished(50)) && ending.elapsed() < kTimeoutMs)
    readTerminal();
  readTerminal();
  if (!run.finished) {
    run.processError = "did not end after SIGINT";
    process.kill();
    process.waitForFinished(5000);
  }
  if (terminal) ::close(master);
  run.status = process.exitStatus();
  run.exitCode = process.exitCode();
  run.out = process.readAllStandardOutput();
  if (!terminal) run.err = process.readAllStandardError();
  return run;
}

// A scene of mixed sizes whose set-up (first prediction, overlap checks) costs far more than a
// short run: one large ball next to a lattice of 4,096 small ones, all in one cell of a grid
// sized for the large one.
QByteArray mixedSizeScene() {
  QByteArrayList balls{R"({"position": [40, 0, 0], "radius": 10})"};
  constexpr int kSide = 16;
  for (int i = 0; i < kSide; ++i)
    for (int j = 0; j < kSide; ++j)
      for (int k = 0; k < kSide; ++k)
        balls << QString(R"({"position": [%1, %2, %3], "velocity": [%4, %5, 0], "radius": 0.01})")
                     .arg(i * 0.05)
                     .arg(j * 0.05)
                     .arg(k * 0.05)
                     .arg(((i * 7 + j * 3 + k) % 5 - 2) * 0.1)
                     .arg(((i + j * 5 + k * 3) % 5 - 2) * 0.1)
                     .toUtf8();
  return R"({"format": "carom-scene", "version": 1, "world": {"gravity": [0, 0, 0]},
 "balls": [)" +
         balls.join(",\n") + "]}\n";
}

}  // namespace

class TestCli : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir dir_;

  QString writeFile(const QString& name, const QByteArray& content) {
    const QString path = dir_.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) ||
        file.write(content) != content.size())
      return QString();
    return path;
  }

  // The current data row's tag as a file name, so that messages can be checked for it.
  static QString rowFileName() {
    return QString::fromUtf8(QTest::currentDataTag())
        .toLower()
        .replace(QRegularExpression("[^a-z0-9]+"), "-");
  }
  QString writeRowFile(const QByteArray& content) {
    return writeFile(rowFileName() + ".json", content);
  }

 private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    QVERIFY2(QFileInfo(QStringLiteral(CAROM_CLI_PATH)).isExecutable(), CAROM_CLI_PATH);
  }

  // --- help and version ---

  void help_data() {
    QTest::addColumn<QString>("flag");
    for (const char* flag : {"--help", "-h", "help"}) QTest::newRow(flag) << QString(flag);
  }
  void help() {
    QFETCH(QString, flag);
    const CliRun run = runCli({flag});
    VERIFY_EXIT(run, 0);
    QVERIFY2(run.out.contains("carom-cli run"), run.out.constData());
    QVERIFY2(run.out.contains("carom-cli validate"), run.out.constData());
    QVERIFY2(run.out.contains("carom-cli bench"), run.out.constData());
    QVERIFY2(run.out.contains("carom-cli study"), run.out.constData());
    QVERIFY2(run.out.contains("--stop-on-divergence"), run.out.constData());
    QVERIFY2(run.out.contains("3 stopped by the watch"), run.out.constData());
    QVERIFY2(run.err.isEmpty(), run.err.constData());
  }

  void version() {
    const CliRun run = runCli({"--version"});
    VERIFY_EXIT(run, 0);
    const QRegularExpression expected("^carom-cli \\d+\\.\\d+\\.\\d+\\n$");
    QVERIFY2(expected.match(QString::fromUtf8(run.out)).hasMatch(), run.out.constData());
    QVERIFY2(run.err.isEmpty(), run.err.constData());
  }

  // --- validate ---

  void bundledScenesExist() {
    const QStringList scenes = QDir(scenesDir()).entryList({"*.json"}, QDir::Files);
    QVERIFY2(scenes.size() >= 5, qPrintable(scenes.join(", ")));
    QVERIFY(scenes.contains("magic-room.json"));
  }

  void validateBundledScene_data() {
    QTest::addColumn<QString>("path");
    for (const QString& name : QDir(scenesDir()).entryList({"*.json"}, QDir::Files))
      QTest::newRow(qPrintable(name)) << sceneFile(name);
  }
  void validateBundledScene() {
    QFETCH(QString, path);
    const CliRun run = runCli({"validate", path});
    VERIFY_EXIT(run, 0);
    QCOMPARE(run.out, QByteArray("ok\n"));
    QVERIFY2(run.err.isEmpty(), run.err.constData());
  }

  // Shapes that touch to within the 1e-9 tolerance of docs/scene-format.md are a valid start.
  void touchingIsAccepted_data() {
    QTest::addColumn<QByteArray>("scene");
    QTest::newRow("balls two radii apart") << sceneText(R"("balls": [
        {"position": [0, 0, 0], "radius": 0.1}, {"position": [0.2, 0, 0], "radius": 0.1},
        {"position": [0.4, 0, 0], "radius": 0.1}])");
    // 0.3 - 0.1 is one ulp short of 0.2 in doubles.
    QTest::newRow("balls a rounding error closer") << sceneText(R"("balls": [
        {"position": [0.1, 0, 0], "radius": 0.1}, {"position": [0.3, 0, 0], "radius": 0.1},
        {"position": [0.7, 0, 0], "radius": 0.3}])");
    QTest::newRow("ball on a plane") << sceneText(R"(
        "planes": [{"point": [0, 0, 0], "normal": [0, 2, 0]}],
        "balls": [{"position": [0, 0.1, 0], "radius": 0.1}])");
    QTest::newRow("ball on a cylinder") << sceneText(R"(
        "cylinders": [{"point": [0, 0, 0], "axis": [0, 1, 0], "radius": 0.3}],
        "balls": [{"position": [0.4, 0, 0], "radius": 0.1}])");
    QTest::newRow("ball on a slanted cylinder") << sceneText(R"(
        "cylinders": [{"point": [0, 0, 0], "axis": [0, 1, 1], "radius": 0.3}],
        "balls": [{"position": [0.4, 5, 5], "radius": 0.1}])");
  }
  void touchingIsAccepted() {
    QFETCH(QByteArray, scene);
    const QString path = writeRowFile(scene);
    QVERIFY(!path.isEmpty());
    const CliRun validate = runCli({"validate", path});
    VERIFY_EXIT(validate, 0);
    QCOMPARE(validate.out, QByteArray("ok\n"));
    const CliRun run = runCli({"run", path, "--duration", "1", "--json"});
    VERIFY_EXIT(run, 0);
    QVERIFY2(QJsonDocument::fromJson(run.out).isObject(), run.out.constData());
  }

  // Scenes validation accepts at the ends of its range (issue 33: the grids' cell counts
  // overflowed, and the run died of SIGSEGV or "internal error: vector::reserve") run under
  // every method.
  void extremeScenesRun_data() {
    QTest::addColumn<QByteArray>("scene");
    QTest::addColumn<QString>("method");
    const QList<std::pair<const char*, QByteArray>> scenes{
        {"micro balls 1 km apart", sceneText(R"("balls": [
            {"position": [0, 0, 0], "velocity": [1, 1, 1], "radius": 1e-6},
            {"position": [1000, 1000, 1000], "radius": 1e-6}])")},
        {"pico balls by a huge box", sceneText(R"(
            "boxes": [{"center": [0, 0, 0], "halfExtents": [5e11, 5e11, 5e11]}],
            "balls": [{"position": [6e11, 0, 0], "radius": 1e-12},
                      {"position": [6e11, 1, 0], "radius": 1e-12}])",
                                               2)},
        {"pico balls by a huge cylinder", sceneText(R"(
            "cylinders": [{"point": [0, 0, 0], "axis": [0, 1, 0], "radius": 5e11, "length": 1e12}],
            "balls": [{"position": [6e11, 0, 0], "radius": 1e-12},
                      {"position": [6e11, 1, 0], "radius": 1e-12}])",
                                                    2)},
        {"pico balls 1e9 m apart", sceneText(R"("balls": [
            {"position": [0, 0, 0], "radius": 1e-12}, {"position": [1e9, 0, 0], "radius": 1e-12}])")}};
    for (const auto& [name, scene] : scenes)
      for (const QString method : {"exact", "swept", "discrete"})
        QTest::newRow(qPrintable(name + QString(", ") + method)) << scene << method;
  }
  void extremeScenesRun() {
    QFETCH(QByteArray, scene);
    QFETCH(QString, method);
    const QString path = writeRowFile(scene);
    QVERIFY(!path.isEmpty());
    const CliRun validate = runCli({"validate", path});
    VERIFY_EXIT(validate, 0);
    const CliRun run = runCli({"run", path, "--duration", "0", "--method", method, "--json"});
    VERIFY_EXIT(run, 0);
    QVERIFY2(QJsonDocument::fromJson(run.out).isObject(), run.out.constData());
  }

  // A version 2 scene with a box: validated, run, and its contact counted as ball-box.
  void runCountsBallBoxContacts() {
    const QString path = writeRowFile(sceneText(R"(
        "boxes": [{"center": [0, 0, 0], "halfExtents": [1, 0.5, 1], "rotation": [0, 1, 0, 30]}],
        "balls": [{"position": [0.2, 2, 0.1], "radius": 0.1}])",
                                                2));
    QVERIFY(!path.isEmpty());
    const CliRun validate = runCli({"validate", path});
    VERIFY_EXIT(validate, 0);
    const CliRun run = runCli({"run", path, "--duration", "0.7", "--json"});
    VERIFY_EXIT(run, 0);
    const QJsonObject report = QJsonDocument::fromJson(run.out).object();
    QCOMPARE(report["collisions"].toObject()["ballBox"].toDouble(), 1.0);
    QCOMPARE(report["escaped"].toDouble(), 0.0);
  }

  // --- run ---

  void runJsonMagicRoom() {
    const QStringList arguments{"run", magicRoom(), "--duration", "2", "--json"};
    const CliRun run = runCli(arguments);
    VERIFY_EXIT(run, 0);
    QVERIFY2(run.err.isEmpty(), run.err.constData());
    // One object on one line: scripts read it whole.
    QVERIFY2(run.out.endsWith("}\n") && run.out.count('\n') == 1, run.out.constData());
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(run.out, &error);
    QVERIFY2(error.error == QJsonParseError::NoError, qPrintable(error.errorString()));
    QVERIFY(document.isObject());
    const QJsonObject report = document.object();

    QVERIFY(report["simulatedTime"].isDouble());
    QVERIFY(report["simulatedTime"].toDouble() == 2.0);
    QVERIFY(report["wallSeconds"].isDouble());
    QVERIFY(report["wallSeconds"].toDouble(-1.0) >= 0.0);

    const QJsonObject collisions = report["collisions"].toObject();
    double total = 0.0;
    for (const char* kind : {"ballBall", "ballPlane", "ballCylinder", "ballBox"}) {
      QVERIFY2(isCount(collisions[kind]), kind);
      total += collisions[kind].toDouble();
    }
    QVERIFY(total > 0.0);

    // The magic room is elastic and the exact method keeps its energy to rounding.
    const QJsonObject energy = report["energy"].toObject();
    QVERIFY(energy["initial"].isDouble() && energy["final"].isDouble());
    const double initial = energy["initial"].toDouble();
    const double final = energy["final"].toDouble();
    QVERIFY(initial > 0.0);
    QVERIFY2(std::abs(final - initial) <= 1e-9 * std::abs(initial),
             qPrintable(
                 QString("initial %1, final %2").arg(initial, 0, 'g', 17).arg(final, 0, 'g', 17)));

    QVERIFY(report["maxPenetration"].isDouble());
    QVERIFY(report["maxPenetration"].toDouble(1.0) < 1e-9);
    QVERIFY(report["escaped"].isDouble());
    QVERIFY(report["escaped"].toDouble(-1.0) == 0.0);

    const QJsonArray balls = report["balls"].toArray();
    QCOMPARE(balls.size(), 10);
    QCOMPARE(balls.size(), readJsonObject(magicRoom())["balls"].toArray().size());
    for (const QJsonValue& ball : balls) {
      QVERIFY(ball.isObject());
      QVERIFY(isVector(ball["position"]));
      QVERIFY(isVector(ball["velocity"]));
    }

    // Full precision: positions after two seconds of bouncing need all 17 digits, and a report
    // rounded for reading would show far fewer.
    const QByteArray rawBalls = rawArray(run.out, "balls");
    QVERIFY(!rawBalls.isEmpty());
    int mostDigits = 0;
    const QRegularExpression number("-?\\d+(\\.\\d+)?([eE][-+]?\\d+)?");
    for (const QRegularExpressionMatch& m : number.globalMatch(QString::fromUtf8(rawBalls)))
      mostDigits = std::max(mostDigits, significantDigits(m.captured().toUtf8()));
    QVERIFY2(mostDigits >= 15, rawBalls.constData());

    // Determinism: the same run prints the same final state, byte for byte.
    const CliRun again = runCli(arguments);
    VERIFY_EXIT(again, 0);
    QCOMPARE(rawArray(again.out, "balls"), rawBalls);
  }

  void runMethods_data() {
    QTest::addColumn<QString>("method");
    QTest::addColumn<QString>("integrator");
    for (const QString method : {"exact", "swept", "discrete"})
      for (const QString integrator : {"explicit-euler", "symplectic-euler", "velocity-verlet"})
        QTest::newRow(qPrintable(method + ' ' + integrator)) << method << integrator;
  }
  void runMethods() {
    QFETCH(QString, method);
    QFETCH(QString, integrator);
    const CliRun run = runCli({"run", magicRoom(), "--duration", "2", "--method", method,
                               "--integrator", integrator, "--dt", "0.01", "--json"});
    VERIFY_EXIT(run, 0);
    const QJsonObject report = QJsonDocument::fromJson(run.out).object();
    QCOMPARE(report["method"].toString(), method);
    QCOMPARE(report["integrator"].toString(), integrator);
    QVERIFY(report["timeStep"].toDouble() == 0.01);
    QVERIFY(report["simulatedTime"].toDouble() == 2.0);
    QCOMPARE(report["balls"].toArray().size(), 10);
    // The stepping methods take steps and the event-driven one does not.
    QVERIFY(isCount(report["steps"]));
    QCOMPARE(report["steps"].toDouble() > 0.0, method != "exact");
  }

  void textReport() {
    const CliRun run = runCli({"run", magicRoom(), "--duration", "2"});
    VERIFY_EXIT(run, 0);
    QVERIFY2(!run.out.startsWith('{'), run.out.constData());
    bool collisions = false;
    bool energy = false;
    for (const QByteArray& line : run.out.split('\n')) {
      collisions = collisions || (line.startsWith("collisions:") && line.contains("ball-ball"));
      energy = energy || (line.startsWith("energy:") && line.contains("initial"));
    }
    QVERIFY2(collisions, run.out.constData());
    QVERIFY2(energy, run.out.constData());
  }

  void trajectory_data() {
    QTest::addColumn<QStringList>("options");
    QTest::addColumn<double>("duration");
    QTest::addColumn<double>("timeStep");
    QTest::addColumn<int>("samples");  // 0: not known in advance
    // The scene's 1/60 s step divides 2 s only up to rounding: still 120 steps and 121 samples.
    QTest::newRow("exact, scene step")
        << QStringList{"--duration", "2"} << 2.0 << 1.0 / 60.0 << 121;
    QTest::newRow("swept, quarter step")
        << QStringList{"--duration", "2", "--method", "swept", "--dt", "0.25"} << 2.0 << 0.25 << 9;
    QTest::newRow("zero duration") << QStringList{"--duration", "0"} << 0.0 << 1.0 / 60.0 << 1;
  }
  void trajectory() {
    QFETCH(QStringList, options);
    QFETCH(double, duration);
    QFETCH(double, timeStep);
    QFETCH(int, samples);
    const QString csv = dir_.filePath(rowFileName() + ".csv");
    const CliRun run =
        runCli(QStringList{"run", magicRoom(), "--json", "--trajectory", csv} + options);
    VERIFY_EXIT(run, 0);
    const QJsonArray finalBalls = QJsonDocument::fromJson(run.out).object()["balls"].toArray();
    const QJsonArray sceneBalls = readJsonObject(magicRoom())["balls"].toArray();
    const int ballCount = static_cast<int>(sceneBalls.size());
    QCOMPARE(ballCount, 10);
    QCOMPARE(finalBalls.size(), ballCount);

    QFile file(csv);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray text = file.readAll();
    QVERIFY(text.endsWith('\n'));
    QList<QByteArray> lines = text.split('\n');
    lines.removeLast();  // after the final newline
    QVERIFY(!lines.isEmpty());
    QCOMPARE(lines.takeFirst(), QByteArray("time,ball,x,y,z,vx,vy,vz,wx,wy,wz"));
    QVERIFY(!lines.isEmpty());
    QCOMPARE(lines.size() % ballCount, 0);
    if (samples > 0) QCOMPARE(lines.size(), samples * ballCount);

    // rows[i] = {time, ball, x, y, z, vx, vy, vz, wx, wy, wz}
    QList<QList<double>> rows;
    for (const QByteArray& line : lines) {
      const QList<QByteArray> fields = line.split(',');
      QVERIFY2(fields.size() == 11, line.constData());
      QList<double> row;
      for (const QByteArray& field : fields) {
        bool ok = false;
        row << field.toDouble(&ok);
        QVERIFY2(ok && std::isfinite(row.last()), line.constData());
      }
      rows << row;
    }

    double previousSample = 0.0;
    for (int i = 0; i < rows.size(); ++i) {
      const QList<double>& row = rows[i];
      // Each sample lists every ball in scene order at one time.
      QVERIFY2(row[1] == i % ballCount, lines[i].constData());
      const double sampleTime = rows[i - i % ballCount][0];
      QVERIFY2(row[0] == sampleTime, lines[i].constData());
      if (i > 0) QVERIFY2(row[0] >= rows[i - 1][0], lines[i].constData());
      // A sample for every time step: no gap longer than one step.
      if (i % ballCount == 0 && i > 0) {
        QVERIFY2(row[0] - previousSample <= timeStep * (1.0 + 1e-9), lines[i].constData());
        previousSample = row[0];
      }
    }
    QVERIFY(rows.first()[0] == 0.0);
    QVERIFY(rows.last()[0] == duration);

    // The first sample is the scene as written, the last the state the report ends with; both
    // to the last bit, which checks the precision of the CSV and of the JSON against each other.
    for (int b = 0; b < ballCount; ++b) {
      const QList<double>& first = rows[b];
      const QList<double>& last = rows[rows.size() - ballCount + b];
      const QJsonObject scene = sceneBalls[b].toObject();
      const QJsonObject report = finalBalls[b].toObject();
      for (int k = 0; k < 3; ++k) {
        QVERIFY2(first[2 + k] == scene["position"][k].toDouble(), lines[b].constData());
        QVERIFY2(first[5 + k] == scene["velocity"][k].toDouble(), lines[b].constData());
        QVERIFY2(last[2 + k] == report["position"][k].toDouble(), qPrintable(QString::number(b)));
        QVERIFY2(last[5 + k] == report["velocity"][k].toDouble(), qPrintable(QString::number(b)));
      }
    }
  }

  // --- bench ---

  // The file bench saves, loads and predicts a gas: a size and three phases with their memory.
  void benchFilesQuick() {
    const CliRun run = runCli({"bench", "--files", "--quick"}, kBenchTimeoutMs);
    VERIFY_EXIT(run, 0);
    const QList<QByteArray> rows = nonEmptyLines(run.out);
    QCOMPARE(rows.size(), 5);
    QVERIFY2(rows[0].startsWith("scene file of 100000 balls: ") && rows[0].endsWith(" MiB"),
             rows[0].constData());
    bool ok = false;
    QVERIFY2(rows[0].split(' ').at(5).toDouble(&ok) > 10.0 && ok, rows[0].constData());
    const char* phases[] = {"save (atomic)", "load and validate", "first prediction (exact)"};
    for (int k = 0; k < 3; ++k) {
      const QByteArray row = rows[k + 2];
      QVERIFY2(row.startsWith(phases[k]), row.constData());
      const QList<QByteArray> cells = row.mid(qstrlen(phases[k])).simplified().split(' ');
      QVERIFY2(cells.size() >= 2 && cells[0].toDouble(&ok) > 0.0 && ok && cells[1] == "s",
               row.constData());
    }
  }

  // Every placement of the big balls at every ratio, under both methods; the rows with big
  // balls use two grids, the gas alone one.
  void benchSizesQuick() {
    const CliRun run = runCli({"bench", "--sizes", "--quick"}, kBenchTimeoutMs);
    VERIFY_EXIT(run, 0);
    QList<QByteArray> rows = nonEmptyLines(run.out);
    QCOMPARE(rows.size(), 1 + 2 * 3 * 3);
    QVERIFY2(rows.takeFirst().contains("us/collision"), run.out.constData());
    for (const QByteArray& row : rows) {
      const QList<QByteArray> cells = row.simplified().split(' ');
      QVERIFY2(cells.size() > 12, row.constData());
      const bool alone = cells[1] == "none";
      QVERIFY2(cells[0] == "exact" || cells[0] == "swept", row.constData());
      QCOMPARE(cells[5], alone ? QByteArray("2000") : QByteArray("2004"));
      bool ok = false;
      QVERIFY2(cells[7].toDouble(&ok) > 1000.0 && ok, row.constData());  // collisions
      QVERIFY2(row.contains(alone ? "cell grid " : "(2 ball size classes)"), row.constData());
    }
  }

  void benchQuick() {
    const CliRun run = runCli({"bench", "--quick"}, kBenchTimeoutMs);
    VERIFY_EXIT(run, 0);
    QList<QByteArray> rows = nonEmptyLines(run.out);
    QVERIFY(!rows.isEmpty());
    const QByteArray header = rows.takeFirst();
    for (const char* column : {"method", "balls", "scene", "collisions", "Mevents/s", "crossings",
                               "energy drift", "wall s"})
      QVERIFY2(header.contains(column), header.constData());

    // The pile table follows the main one.
    qsizetype pileHeader = 0;
    while (pileHeader < rows.size() && !rows[pileHeader].startsWith("pile ")) ++pileHeader;
    QVERIFY(pileHeader < rows.size());
    const QList<QByteArray> piles = rows.mid(pileHeader + 1);
    rows = rows.mid(0, pileHeader);
    QCOMPARE(piles.size(), 2);
    for (const QByteArray& row : piles) {
      const QList<QByteArray> cells = row.simplified().split(' ');
      QVERIFY2(cells.size() == 9, row.constData());
      QVERIFY2(cells[0] == (row == piles[0] ? "pile" : "rough-pile"), row.constData());
      bool ok = false;
      QVERIFY2(cells[3].toDouble(&ok) > 0.0 && ok, row.constData());  // simulated seconds
      QVERIFY2(cells[7].contains('/'), row.constData());              // resting of all
    }

    QSet<QByteArray> methods, scenes;
    for (const QByteArray& row : rows) {
      const QList<QByteArray> cells = row.simplified().split(' ');
      QVERIFY2(cells.size() == 11, row.constData());
      methods << cells[0];
      bool ok = false;
      QVERIFY2(cells[1].toInt(&ok) > 0 && ok, row.constData());
      scenes << cells[2];
      // A collisions count, and a drift only for the elastic scenes.
      QVERIFY2(cells[4].toDouble(&ok) > 0 && ok, row.constData());
      QVERIFY2((cells[9] == "-") == (cells[2] == "galton"), row.constData());
      // Events and the crossings' share of them only for `exact`, whose events they are.
      QVERIFY2((cells[6] == "-") == (cells[0] != "exact"), row.constData());
      QVERIFY2((cells[7] == "-") == (cells[0] != "exact"), row.constData());
    }
    QCOMPARE(scenes, (QSet<QByteArray>{"gas", "rough-gas", "gravity-gas", "galton", "mixed"}));
    QCOMPARE(methods, (QSet<QByteArray>{"exact", "swept", "discrete"}));

    const QList<QByteArray> progress = nonEmptyLines(run.err);
    for (const QByteArray& line : progress) QVERIFY2(line.startsWith("bench:"), line.constData());
    QCOMPARE(progress.size(), rows.size() + piles.size());
    QCOMPARE(rows.size(), 10);
  }

  // --- study ---

  // The figures are times, unchecked; what is checked is that every run is reported once and
  // the summary names the threads asked for.
  void studyMagicRoom_data() {
    QTest::addColumn<int>("threads");
    QTest::newRow("1 thread") << 1;
    QTest::newRow("2 threads") << 2;
  }
  void studyMagicRoom() {
    QFETCH(int, threads);
    const CliRun run =
        runCli({"study", magicRoom(), "--duration", "0.5", "--threads", QString::number(threads)});
    VERIFY_EXIT(run, 0);
    QList<QByteArray> lines = nonEmptyLines(run.out);
    QVERIFY2(lines.size() == 3 + 31 + 5, qPrintable(run.describe()));
    QVERIFY2(lines.takeFirst().simplified() == "simulated s 0.5", qPrintable(run.describe()));
    // The finest setting follows the magic room's few balls for some part of the half second.
    const QList<QByteArray> horizon = lines.takeFirst().simplified().split(' ');
    QVERIFY2(horizon.size() > 3 && horizon[0] == "horizon" && horizon[2].toDouble() > 0.0 &&
                 horizon[2].toDouble() <= 0.5,
             qPrintable(run.describe()));
    const QByteArray header = lines.takeFirst();
    QVERIFY2(header.startsWith("method"), qPrintable(run.describe()));
    for (const char* column : {"position error", "energy drift", "penetration m", "escaped",
                               "speeds KS", "positions KS"})
      QVERIFY2(header.contains(column), qPrintable(run.describe()));
    QVERIFY2(lines[0].startsWith("exact"), qPrintable(run.describe()));
    QSet<QByteArray> runs;
    for (int i = 0; i < 31; ++i) runs << lines[i].simplified().split(' ').mid(0, 3).join(' ');
    QCOMPARE(runs.size(), 31);
    QCOMPARE(lines[31].simplified(), "threads " + QByteArray::number(threads));
    for (const char* figure : {"wall s", "reference s", "runs s", "speed-up"})
      QVERIFY2(run.out.contains(figure), qPrintable(run.describe()));
    QVERIFY2(run.err.startsWith("study:"), qPrintable(run.describe()));
  }

  void autoChoosesAndReports() {
    const CliRun run = runCli(
        {"run", sceneFile("gas-box.json"), "--duration", "20", "--method", "auto", "--json"});
    VERIFY_EXIT(run, 0);
    const QJsonObject report = QJsonDocument::fromJson(run.out).object();
    const QJsonObject choice = report["auto"].toObject();
    const QJsonArray candidates = choice["candidates"].toArray();
    QCOMPARE(candidates.size(), 13);
    QVERIFY(choice["met"].toBool());
    const QJsonObject chosen = candidates[choice["chosen"].toInt()].toObject();
    // The run is the chosen setting's, and the chosen one meets the default tolerance.
    QCOMPARE(report["method"].toString(), chosen["method"].toString());
    QVERIFY(chosen["meets"].toBool());
    QVERIFY(chosen["energyErrorPerSecond"].toDouble() <=
            choice["tolerance"].toObject()["energyPerSecond"].toDouble());
    QVERIFY(chosen["verdict"].toString().contains("cheapest"));
    for (const QJsonValue c : candidates) {
      QVERIFY(!c.toObject()["verdict"].toString().isEmpty());
      // Nothing that meets the tolerance is cheaper than the chosen one.
      if (c.toObject()["meets"].toBool())
        QVERIFY(c.toObject()["costPerSecond"].toDouble() >= chosen["costPerSecond"].toDouble());
    }
    QVERIFY(choice["pilotShare"].toDouble() >= 0.0);
    QVERIFY(!choice["reason"].toString().isEmpty());
  }

  void autoTextSaysWhatItChose() {
    const CliRun run = runCli(
        {"run", magicRoom(), "--duration", "5", "--method", "auto", "--tolerance", "0.01,0.1"});
    VERIFY_EXIT(run, 0);
    QVERIFY2(run.out.contains("auto: tolerance: energy error 0.01 per simulated second, "
                              "penetration 0.1 of the radius"),
             qPrintable(run.describe()));
    QVERIFY2(run.out.contains("auto: chose "), qPrintable(run.describe()));
    QVERIFY2(run.out.contains("of the run's"), qPrintable(run.describe()));
  }

  // A scene saved under method auto runs under the pilot's choice for its own tolerance;
  // --tolerance overrides it, a method given runs that method, and --integrator alone is refused.
  void aSceneSavedUnderAutoRunsAuto() {
    QFile room(magicRoom());
    QVERIFY(room.open(QIODevice::ReadOnly));
    QByteArray text = room.readAll();
    QVERIFY(text.contains(R"("method": "exact")"));
    text.replace(R"("method": "exact")", R"("method": "auto", "tolerance": [0.02, 0.2])");
    const QString file = writeFile("auto.json", text);
    const CliRun run = runCli({"run", file, "--duration", "5", "--json"});
    VERIFY_EXIT(run, 0);
    const QJsonObject tolerance =
        QJsonDocument::fromJson(run.out).object()["auto"].toObject()["tolerance"].toObject();
    QCOMPARE(tolerance["energyPerSecond"].toDouble(), 0.02);
    QCOMPARE(tolerance["penetrationFraction"].toDouble(), 0.2);
    const CliRun tighter = runCli(
        {"run", file, "--duration", "5", "--method", "auto", "--tolerance", "0.01", "--json"});
    VERIFY_EXIT(tighter, 0);
    QCOMPARE(QJsonDocument::fromJson(tighter.out)
                 .object()["auto"]
                 .toObject()["tolerance"]
                 .toObject()["energyPerSecond"]
                 .toDouble(),
             0.01);
    const CliRun swept = runCli({"run", file, "--duration", "1", "--method", "swept", "--json"});
    VERIFY_EXIT(swept, 0);
    QVERIFY(!QJsonDocument::fromJson(swept.out).object().contains("auto"));
    QCOMPARE(QJsonDocument::fromJson(swept.out).object()["method"].toString(), QString("swept"));
    const CliRun integrator = runCli({"run", file, "--integrator", "velocity-verlet"});
    VERIFY_EXIT(integrator, 2);
    QVERIFY2(integrator.err.contains("the scene's method is auto"),
             qPrintable(integrator.describe()));
  }

  void autoWithNoSettingMeetingTheTolerance() {
    // Below round-off: nothing meets it (the largest energy error over the pilot is a round-off
    // at least for every setting; test_method_choice checks this for pilots of many lengths).
    // Nothing runs unless the closest is asked for.
    const QStringList arguments{"run",      magicRoom(), "--duration",  "10",
                                "--method", "auto",      "--tolerance", "1e-30,1e-30"};
    const CliRun refused = runCli(arguments);
    VERIFY_EXIT(refused, 4);
    QVERIFY2(refused.err.contains("no setting meets the tolerance") &&
                 refused.err.contains("--accept-closest"),
             qPrintable(refused.describe()));
    QVERIFY2(refused.out.contains("auto: no setting meets the tolerance"),
             qPrintable(refused.describe()));
    QVERIFY2(!refused.out.contains("collisions:"), qPrintable(refused.describe()));  // no run
    const CliRun closest = runCli(arguments + QStringList{"--accept-closest", "--json"});
    VERIFY_EXIT(closest, 0);
    const QJsonObject report = QJsonDocument::fromJson(closest.out).object();
    const QJsonObject choice = report["auto"].toObject();
    QVERIFY(!choice["met"].toBool());
    const QJsonObject ran = choice["candidates"].toArray()[choice["chosen"].toInt()].toObject();
    QCOMPARE(report["method"].toString(), ran["method"].toString());
    QVERIFY(report["simulatedTime"].toDouble() == 10.0);
  }

  // --- bad input: exit code 2, nothing on stdout, a short message naming the problem ---

  void badArguments_data() {
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QStringList>("message");  // substrings of stderr
    const QString scene = magicRoom();
    const QString other = sceneFile("gas-box.json");
    const QString missing = dir_.filePath("missing.json");
    const QString noDir = dir_.filePath("no/such/dir/trajectory.csv");
    QTest::newRow("no arguments") << QStringList{} << QStringList{"no command"};
    QTest::newRow("unknown command")
        << QStringList{"simulate", scene} << QStringList{"unknown command", "simulate"};
    QTest::newRow("unknown option")
        << QStringList{"run", scene, "--fast"} << QStringList{"unknown option", "--fast"};
    QTest::newRow("unknown bench option")
        << QStringList{"bench", "--slow"} << QStringList{"--slow"};
    QTest::newRow("two benches") << QStringList{"bench", "--files", "--timeline"}
                                 << QStringList{"--timeline", "--files"};
    QTest::newRow("three benches") << QStringList{"bench", "--sizes", "--files", "--timeline"}
                                   << QStringList{"--timeline", "--sizes"};
    QTest::newRow("unknown study option")
        << QStringList{"study", scene, "--fast"} << QStringList{"unknown option", "--fast"};
    QTest::newRow("study without a scene")
        << QStringList{"study", "--threads", "2"} << QStringList{"no scene file"};
    QTest::newRow("study missing file")
        << QStringList{"study", missing} << QStringList{missing, "cannot open"};
    QTest::newRow("--threads 0") << QStringList{"study", scene, "--threads", "0"}
                                 << QStringList{"--threads", "'0'"};
    QTest::newRow("--threads 2.5")
        << QStringList{"study", scene, "--threads", "2.5"} << QStringList{"--threads", "2.5"};
    QTest::newRow("study --duration nan")
        << QStringList{"study", scene, "--duration", "nan"} << QStringList{"--duration", "nan"};
    QTest::newRow("run without a scene")
        << QStringList{"run", "--json"} << QStringList{"no scene file"};
    QTest::newRow("validate without a scene")
        << QStringList{"validate"} << QStringList{"no scene file"};
    QTest::newRow("two scene files")
        << QStringList{"run", scene, other} << QStringList{other, "one scene file"};
    QTest::newRow("missing file") << QStringList{"run", missing}
                                  << QStringList{missing, "cannot open"};
    QTest::newRow("validate missing file")
        << QStringList{"validate", missing} << QStringList{missing, "cannot open"};
    QTest::newRow("directory as scene")
        << QStringList{"run", dir_.path()} << QStringList{dir_.path(), "directory"};
    QTest::newRow("--method fast") << QStringList{"run", scene, "--method", "fast"}
                                   << QStringList{"unknown method", "fast", "exact"};
    QTest::newRow("--integrator rk4")
        << QStringList{"run", scene, "--integrator", "rk4"}
        << QStringList{"unknown integrator", "rk4", "velocity-verlet"};
    QTest::newRow("--dt 0") << QStringList{"run", scene, "--dt", "0"}
                            << QStringList{"--dt", "positive"};
    QTest::newRow("--dt -1") << QStringList{"run", scene, "--dt", "-1"}
                             << QStringList{"--dt", "positive"};
    QTest::newRow("--dt nan") << QStringList{"run", scene, "--dt", "nan"}
                              << QStringList{"--dt", "nan"};
    QTest::newRow("--dt inf") << QStringList{"run", scene, "--dt", "inf"}
                              << QStringList{"--dt", "inf"};
    QTest::newRow("--dt 1e7") << QStringList{"run", scene, "--dt", "1e7"}
                              << QStringList{"--dt", "1e7"};
    QTest::newRow("--duration -5")
        << QStringList{"run", scene, "--duration", "-5"} << QStringList{"--duration", "-5"};
    QTest::newRow("--duration abc")
        << QStringList{"run", scene, "--duration", "abc"} << QStringList{"--duration", "abc"};
    QTest::newRow("--duration without value")
        << QStringList{"run", scene, "--duration"} << QStringList{"--duration", "value"};
    QTest::newRow("--watch-penetration -1")
        << QStringList{"run", scene, "--stop-on-divergence", "--watch-penetration", "-1"}
        << QStringList{"--watch-penetration", "'-1'"};
    QTest::newRow("--watch-energy-rise nan")
        << QStringList{"run", scene, "--stop-on-divergence", "--watch-energy-rise", "nan"}
        << QStringList{"--watch-energy-rise", "nan"};
    QTest::newRow("--watch-escape without value")
        << QStringList{"run", scene, "--stop-on-divergence", "--watch-escape"}
        << QStringList{"--watch-escape", "value"};
    QTest::newRow("--watch-off unknown check")
        << QStringList{"run", scene, "--stop-on-divergence", "--watch-off", "escape,speed"}
        << QStringList{"--watch-off", "'speed'", "energy-rise"};
    QTest::newRow("watch option without --stop-on-divergence")
        << QStringList{"run", scene, "--watch-off", "escape"}
        << QStringList{"--stop-on-divergence"};
    QTest::newRow("--tolerance 0")
        << QStringList{"run", scene, "--method", "auto", "--tolerance", "0"}
        << QStringList{"tolerance.energy", "above zero"};
    QTest::newRow("--tolerance 1e-3,-1")
        << QStringList{"run", scene, "--method", "auto", "--tolerance", "1e-3,-1"}
        << QStringList{"tolerance.penetration", "above zero"};
    QTest::newRow("--tolerance 1e-3,x")
        << QStringList{"run", scene, "--method", "auto", "--tolerance", "1e-3,x"}
        << QStringList{"--tolerance", "'1e-3,x'"};
    QTest::newRow("--tolerance without auto")
        << QStringList{"run", scene, "--tolerance", "1e-3"} << QStringList{"--method auto"};
    QTest::newRow("--accept-closest without auto")
        << QStringList{"run", scene, "--accept-closest"} << QStringList{"--method auto"};
    QTest::newRow("auto with an integrator")
        << QStringList{"run", scene, "--method", "auto", "--integrator", "velocity-verlet"}
        << QStringList{"--integrator"};
    QTest::newRow("--trajectory into missing directory")
        << QStringList{"run", scene, "--json", "--trajectory", noDir}
        << QStringList{"trajectory", noDir};
  }
  void badArguments() {
    QFETCH(QStringList, arguments);
    QFETCH(QStringList, message);
    const CliRun run = runCli(arguments);
    VERIFY_REFUSED(run);
    for (const QString& part : message)
      QVERIFY2(QString::fromUtf8(run.err).contains(part), qPrintable(part + '\n' + run.describe()));
  }

  void badScene_data() {
    QTest::addColumn<QByteArray>("scene");
    QTest::addColumn<QStringList>("message");  // substrings of stderr besides the file name
    QTest::newRow("invalid json") << QByteArray(R"({"format": "carom-scene", "version": 1,
 "balls": [
  {"position": [0, 0, 0], "radius": 0.1,}
 ]
}
)") << QStringList{"invalid JSON", "line 3"};
    QTest::newRow("empty file") << QByteArray() << QStringList{"invalid JSON"};
    QTest::newRow("top-level array") << QByteArray(R"([{"format": "carom-scene", "version": 1}])")
                                     << QStringList{"object", "array"};
    QTest::newRow("no format") << QByteArray(R"({"version": 1})")
                               << QStringList{"format", "missing"};
    QTest::newRow("newer version") << sceneText("", 4) << QStringList{"version 4", "newer"};
    QTest::newRow("wrong type") << sceneText(
                                       R"("balls": [{"position": [0, 0, 0], "radius": "big"}])")
                                << QStringList{"balls[0].radius", "number", "string"};
    QTest::newRow("short vector") << sceneText(R"("balls": [{"position": [0, 0], "radius": 0.1}])")
                                  << QStringList{"balls[0].position", "3 numbers"};
    QTest::newRow("missing position") << sceneText(R"("balls": [{"radius": 0.1}])")
                                      << QStringList{"balls[0].position", "missing"};
    QTest::newRow("absurd position")
        << sceneText(R"("balls": [{"position": [1e300, 0, 0], "radius": 1}])")
        << QStringList{"balls[0].position", "1e300"};
    QTest::newRow("absurd velocity")
        << sceneText(
               R"("balls": [{"position": [0, 0, 0], "velocity": [0, -1e300, 0],
                                     "radius": 1}])")
        << QStringList{"balls[0].velocity", "1e300"};
    QTest::newRow("absurd mass")
        << sceneText(R"("balls": [{"position": [0, 0, 0], "radius": 1, "mass": 1e300}])")
        << QStringList{"balls[0].mass", "1e300"};
    QTest::newRow("beyond double")
        << sceneText(R"("balls": [{"position": [1e400, 0, 0], "radius": 1}])")
        << QStringList{"invalid JSON"};
    QTest::newRow("nan literal") << sceneText(
                                        R"("balls": [{"position": [NaN, 0, 0], "radius": 1}])")
                                 << QStringList{"invalid JSON"};
    QTest::newRow("zero normal") << sceneText(
                                        R"("planes": [{"point": [0, 0, 0], "normal": [0, 0, 0]}])")
                                 << QStringList{"planes[0].normal", "zero"};
    QTest::newRow("zero axis")
        << sceneText(R"("cylinders": [{"point": [0, 0, 0], "axis": [0, 0, 0], "radius": 1}])")
        << QStringList{"cylinders[0].axis", "zero"};
    QTest::newRow("negative radius")
        << sceneText(R"("balls": [{"position": [0, 0, 0], "radius": -0.1}])")
        << QStringList{"balls[0].radius", "positive"};
    QTest::newRow("zero mass")
        << sceneText(R"("balls": [{"position": [0, 0, 0], "radius": 0.1, "mass": 0}])")
        << QStringList{"balls[0].mass", "positive"};
    QTest::newRow("restitution 1.5") << sceneText(
                                            R"("balls": [{"position": [0, 0, 0], "radius": 0.1,
                                     "restitution": 1.5}])")
                                     << QStringList{"balls[0].restitution", "1.5"};
    QTest::newRow("world restitution") << sceneText(R"("world": {"restitution": -0.5})")
                                       << QStringList{"world.restitution", "-0.5"};
    QTest::newRow("zero time step")
        << sceneText(R"("world": {"timeStep": 0})") << QStringList{"world.timeStep", "positive"};
    QTest::newRow("unknown method")
        << sceneText(R"("world": {"method": "fast"})") << QStringList{"world.method", "fast"};
    QTest::newRow("unknown integrator")
        << sceneText(R"("world": {"integrator": "rk4"})") << QStringList{"world.integrator", "rk4"};
    QTest::newRow("only the fourth ball bad") << sceneText(R"("balls": [
        {"position": [0, 0, 0], "radius": 0.1}, {"position": [1, 0, 0], "radius": 0.1},
        {"position": [2, 0, 0], "radius": 0.1}, {"position": [3, 0, 0], "radius": 0},
        {"position": [4, 0, 0], "radius": 0.1}])")
                                              << QStringList{"balls[3].radius", "positive"};
    QTest::newRow("overlapping balls") << sceneText(R"("balls": [
        {"position": [0, 0, 0], "radius": 0.1}, {"position": [0.15, 0, 0], "radius": 0.1}])")
                                       << QStringList{"balls[1].position", "overlaps balls[0]"};
    // Far beyond rounding and far below anything visible: still an overlap.
    QTest::newRow("balls overlapping by 1e-5")
        << sceneText(R"("balls": [
        {"position": [0, 0, 0], "radius": 0.1}, {"position": [0.19999, 0, 0], "radius": 0.1}])")
        << QStringList{"balls[1].position", "overlaps balls[0]"};
    QTest::newRow("ball overlapping a plane")
        << sceneText(R"(
        "planes": [{"point": [0, 0, 0], "normal": [0, 1, 0]}],
        "balls": [{"position": [0, 0.05, 0], "radius": 0.1}])")
        << QStringList{"balls[0].position", "overlaps planes[0]"};
    QTest::newRow("ball behind a plane") << sceneText(R"(
        "planes": [{"point": [0, 0, 0], "normal": [0, 1, 0]}],
        "balls": [{"position": [0, -0.1, 0], "radius": 0.1}])")
                                         << QStringList{"balls[0].position", "planes[0]", "behind"};
    QTest::newRow("duplicate top-level key")
        << QByteArray(R"({"format": "carom-scene", "version": 1, "version": 1})")
        << QStringList{"version: duplicate key"};
    QTest::newRow("duplicate key in a ball") << sceneText(R"("balls": [
        {"position": [0, 0, 0], "radius": 0.1}, {"position": [1, 0, 0], "radius": 0.1},
        {"position": [2, 0, 0], "radius": 0.1, "radius": 0.2}])")
                                             << QStringList{"balls[2].radius: duplicate key"};
    QTest::newRow("ball inside a cylinder")
        << sceneText(R"(
        "cylinders": [{"point": [0, 0, 0], "axis": [0, 1, 0], "radius": 1}],
        "balls": [{"position": [0.5, 0, 0], "radius": 0.1}])")
        << QStringList{"balls[0].position", "overlaps cylinders[0]"};
  }
  void badScene() {
    QFETCH(QByteArray, scene);
    QFETCH(QStringList, message);
    const QString path = writeRowFile(scene);
    QVERIFY(!path.isEmpty());
    for (const QStringList& arguments :
         {QStringList{"validate", path}, QStringList{"run", path, "--json"}}) {
      const CliRun run = runCli(arguments);
      VERIFY_REFUSED(run);
      const QString err = QString::fromUtf8(run.err);
      QVERIFY2(err.contains(path), qPrintable(run.describe()));
      for (const QString& part : message)
        QVERIFY2(err.contains(part), qPrintable(part + '\n' + run.describe()));
    }
  }

  // A refused scene must not leave an empty or partial trajectory behind.
  void badSceneWritesNoTrajectory() {
    const QString scene = writeFile("bad-for-trajectory.json", sceneText(R"("balls": [
        {"position": [0, 0, 0], "radius": 0.1}, {"position": [0.1, 0, 0], "radius": 0.1}])"));
    QVERIFY(!scene.isEmpty());
    const QString csv = dir_.filePath("never-written.csv");
    const CliRun run = runCli({"run", scene, "--trajectory", csv});
    VERIFY_EXIT(run, 2);
    QVERIFY2(!QFileInfo::exists(csv), qPrintable(run.describe()));
  }

  // Output that cannot be written must not look like success to a script.
  void stdoutWriteFailureIsAnError() {
    if (!QFileInfo::exists("/dev/full")) QSKIP("needs /dev/full");
    const CliRun run =
        runCli({"run", magicRoom(), "--duration", "1", "--json"}, kTimeoutMs, "/dev/full");
    QVERIFY2(run.finished && run.status == QProcess::NormalExit, qPrintable(run.describe()));
    QVERIFY2(run.exitCode != 0, qPrintable(run.describe()));
  }

  // --- issue 12: the runner counts honestly ---

  // --trajectory reports every step but must not change the steps: 10,000 asked, 10,000 taken
  // with and without it, and the same final state to the last bit.
  void trajectoryKeepsTheSteps_data() {
    QTest::addColumn<QString>("method");
    for (const char* method : {"exact", "swept", "discrete"}) QTest::newRow(method) << method;
  }
  void trajectoryKeepsTheSteps() {
    QFETCH(QString, method);
    const QStringList arguments{"run",  magicRoom(), "--duration", "100",   "--dt",
                                "0.01", "--method",  method,       "--json"};
    const CliRun plain = runCli(arguments);
    VERIFY_EXIT(plain, 0);
    const QString csv = dir_.filePath(rowFileName() + "-steps.csv");
    const CliRun traced = runCli(arguments + QStringList{"--trajectory", csv});
    VERIFY_EXIT(traced, 0);
    const double stepsAsked = method == "exact" ? 0.0 : 10000.0;
    for (const CliRun* run : {&plain, &traced}) {
      const QJsonObject report = QJsonDocument::fromJson(run->out).object();
      QVERIFY2(report["steps"].toDouble(-1) == stepsAsked, qPrintable(run->describe()));
      QVERIFY2(report["simulatedTime"].toDouble() == 100.0, qPrintable(run->describe()));
    }
    QCOMPARE(rawArray(traced.out, "balls"), rawArray(plain.out, "balls"));
  }

  // wallSeconds is all the work (set-up, run, measurements), within the process's own time;
  // setupSeconds is the loading, checking, building and first prediction, part of it.
  void wallSecondsCountsAllTheWork_data() {
    QTest::addColumn<QString>("method");
    for (const char* method : {"exact", "swept", "discrete"}) QTest::newRow(method) << method;
  }
  void wallSecondsCountsAllTheWork() {
    QFETCH(QString, method);
    const QString scene = writeFile("mixed-sizes.json", mixedSizeScene());
    QVERIFY(!scene.isEmpty());
    QElapsedTimer process;
    process.start();
    // Long enough that the run is measurable: every method gives each size class a grid of its
    // own, so this scene is fast.
    const QString duration = method == "exact" ? "30" : "5";
    const CliRun run = runCli({"run", scene, "--duration", duration, "--method", method, "--json"});
    const double processSeconds = process.nsecsElapsed() * 1e-9;
    VERIFY_EXIT(run, 0);
    const QJsonObject report = QJsonDocument::fromJson(run.out).object();
    const double wall = report["wallSeconds"].toDouble(-1.0);
    const QString figures = QString("wallSeconds %1, setupSeconds %2, process %3 s")
                                .arg(wall)
                                .arg(report["setupSeconds"].toDouble(-1.0))
                                .arg(processSeconds);
    QVERIFY2(wall > 0.0 && wall <= processSeconds, qPrintable(figures));
    QVERIFY2(report["setupSeconds"].isDouble(), qPrintable(run.describe()));
    const double setup = report["setupSeconds"].toDouble();
    QVERIFY2(setup > 0.0 && setup <= wall, qPrintable(figures));
    // The parts, timed apart on the same clock, all fall within it (to their rounding to
    // seconds). How much of the process's time they are is the machine's to say: a cold start
    // under load (a CI run's first program) took 0.3 s of a 0.7 s process.
    const double runSeconds = report["runSeconds"].toDouble(-1.0);
    const double measureSeconds = report["measureSeconds"].toDouble(-1.0);
    QVERIFY2(runSeconds > 0.0 && measureSeconds >= 0.0, qPrintable(run.describe()));
    QVERIFY2(setup + runSeconds + measureSeconds <= wall * (1.0 + 1e-12) + 1e-9,
             qPrintable(figures));

    const CliRun text = runCli({"run", scene, "--duration", "0.01", "--method", method});
    VERIFY_EXIT(text, 0);
    bool setupLine = false;
    for (const QByteArray& line : text.out.split('\n'))
      setupLine = setupLine || (line.startsWith("wall:") && line.contains("set-up"));
    QVERIFY2(setupLine, text.out.constData());
  }

  // 1e12 s at 1e-12 s is 1e24 steps: refused at once, not run with no sign of life. `exact`
  // takes no steps, but its trajectory would take a row a step.
  void absurdStepCountIsRefused_data() {
    QTest::addColumn<QStringList>("options");
    QTest::newRow("swept") << QStringList{"--method", "swept"};
    QTest::newRow("discrete") << QStringList{"--method", "discrete"};
    QTest::newRow("exact with a trajectory")
        << QStringList{"--method", "exact", "--trajectory", dir_.filePath("absurd.csv")};
  }
  void absurdStepCountIsRefused() {
    QFETCH(QStringList, options);
    const CliRun run = runCli(
        QStringList{"run", magicRoom(), "--duration", "1e12", "--dt", "1e-12"} + options, 10000);
    VERIFY_REFUSED(run);
    QVERIFY2(run.err.contains("1e+24 steps"), qPrintable(run.describe()));
    QVERIFY(!QFileInfo::exists(dir_.filePath("absurd.csv")));
  }

  // Ctrl+C stops a run and still prints the report so far, marked as interrupted, with the
  // shell's exit code for SIGINT, 130.
  void ctrlCPrintsTheReportSoFar_data() {
    QTest::addColumn<QString>("method");
    QTest::addColumn<bool>("json");
    for (const QString method : {"exact", "swept", "discrete"}) {
      QTest::newRow(qPrintable(method + ", json")) << method << true;
      QTest::newRow(qPrintable(method + ", text")) << method << false;
    }
  }
  void ctrlCPrintsTheReportSoFar() {
    QFETCH(QString, method);
    QFETCH(bool, json);
    QStringList arguments{"run", magicRoom(), "--duration", "1e9", "--method", method};
    if (json) arguments << "--json";
    // A Ctrl+C that comes before the program has installed its handler, or before its first
    // slice (a loaded machine, a sanitizer build starting slowly), tests nothing: it is sent
    // again later, up to three times. A handler never installed still fails every time.
    CliRun run;
    for (int attempt = 1; attempt <= 3; ++attempt) {
      run = interruptCli(arguments, 1500 * attempt);
      const bool tooEarly =
          run.status == QProcess::CrashExit ||
          (json && QJsonDocument::fromJson(run.out).object()["simulatedTime"].toDouble() == 0.0);
      if (!tooEarly) break;
    }
    VERIFY_EXIT(run, 130);
    if (json) {
      const QJsonObject report = QJsonDocument::fromJson(run.out).object();
      QVERIFY2(report["interrupted"].toBool(), qPrintable(run.describe()));
      const double simulated = report["simulatedTime"].toDouble(-1.0);
      QVERIFY2(simulated > 0.0 && simulated < 1e9, qPrintable(run.describe()));
      QCOMPARE(report["balls"].toArray().size(), 10);
      QVERIFY2(report["wallSeconds"].toDouble() > 0.5, qPrintable(run.describe()));
    } else {
      QVERIFY2(run.out.startsWith("method:"), qPrintable(run.describe()));
      QVERIFY2(run.out.contains("interrupted"), qPrintable(run.describe()));
    }
    QVERIFY2(run.err.contains("interrupted"), qPrintable(run.describe()));
  }

  // On a terminal a long run shows a progress bar with an estimate of the time left.
  void progressBarOnATerminal_data() {
    QTest::addColumn<QString>("method");
    for (const char* method : {"exact", "swept", "discrete"}) QTest::newRow(method) << method;
  }
  void progressBarOnATerminal() {
    QFETCH(QString, method);
    const CliRun run = interruptCli(
        {"run", magicRoom(), "--duration", "1e9", "--method", method, "--json"}, 2500, true);
    VERIFY_EXIT(run, 130);
    QVERIFY2(run.err.contains('%') && run.err.contains("left") && run.err.contains('\r'),
             qPrintable(run.describe()));
    QVERIFY2(QJsonDocument::fromJson(run.out).isObject(), qPrintable(run.describe()));
  }

  // Not on a terminal a long run prints a plain line every 10 s, and a short one nothing (the
  // other tests check that stderr stays empty).
  void progressLinesWithoutATerminal() {
    const CliRun run = interruptCli({"run", magicRoom(), "--duration", "1e9", "--json"}, 11500);
    VERIFY_EXIT(run, 130);
    const QList<QByteArray> lines = nonEmptyLines(run.err);
    QVERIFY2(lines.size() == 2, qPrintable(run.describe()));
    QVERIFY2(lines[0].startsWith("carom-cli: progress:") && lines[0].contains("left"),
             qPrintable(run.describe()));
    QVERIFY2(!run.err.contains('\r'), qPrintable(run.describe()));
  }

  // A FIFO with no writer would block a read forever: anything but a regular file is refused
  // at once, before it is opened.
  // --- the watch: --stop-on-divergence ---

  // A heavy ball crushes a light one against a thick box at a step far too long for it: the
  // light ball's centre ends up in the box after the first step (test_watch has the same).
  QString crushScene() {
    return writeFile("crush.json", sceneText(R"(
 "world": {"gravity": [0, 0, 0], "timeStep": 0.1, "method": "discrete"},
 "boxes": [{"center": [1, 0, 0], "halfExtents": [0.5, 1, 1]}],
 "balls": [
  {"position": [-0.5, 0, 0], "velocity": [8, 0, 0], "radius": 0.3, "mass": 1000},
  {"position": [0.39, 0, 0], "velocity": [0, 0, 0], "radius": 0.1, "mass": 0.001, "name": "nut"}
 ])",
                                             2));
  }

  void stopOnDivergenceText() {
    const CliRun run = runCli({"run", crushScene(), "--stop-on-divergence"});
    VERIFY_EXIT(run, 3);
    QVERIFY2(run.out.startsWith("method:"), qPrintable(run.describe()));
    QVERIFY2(run.out.contains("simulated: 0.1 s"), qPrintable(run.describe()));
    QVERIFY2(run.out.contains("diverged: escape, ball 1 (\"nut\"), at 0.1 s (last good step 0 s)"),
             qPrintable(run.describe()));
    QVERIFY2(run.err.contains("stopped by the watch at 0.1 of 10 s"), qPrintable(run.describe()));
    // A trajectory ends with the state the watch stopped on.
    const QString csv = dir_.filePath("crush.csv");
    const CliRun traced =
        runCli({"run", crushScene(), "--stop-on-divergence", "--trajectory", csv});
    VERIFY_EXIT(traced, 3);
    QFile file(csv);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QList<QByteArray> rows = file.readAll().trimmed().split('\n');
    QCOMPARE(rows.size(), 1 + 2 + 2);  // the header, then both balls at 0 and at 0.1 s
    QVERIFY2(rows.last().startsWith("0.1"), rows.last().constData());
  }

  void stopOnDivergenceJson() {
    // With the escape check off the centre in the box is an overlap of two radii.
    const CliRun run =
        runCli({"run", crushScene(), "--stop-on-divergence", "--watch-off", "escape", "--json"});
    VERIFY_EXIT(run, 3);
    const QJsonObject report = QJsonDocument::fromJson(run.out).object();
    const QJsonObject divergence = report["divergence"].toObject();
    QCOMPARE(divergence["kind"].toString(), QString("penetration"));
    QCOMPARE(divergence["ball"].toInt(-1), 1);
    QCOMPARE(divergence["ballName"].toString(), QString("nut"));
    QCOMPARE(divergence["time"].toDouble(), 0.1);
    QCOMPARE(divergence["lastGoodTime"].toDouble(-1), 0.0);
    QCOMPARE(divergence["tolerance"].toDouble(), 0.5);
    QVERIFY2(divergence["value"].toDouble() > 1.9, qPrintable(run.describe()));
    QCOMPARE(report["simulatedTime"].toDouble(), 0.1);
  }

  void watchOffRunsToTheEnd() {
    const CliRun run = runCli({"run", crushScene(), "--stop-on-divergence", "--watch-off",
                               "escape,penetration", "--json"});
    VERIFY_EXIT(run, 0);
    const QJsonObject report = QJsonDocument::fromJson(run.out).object();
    QVERIFY2(report["divergence"].isNull(), qPrintable(run.describe()));
    QCOMPARE(report["simulatedTime"].toDouble(), 10.0);
    // A tolerance wider than the overlap lets the same run through.
    const CliRun wide = runCli({"run", crushScene(), "--stop-on-divergence", "--watch-off",
                                "escape", "--watch-penetration", "2.5"});
    VERIFY_EXIT(wide, 0);
    QVERIFY2(!wide.out.contains("diverged"), qPrintable(wide.describe()));
  }

  void watchSilentOnCorrectRuns_data() {
    QTest::addColumn<QString>("method");
    QTest::newRow("exact") << "exact";
    QTest::newRow("swept") << "swept";
  }
  void watchSilentOnCorrectRuns() {
    QFETCH(QString, method);
    const CliRun run = runCli({"run", magicRoom(), "--method", method, "--duration", "20",
                               "--stop-on-divergence", "--json"});
    VERIFY_EXIT(run, 0);
    const QJsonObject report = QJsonDocument::fromJson(run.out).object();
    QVERIFY2(report.contains("divergence") && report["divergence"].isNull(),
             qPrintable(run.describe()));
    // Without the option the report has no such key.
    const CliRun plain = runCli({"run", magicRoom(), "--duration", "1", "--json"});
    VERIFY_EXIT(plain, 0);
    QVERIFY(!QJsonDocument::fromJson(plain.out).object().contains("divergence"));
  }

  void nonRegularFileIsRefused_data() {
    QTest::addColumn<QString>("command");
    QTest::newRow("validate") << "validate";
    QTest::newRow("run") << "run";
  }
  void nonRegularFileIsRefused() {
    QFETCH(QString, command);
    const QString fifo = dir_.filePath(rowFileName() + ".fifo");
    QVERIFY(::mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
    const CliRun run = runCli({command, fifo}, 10000);
    VERIFY_REFUSED(run);
    QVERIFY2(run.err.contains(fifo.toUtf8() + ": not a regular file"), qPrintable(run.describe()));
    const CliRun device = runCli({command, "/dev/null"}, 10000);
    VERIFY_REFUSED(device);
    QVERIFY2(device.err.contains("/dev/null: not a regular file"), qPrintable(device.describe()));
  }

  // --- issue 33: no lost work under faults ---

  // `--trajectory x.json` on the scene x.json replaced the scene with CSV and exited 0.
  void trajectoryThatIsTheSceneIsRefused() {
    const QByteArray text = fileBytes(magicRoom());
    const QString scene = writeFile("own-trajectory.json", text);
    const QString link = dir_.filePath("own-trajectory-link.json");
    const QString hardLink = dir_.filePath("own-trajectory-hard.json");
    QVERIFY(QFile::link(scene, link));
    QCOMPARE(::link(QFile::encodeName(scene).constData(), QFile::encodeName(hardLink).constData()),
             0);
    for (const QString& output : {scene, link, hardLink}) {
      const CliRun run = runCli({"run", scene, "--duration", "0.1", "--trajectory", output});
      VERIFY_REFUSED(run);
      QVERIFY2(run.err.contains("is the scene file"), qPrintable(run.describe()));
      QCOMPARE(fileBytes(scene), text);
    }
  }

  // On a full disk the trajectory fails with the reason, leaves no partial file and keeps the
  // one that was there; with room it is written whole.
  void trajectoryOnAFullDisk() {
    SmallFilesystem disk(200 * 1024);
    if (!disk.mounted()) QSKIP(qPrintable(disk.error()));
    const QString kept = disk.filePath("kept.csv");
    const QString fresh = disk.filePath("fresh.csv");
    {
      QFile file(kept);
      QVERIFY(file.open(QIODevice::WriteOnly));
      QCOMPARE(file.write("old\n"), qint64(4));
    }
    QVERIFY(disk.fill(4096));
    for (const QString& csv : {kept, fresh}) {
      const CliRun run = runCli({"run", magicRoom(), "--duration", "2", "--trajectory", csv});
      VERIFY_EXIT(run, 1);
      QVERIFY2(run.err.contains("No space left on device"), qPrintable(run.describe()));
      QVERIFY2(!run.err.contains("Unknown error"), qPrintable(run.describe()));
    }
    QCOMPARE(fileBytes(kept), QByteArray("old\n"));
    QVERIFY(!QFileInfo::exists(fresh));
    QCOMPARE(QDir(disk.path()).entryList(QDir::Files), QStringList{"kept.csv"});
    QVERIFY(disk.unfill());
    const CliRun run = runCli({"run", magicRoom(), "--duration", "2", "--trajectory", kept});
    VERIFY_EXIT(run, 0);
    QVERIFY(fileBytes(kept).startsWith("time,ball,"));
  }

  // A name in Latin-1 bytes was "No such file or directory", and a trajectory so named was
  // written under another name. The shell passes the bytes as a user's would.
  void fileNamesInLatin1() {
    const QByteArray folder = QFile::encodeName(dir_.path());
    const QByteArray scene = folder + "/lat\xe9.json";
    QVERIFY(QFile::copy(magicRoom(), QFile::decodeName(folder + "/latin1-source.json")));
    QCOMPARE(::rename((folder + "/latin1-source.json").constData(), scene.constData()), 0);
    const auto runRaw = [&](const QByteArray& command) {
      QProcess shell;
      shell.setProgram("/bin/sh");
      // $1 is the program, the rest is printf'd bytes: \351 is é in Latin-1.
      shell.setArguments(
          {"-c", QString::fromLatin1(command), "sh", CAROM_CLI_PATH, QFile::decodeName(folder)});
      shell.start();
      shell.waitForFinished(kTimeoutMs);
      return std::make_pair(shell.exitCode(),
                            shell.readAllStandardOutput() + shell.readAllStandardError());
    };
    auto [validated, said] = runRaw(R"sh("$1" validate "$2/$(printf 'lat\351.json')")sh");
    QCOMPARE(validated, 0);
    QCOMPARE(said, QByteArray("ok\n"));
    auto [ran, report] = runRaw(
        R"sh("$1" run "$2/$(printf 'lat\351.json')" --duration 0.1 --trajectory "$2/$(printf 'tr\351.csv')")sh");
    QVERIFY2(ran == 0, report.constData());
    QCOMPARE(::access((folder + "/tr\xe9.csv").constData(), R_OK), 0);
    QVERIFY(!QFileInfo::exists(dir_.filePath(QString::fromUtf8("tr\uFFFD.csv"))));
  }

  // The loader mapped the file: cut short under it, the process died of SIGBUS. Cut at several
  // moments of a validation, it now always answers.
  void aFileThatShrinksWhileItIsValidated() {
    QByteArray text = sceneText("\"balls\": [");
    text.chop(2);  // "}\n"
    for (int i = 0; i < 300'000; ++i)
      text += QString("%1{\"position\": [%2, %3, %4], \"radius\": 0.01}")
                  .arg(i ? ", " : "")
                  .arg(0.1 * (i % 100))
                  .arg(0.1 * ((i / 100) % 100))
                  .arg(0.1 * (i / 10'000))
                  .toUtf8();
    text += "]}\n";
    const QString scene = dir_.filePath("shrinking.json");
    for (int delayMs : {0, 5, 20, 60, 150, 400}) {
      QVERIFY(!writeFile("shrinking.json", text).isEmpty());
      QProcess process;
      process.setProgram(QStringLiteral(CAROM_CLI_PATH));
      process.setArguments({"validate", scene});
      process.setStandardInputFile(QProcess::nullDevice());
      process.start();
      QVERIFY(process.waitForStarted());
      QThread::msleep(delayMs);
      QVERIFY(QFile::resize(scene, 1000));
      QVERIFY(process.waitForFinished(kTimeoutMs));
      const QByteArray err = process.readAllStandardError();
      QVERIFY2(process.exitStatus() == QProcess::NormalExit,
               qPrintable(QString("crashed after %1 ms: %2").arg(delayMs).arg(QString(err))));
      QVERIFY2(process.exitCode() == 0 ||
                   (process.exitCode() == 2 && err.startsWith(scene.toUtf8() + ": ")),
               err.constData());
    }
  }

  // Under a memory limit the load ran out and aborted with std::bad_alloc (SIGABRT).
  void runningOutOfMemoryIsAMessage() {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    QSKIP("the sanitizers reserve more address space than the limit allows");
#else
    QByteArray text = sceneText("\"balls\": [");
    text.chop(2);
    for (int i = 0; i < 400'000; ++i)
      text += QString("%1{\"position\": [%2, %3, %4], \"radius\": 0.01, \"name\": \"ball %5\"}")
                  .arg(i ? ", " : "")
                  .arg(0.1 * (i % 100))
                  .arg(0.1 * ((i / 100) % 100))
                  .arg(0.1 * (i / 10'000))
                  .arg(i)
                  .toUtf8();
    text += "]}\n";
    const QString scene = writeFile("memory.json", text);
    QVERIFY(!scene.isEmpty());
    // Room for the program and the file, not for the scene built from it.
    const rlim_t limit = rlim_t(QFileInfo(scene).size()) + (rlim_t(160) << 20);
    QProcess process;
    process.setProgram(QStringLiteral(CAROM_CLI_PATH));
    process.setArguments({"run", scene, "--duration", "0"});
    process.setStandardInputFile(QProcess::nullDevice());
    process.setChildProcessModifier([limit] {
      const struct rlimit memory { limit, limit };
      ::setrlimit(RLIMIT_AS, &memory);
    });
    process.start();
    QVERIFY(process.waitForFinished(kTimeoutMs));
    const QByteArray err = process.readAllStandardError();
    QVERIFY2(process.exitStatus() == QProcess::NormalExit, err.constData());
    QVERIFY2(process.exitCode() != 0, err.constData());
    QVERIFY2(err.contains("not enough memory"), err.constData());
#endif
  }
};

QTEST_GUILESS_MAIN(TestCli)
#include "test_cli.moc"
