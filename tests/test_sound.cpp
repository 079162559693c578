// The collision sounds (SoundBoard, and the window's SoundThread with its player process)
// against a real (null-sink) PulseAudio server: run under scripts/with-pulseaudio.sh.

#include "ui/run/simulation_snapshot.h"
#include "ui/sound/sound_board.h"
#include "ui/sound_thread.h"
#include "ui/status_readout.h"

#include <QApplication>
#include <QProcess>
#include <QSignalSpy>
#include <QtTest>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>

using carom::CollisionRecord;
using carom::ContactKind;
using carom::sound::SoundBoard;

namespace {

CollisionRecord hit(ContactKind kind, double speed) {
  CollisionRecord c;
  c.kind = kind;
  c.normalSpeed = speed;
  return c;
}

// Records the null sink's monitor with parec: what the sound server actually mixed.
class Recorder {
 public:
  bool start() {
    parec_.setProgram(QStringLiteral("parec"));
    parec_.setArguments({"-d", "ci.monitor", "--format=s16le", "--rate=44100", "--channels=1",
                         "--raw", "--latency-msec=20"});
    parec_.start();
    if (!parec_.waitForStarted(5000)) return false;
    // The stream is connected once the first samples arrive (the idle null sink still sends
    // silence); sounds played before then would be missed.
    QElapsedTimer waited;
    waited.start();
    while (bytes() < 4410 && waited.elapsed() < 10000) QTest::qWait(10);
    return bytes() >= 4410;
  }
  qsizetype bytes() {
    data_ += parec_.readAllStandardOutput();
    return data_.size();
  }
  int peak() {
    bytes();
    int top = 0;
    for (qsizetype i = 0; i + 1 < data_.size(); i += 2) {
      std::int16_t s;
      std::memcpy(&s, data_.constData() + i, 2);
      top = std::max(top, std::abs(static_cast<int>(s)));
    }
    return top;
  }
  // Sounds heard: runs of loud samples, each after at least `quietSamples` of quiet.
  int onsets(int loud, qsizetype quietSamples) {
    bytes();
    int count = 0;
    qsizetype quiet = quietSamples;
    for (qsizetype i = 0; i + 1 < data_.size(); i += 2) {
      std::int16_t s;
      std::memcpy(&s, data_.constData() + i, 2);
      if (std::abs(static_cast<int>(s)) > loud) {
        if (quiet >= quietSamples) ++count;
        quiet = 0;
      } else {
        ++quiet;
      }
    }
    return count;
  }
  void stop() {
    bytes();
    parec_.terminate();
    if (!parec_.waitForFinished(3000)) parec_.kill();
    data_ += parec_.readAllStandardOutput();
  }
  ~Recorder() {
    if (parec_.state() != QProcess::NotRunning) stop();
  }

 private:
  QProcess parec_;
  QByteArray data_;
};

// Well above dither or rounding noise, well below a sound played at even a tenth of volume.
constexpr int kSilencePeak = 200;
constexpr int kSoundPeak = 1000;

// This test's own server, through scripts/with-pulseaudio.sh: "--kill" takes it away as a crash
// would, "--start" brings it back on the same socket with the same null sink.
bool controlServer(const char* command) {
  const QString control = qEnvironmentVariable("CAROM_PULSE_CONTROL");
  const QString dir = qEnvironmentVariable("CAROM_PULSE_DIR");
  if (control.isEmpty() || dir.isEmpty()) return false;
  return QProcess::execute(control, {QString::fromLatin1(command), dir}) == 0;
}

// carom-sound, as the window starts it: its input stays open until closed.
void startPlayer(QProcess& player) {
  player.setProgram(QDir(QCoreApplication::applicationDirPath())
                        .absoluteFilePath(QStringLiteral(CAROM_SOUND_PLAYER_FROM_BINDIR)));
  player.setProcessChannelMode(QProcess::SeparateChannels);
  player.start();
}

// The player's next line, waiting for it at most `ms`; empty if none came.
QByteArray nextLine(QProcess& player, int ms = 5000) {
  QElapsedTimer waited;
  waited.start();
  while (!player.canReadLine() && waited.elapsed() < ms) player.waitForReadyRead(100);
  return player.canReadLine() ? player.readLine().trimmed() : QByteArray();
}

// Restarts the server when a test that killed it ends early, so the tests after it have one.
class ServerBack {
 public:
  ~ServerBack() {
    if (killed) controlServer("--start");
  }
  bool killed = false;
};

}  // namespace

class TestSound : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    if (qEnvironmentVariableIsSet("CAROM_SOUND_CHILD")) return;
    QVERIFY2(qEnvironmentVariableIsSet("PULSE_SERVER"),
             "run under scripts/with-pulseaudio.sh, which provides the null sink 'ci'");
  }

  void volumeRisesWithImpactSpeed() {
    const double ref = 2.0;
    QCOMPARE(carom::sound::volumeForSpeed(0.0, ref), 0.0);
    QCOMPARE(carom::sound::volumeForSpeed(-1.0, ref), 0.0);
    QCOMPARE(carom::sound::volumeForSpeed(std::nan(""), ref), 0.0);
    QCOMPARE(carom::sound::volumeForSpeed(ref, ref), 0.5);
    double previous = 0.0;
    for (double speed : {0.01, 0.1, 0.5, 1.0, 2.0, 5.0, 20.0, 1e6}) {
      const double v = carom::sound::volumeForSpeed(speed, ref);
      QVERIFY2(v > previous, qPrintable(QString("not louder at %1 m/s").arg(speed)));
      QVERIFY(v <= 1.0);
      previous = v;
    }
    // A larger reference makes the same impact quieter.
    QVERIFY(carom::sound::volumeForSpeed(1.0, 4.0) < carom::sound::volumeForSpeed(1.0, 1.0));
  }

  // Once both sounds are loaded, which takes a turn of the event loop.
  void availableWithServer() {
    SoundBoard board;
    QSignalSpy changed(&board, &SoundBoard::availabilityChanged);
    QTRY_VERIFY(board.available());
    QVERIFY(!board.failed());
    QCOMPARE(changed.count(), 1);
  }

  void silentWithoutPlay() {
    SoundBoard board;
    Recorder recorder;
    QVERIFY(recorder.start());
    QTest::qWait(1000);
    recorder.stop();
    QVERIFY2(recorder.peak() <= kSilencePeak, qPrintable(QString::number(recorder.peak())));
    QCOMPARE(board.playedCount(), 0);
  }

  void playReachesTheServer() {
    SoundBoard board;
    QTRY_VERIFY(board.available());
    Recorder recorder;
    QVERIFY(recorder.start());
    board.play({hit(ContactKind::BallBall, 4.0), hit(ContactKind::BallPlane, 3.0)});
    QCOMPARE(board.playedCount(), 2);
    QCOMPARE(board.droppedCount(), 0);
    QTRY_VERIFY_WITH_TIMEOUT(recorder.peak() > kSoundPeak, 5000);
    QTest::qWait(500);  // the rest of both sounds, for the peak in the log
    recorder.stop();
    qInfo("recorded peak %d of 32767", recorder.peak());
  }

  // One clack at a known volume arrives whole: not clipped, and with its attack (the loudest
  // part, which a fresh PulseAudio stream tends to swallow) intact.
  void clackArrivesAtItsVolume() {
    QFile wav(QStringLiteral(":/sounds/ball-ball.wav"));
    QVERIFY(wav.open(QIODevice::ReadOnly));
    const QByteArray pcm = wav.readAll().mid(44);  // 16-bit mono PCM after a plain header
    int filePeak = 0;
    for (qsizetype i = 0; i + 1 < pcm.size(); i += 2) {
      std::int16_t s;
      std::memcpy(&s, pcm.constData() + i, 2);
      filePeak = std::max(filePeak, std::abs(static_cast<int>(s)));
    }
    QVERIFY(filePeak > 10000);

    SoundBoard board;
    QTRY_VERIFY(board.available());
    const double speed = board.settings().referenceSpeed;
    const double expected = filePeak * board.settings().masterVolume *
                            carom::sound::volumeForSpeed(speed, board.settings().referenceSpeed);
    Recorder recorder;
    QVERIFY(recorder.start());
    board.play({hit(ContactKind::BallBall, speed)});
    QTRY_VERIFY_WITH_TIMEOUT(recorder.peak() > kSoundPeak, 5000);
    QTest::qWait(500);
    recorder.stop();
    qInfo("clack peak %d, expected %.0f", recorder.peak(), expected);
    QVERIFY(recorder.peak() > 0.7 * expected);
    QVERIFY(recorder.peak() < 1.1 * expected);
  }

  // A QSoundEffect of Qt 6.4 reused for one sound after another went silent after five plays;
  // each of twelve, on a single voice, is heard once (and the looping voice does not come round
  // again).
  void everySoundOfALongRunIsHeard() {
    SoundBoard::Settings settings;
    settings.voicesPerSound = 1;
    SoundBoard board(settings);
    QTRY_VERIFY(board.available());
    Recorder recorder;
    QVERIFY(recorder.start());
    constexpr int kPlays = 12;
    for (int k = 0; k < kPlays; ++k) {
      board.play({hit(ContactKind::BallBall, 4.0)});
      QTest::qWait(600);  // the voice is free again after 300 ms
    }
    QTest::qWait(500);
    recorder.stop();
    QCOMPARE(board.playedCount(), kPlays);
    // A clack is 80 ms long; 150 ms of quiet separates two.
    QCOMPARE(recorder.onsets(kSoundPeak, 44100 * 150 / 1000), kPlays);
  }

  // As the window plays them: from the GUI thread, posted to the sound thread, which hands them
  // to the player process while the GUI thread is busy elsewhere.
  void soundThreadPlaysWhileTheGuiIsBusy() {
    carom::ui::SoundThread sound;
    QTRY_VERIFY_WITH_TIMEOUT(sound.available(), 10000);  // once its player can play
    QVERIFY(!sound.muted());
    Recorder recorder;
    QVERIFY(recorder.start());
    sound.play({hit(ContactKind::BallBall, 4.0)});
    // The GUI thread blocks for half a second, as a very long frame would, without turning its
    // event loop: the sound has started all the same, and is fed.
    QThread::msleep(500);
    QCOMPARE(sound.playedCount(), 1);
    QTest::qWait(500);
    recorder.stop();
    QVERIFY2(recorder.peak() > kSoundPeak, qPrintable(QString::number(recorder.peak())));
    // Muted: nothing more starts, and the drop is not counted as played.
    sound.setMuted(true);
    QVERIFY(sound.muted());
    sound.play({hit(ContactKind::BallPlane, 4.0)});
    QTest::qWait(300);
    QCOMPARE(sound.playedCount(), 1);
  }

  void mutedPlaysNothing() {
    carom::ui::SoundThread sound;
    QTRY_VERIFY_WITH_TIMEOUT(sound.available(), 10000);
    sound.setMuted(true);
    Recorder recorder;
    QVERIFY(recorder.start());
    sound.play({hit(ContactKind::BallBall, 4.0), hit(ContactKind::BallCylinder, 3.0)});
    QTest::qWait(1000);
    recorder.stop();
    QCOMPARE(sound.playedCount(), 0);
    QCOMPARE(sound.droppedCount(), 0);
    QVERIFY2(recorder.peak() <= kSilencePeak, qPrintable(QString::number(recorder.peak())));
  }

  void thousandInOneFrameAreLimited() {
    SoundBoard board;
    QTRY_VERIFY(board.available());
    std::vector<CollisionRecord> frame;
    for (int i = 0; i < 1000; ++i)
      frame.push_back(hit(i % 3 == 0 ? ContactKind::BallBall : ContactKind::BallPlane, 1.0 + i));
    board.play(frame);
    QVERIFY(board.playedCount() >= 1);
    QVERIFY(board.playedCount() <= board.settings().maxPerSecond);
    QCOMPARE(board.playedCount() + board.droppedCount(), 1000);
  }

  void rateLimitOverTime() {
    SoundBoard::Settings settings;
    settings.maxPerSecond = 30;
    settings.minimumGapMs = 15;
    settings.voicesPerSound = 40;  // enough that voices never run out before the limit
    SoundBoard board(settings);
    QTRY_VERIFY(board.available());
    // One collision a millisecond for a second of board time, alternating kinds.
    for (int t = 0; t < 1000; ++t)
      board.playAt({hit(t % 2 ? ContactKind::BallBall : ContactKind::BallPlane, 2.0)}, t);
    QCOMPARE(board.playedCount(), 30);
    QCOMPARE(board.droppedCount(), 970);
    // The window slides: a second later there is room again.
    board.playAt({hit(ContactKind::BallBall, 2.0)}, 2500);
    QCOMPARE(board.playedCount(), 31);
  }

  void sameSoundKeepsAGap() {
    SoundBoard board;
    QTRY_VERIFY(board.available());
    board.playAt({hit(ContactKind::BallBall, 2.0)}, 100);
    board.playAt({hit(ContactKind::BallBall, 2.0)}, 105);   // too soon after the last clack
    board.playAt({hit(ContactKind::BallPlane, 2.0)}, 106);  // another sound: allowed
    QCOMPARE(board.playedCount(), 2);
    QCOMPARE(board.droppedCount(), 1);
    board.playAt({hit(ContactKind::BallBall, 2.0)}, 100 + board.settings().minimumGapMs);
    QCOMPARE(board.playedCount(), 3);
  }

  void tooSoftIsSilent() {
    SoundBoard board;
    QTRY_VERIFY(board.available());
    board.play({hit(ContactKind::BallBall, board.settings().minimumSpeed / 2)});
    QCOMPARE(board.playedCount(), 0);
    QCOMPARE(board.droppedCount(), 1);
  }

  // The player process on its own: ready, an answer with its totals to each frame, a clear
  // message and no answer for a line that is not one, and an exit once its input ends.
  void playerAnswersFrames() {
    QProcess player;
    startPlayer(player);
    QVERIFY2(player.waitForStarted(5000), qPrintable(player.program()));
    QCOMPARE(nextLine(player), QByteArray("ready"));
    player.write("hits 1 4 0 0\n");
    QCOMPARE(nextLine(player), QByteArray("counts 1 0"));
    player.write("hits 1 nan 0 0\nnoise\nhits 0 0 3 2\n");
    QCOMPARE(nextLine(player), QByteArray("counts 2 2"));
    player.closeWriteChannel();
    QVERIFY(player.waitForFinished(5000));
    const QByteArray errors = player.readAllStandardError();
    QVERIFY2(player.exitStatus() == QProcess::NormalExit, errors.constData());
    QCOMPARE(player.exitCode(), 0);
    QVERIFY2(errors.contains("carom-sound: not a frame: hits 1 nan 0 0") &&
                 errors.contains("carom-sound: not a frame: noise"),
             errors.constData());
  }

  // A sound whose stream cannot open is not counted as played: the server is killed and the
  // board asked to play before its event loop has turned, so before the watch on the
  // connection could say anything. The board then says it has failed, for good.
  void aSoundWithNoServerIsNotCounted() {
    SoundBoard board;
    QTRY_VERIFY(board.available());
    board.play({hit(ContactKind::BallBall, 4.0)});
    QCOMPARE(board.playedCount(), 1);
    QSignalSpy failure(&board, &SoundBoard::failure);
    ServerBack server;
    QVERIFY(controlServer("--kill"));
    server.killed = true;
    QThread::msleep(100);  // for Qt's connection to see its end, without this thread's events
    QVERIFY(board.available());
    board.play({hit(ContactKind::BallPlane, 4.0)});
    QCOMPARE(board.playedCount(), 1);
    QVERIFY(!board.available());
    QVERIFY(board.failed());
    QCOMPARE(failure.count(), 1);
    QVERIFY(controlServer("--start"));
    server.killed = false;
  }

  // The sound server goes away for longer than Qt 6.4 waits before its one attempt to reconnect
  // (3 s), while the window keeps sending frames, and comes back: the status line says there is
  // no sound (also with the simulation paused, no snapshot coming), nothing is counted as
  // played meanwhile, and sound plays again once the server is back. (This process's own Qt
  // audio is left without a server for good: the tests after this one play none in-process.)
  void soundComesBackWithTheServer() {
    carom::ui::SoundThread sound;
    carom::ui::StatusReadout status(&sound);
    status.showSnapshot(std::make_shared<const carom::ui::SimulationSnapshot>());
    const auto saysNoSound = [&status] { return status.text().contains("sound unavailable"); };
    QTRY_VERIFY_WITH_TIMEOUT(sound.available(), 10000);
    QTRY_VERIFY(!status.text().isEmpty() && !saysNoSound());
    {
      Recorder recorder;
      QVERIFY(recorder.start());
      sound.play({hit(ContactKind::BallBall, 4.0)});
      QTRY_VERIFY_WITH_TIMEOUT(recorder.peak() > kSoundPeak, 5000);
    }
    QTRY_COMPARE(sound.playedCount(), 1);

    ServerBack server;
    QVERIFY(controlServer("--kill"));
    server.killed = true;
    // Said while nothing plays, not only at the next collision.
    QTRY_VERIFY_WITH_TIMEOUT(!sound.available(), 5000);
    QTRY_VERIFY(saysNoSound());
    constexpr int kServerDownMs = 8000;
    QElapsedTimer down;
    down.start();
    while (down.elapsed() < kServerDownMs) {
      sound.play({hit(ContactKind::BallBall, 4.0), hit(ContactKind::BallPlane, 4.0)});
      QTest::qWait(100);
      QVERIFY(!sound.available());
    }
    QCOMPARE(sound.playedCount(), 1);

    QVERIFY(controlServer("--start"));
    server.killed = false;
    QTRY_VERIFY_WITH_TIMEOUT(sound.available(), 15000);
    QTRY_VERIFY(!saysNoSound());
    Recorder recorder;
    QVERIFY(recorder.start());
    sound.play({hit(ContactKind::BallBall, 4.0)});
    QTRY_VERIFY_WITH_TIMEOUT(recorder.peak() > kSoundPeak, 5000);
    QTRY_COMPARE(sound.playedCount(), 2);
  }

  // The audio backend picks its server once per process, so the board without a server runs
  // in a child process: this same test program, running only noServerChild.
  void noServer() {
    QProcess child;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("CAROM_SOUND_CHILD", "1");
    env.insert("PULSE_SERVER", "unix:/nonexistent/carom-no-pulse/native");
    child.setProcessEnvironment(env);
    child.setProcessChannelMode(QProcess::MergedChannels);
    child.start(QCoreApplication::applicationFilePath(), {"noServerChild"});
    QVERIFY(child.waitForFinished(60000));
    const QByteArray out = child.readAll();
    QVERIFY2(child.exitStatus() == QProcess::NormalExit && child.exitCode() == 0, out.constData());
    QVERIFY2(out.contains("PASS   : TestSound::noServerChild()"), out.constData());
  }

  void noServerChild() {
    if (!qEnvironmentVariableIsSet("CAROM_SOUND_CHILD")) QSKIP("runs in noServer's child");
    SoundBoard board;
    QSignalSpy changed(&board, &SoundBoard::availabilityChanged);
    QVERIFY(!board.available());
    QVERIFY(board.failed());
    std::vector<CollisionRecord> frame(1000, hit(ContactKind::BallBall, 3.0));
    board.play(frame);
    // Nothing was attempted, not even counted: play() returned before touching any voice.
    QCOMPARE(board.playedCount(), 0);
    QCOMPARE(board.droppedCount(), 0);
    QTest::qWait(300);  // nor does it turn available once events are processed
    QVERIFY(!board.available());
    QCOMPARE(changed.count(), 0);

    // A player finds no output and exits at once, its input still open.
    QProcess player;
    startPlayer(player);
    QVERIFY(player.waitForFinished(5000));
    QCOMPARE(player.exitCode(), 0);
    QCOMPARE(player.readAllStandardOutput(), QByteArray());

    // The window's sound: its players find no output and exit, and it says so.
    carom::ui::SoundThread sound;
    QTest::qWait(2000);  // a first player and a few more
    QVERIFY(!sound.available());
    sound.play(frame);
    QTest::qWait(300);
    QCOMPARE(sound.playedCount(), 0);
    QCOMPARE(sound.droppedCount(), 0);
  }
};

// The status line is a QLabel: a QApplication, on the offscreen platform, so that the test needs
// no display.
int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  TestSound test;
  return QTest::qExec(&test, argc, argv);
}
#include "test_sound.moc"
