// File > Export Video in the window (Xvfb, Mesa's OpenGL): the frames replayed from the recorded
// run as PNGs and as an MP4 (checked with ffprobe), Cancel, refusals, and the menu's dialogs.

#include "sim/simulation.h"
#include "tests/editor_fixture.h"
#include "ui/dialogs/video_export.h"
#include "ui/language.h"
#include "ui/run/run_session.h"
#include "ui/run/video_frames.h"

#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QProcess>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <cmath>
#include <utility>

using carom::Vec3;
using carom::ui::VideoExport;
using carom::ui::VideoExportDialog;
using carom::ui::VideoSettings;

class TestVideoExport : public carom::testing::EditorFixture {
  Q_OBJECT

 private slots:
  // English, for its plural forms ("25 video frames").
  void initTestCase() { carom::ui::installTranslation(*QCoreApplication::instance(), "en"); }
  void init() { openWindow(); }
  void cleanup() { window_.reset(); }

  void framesAreTheRecordedOnesAtOrBefore();
  void pngFramesOfTheRecordedRun();
  void explosionsAreTheRunsCollisions();
  void mp4HasTheFramesAndDuration();
  void cancelStopsAndRemovesTheMp4();
  void cancelLeavesThePngsWritten();
  void badInputsAreRefused();
  void ffmpegFailingIsSaid();
  void menuPausesAsksAndExports();
  void mp4IsDisabledWithoutFfmpeg();

 private:
  // The floor scene's ball thrown sideways and up, so that every frame differs.
  void throwTheBall() {
    carom::Scene edited = document().scene();
    edited.balls[0].velocity = Vec3(2, 4, 0);
    QVERIFY(carom::testing::applyEdit(document(), edited, "throw").isEmpty());
  }
  // Runs past `time` of simulated time, then pauses and waits for the pause to be shown.
  void runPast(double time) {
    throwTheBall();
    window_->setRunning(true);
    QTRY_VERIFY_WITH_TIMEOUT(
        [&] {
          const auto latest = window_->simulation().latest();
          return latest && latest->latestTime > time;
        }(),
        30000);
    window_->setRunning(false);
    QTRY_VERIFY([&] {
      const auto latest = window_->simulation().latest();
      return latest && !latest->running;
    }());
  }
  VideoSettings settings(VideoSettings::Format format, const QString& path) {
    VideoSettings settings;
    settings.from = 0.0;
    settings.to = 1.0;
    settings.fps = 24;
    settings.size = QSize(320, 240);
    settings.format = format;
    settings.path = path;
    return settings;
  }
  // Waits for the export to end; its `ok` and text.
  std::pair<bool, QString> waitForEnd(QSignalSpy& finished) {
    [&] { QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, 120000); }();
    if (finished.isEmpty()) return {false, "never finished"};
    return {finished.at(0).at(0).toBool(), finished.at(0).at(1).toString()};
  }
  // Every frame of the stretch, made by the worker alone.
  std::vector<carom::ui::VideoFrame> replayFrames(double from, double to, int fps) {
    const int count = carom::ui::videoFrameCount(from, to, fps);
    auto queue = std::make_shared<carom::ui::VideoFrameQueue>(count);
    window_->simulation().controls().exportVideo(queue, from, to, fps);
    std::vector<carom::ui::VideoFrame> frames;
    // The caller counts the frames that came.
    (void)QTest::qWaitFor(
        [&] {
          for (carom::ui::VideoFrame& frame : queue->take()) frames.push_back(std::move(frame));
          return int(frames.size()) >= count;
        },
        30000);
    return frames;
  }
  // Exports the stretch as PNGs into `folder`; empty, or what went wrong.
  QString exportPngs(const QString& folder) {
    VideoExport& exporter = *videoExport(*window_);
    QSignalSpy finished(&exporter, &VideoExport::finished);
    const QString refused = exporter.start(settings(VideoSettings::Format::Png, folder));
    if (!refused.isEmpty()) return refused;
    const auto [ok, text] = waitForEnd(finished);
    return ok ? QString() : text;
  }
  static QStringList frameFiles(const QString& folder) {
    return QDir(folder).entryList({"frame_*.png"}, QDir::Files, QDir::Name);
  }
  static bool haveFfmpeg() {
    return !QStandardPaths::findExecutable("ffmpeg").isEmpty() &&
           !QStandardPaths::findExecutable("ffprobe").isEmpty();
  }
};

// The worker's part alone: for each video frame, the latest recorded frame at or before its
// moment (recorded frames end steps, so at most a step earlier), in order, and the live run
// and the frame shown left as they were.
void TestVideoExport::framesAreTheRecordedOnesAtOrBefore() {
  runPast(1.0);
  const auto before = window_->simulation().latest();
  const double dt = before->world.timeStep;
  const int fps = 24;
  const double from = 0.25, to = 0.9;
  const int count = carom::ui::videoFrameCount(from, to, fps);
  QCOMPARE(count, 16);  // 0.25 + 15/24 = 0.875 is the last not after 0.9
  QCOMPARE(carom::ui::videoFrameCount(0.0, 1.0, 24), 25);
  QCOMPARE(carom::ui::videoFrameCount(0.5, 0.5, 24), 1);
  auto queue = std::make_shared<carom::ui::VideoFrameQueue>(count);
  window_->simulation().controls().exportVideo(queue, from, to, fps);
  std::vector<carom::ui::VideoFrame> frames;
  QTRY_VERIFY_WITH_TIMEOUT(
      [&] {
        for (carom::ui::VideoFrame& frame : queue->take()) frames.push_back(std::move(frame));
        return int(frames.size()) >= count;
      }(),
      30000);
  QCOMPARE(int(frames.size()), count);
  QVERIFY(!queue->abandoned());
  for (int k = 0; k < count; ++k) {
    const carom::ui::VideoFrame& frame = frames[k];
    QCOMPARE(frame.index, k);
    QCOMPARE(frame.time, carom::ui::videoFrameTime(from, fps, k));
    const QString at =
        QString("frame %1 at %2 shows %3").arg(k).arg(frame.time).arg(frame.recordedTime);
    QVERIFY2(frame.recordedTime <= frame.time + 1e-9, qPrintable(at));
    QVERIFY2(frame.time - frame.recordedTime < dt + 1e-9, qPrintable(at));
    QCOMPARE(frame.positions.size(), std::size_t(1));
  }
  // The ball is thrown: it moves between frames.
  QVERIFY(frames.front().positions[0] != frames.back().positions[0]);
  // The live run was not disturbed.
  const auto after = window_->simulation().latest();
  QCOMPARE(after->frameCount, before->frameCount);
  QCOMPARE(after->frame, before->frame);
  QCOMPARE(after->latestTime, before->latestTime);
}

void TestVideoExport::pngFramesOfTheRecordedRun() {
  runPast(1.0);
  QTemporaryDir folder;
  const QString frames = folder.filePath("frames");  // made by the export
  VideoExport& exporter = *videoExport(*window_);
  QSignalSpy finished(&exporter, &VideoExport::finished);
  QSignalSpy progressed(&exporter, &VideoExport::progressed);
  QCOMPARE(exporter.start(settings(VideoSettings::Format::Png, frames)), QString());
  QVERIFY(exporter.busy());
  QVERIFY(exporter.progressDialog());
  const auto [ok, text] = waitForEnd(finished);
  QVERIFY2(ok, qPrintable(text));
  QVERIFY(!exporter.busy());
  QVERIFY2(text.startsWith("Exported 25 video frames of 320×240 at 24 fps"), qPrintable(text));
  QCOMPARE(statusMessage(*window_), text);
  QCOMPARE(progressed.count(), 25);
  QCOMPARE(progressed.last().at(0).toInt(), 25);
  const QStringList files = frameFiles(frames);
  QCOMPARE(files.size(), 25);
  QCOMPARE(files.first(), QString("frame_000001.png"));
  QCOMPARE(files.last(), QString("frame_000025.png"));
  const QImage first(QDir(frames).filePath(files.first()));
  const QImage last(QDir(frames).filePath(files.last()));
  QCOMPARE(first.size(), QSize(320, 240));
  QCOMPARE(last.size(), QSize(320, 240));
  QVERIFY(first.convertToFormat(QImage::Format_RGB32) !=
          last.convertToFormat(QImage::Format_RGB32));
  // The same folder again would mix two exports' frames: refused, nothing written.
  const QString again = exporter.start(settings(VideoSettings::Format::Png, frames));
  QVERIFY2(again.contains("already holds frames"), qPrintable(again));
  QVERIFY(!exporter.busy());
}

// The frames carry the replay's collisions, each once, and the video draws their explosions:
// frames before the first collision are the same with View > Explosions off, frames while its
// explosion lives are not.
void TestVideoExport::explosionsAreTheRunsCollisions() {
  runPast(1.0);
  const std::vector<carom::ui::VideoFrame> frames = replayFrames(0.0, 1.0, 24);
  QCOMPARE(frames.size(), std::size_t(25));
  std::vector<carom::CollisionRecord> shown;
  for (const carom::ui::VideoFrame& frame : frames)
    for (const carom::CollisionRecord& collision : frame.collisions) {
      QVERIFY(collision.time <= frame.recordedTime);
      shown.push_back(collision);
    }
  carom::Simulation fresh(document().scene());
  fresh.setCollisionLog(true);
  while (fresh.time() < frames.back().recordedTime) fresh.step();
  const std::vector<carom::CollisionRecord> expected = fresh.takeCollisions();
  // Thrown up at 4 m/s, the ball lands once, after 2·4/9.81 s.
  QVERIFY(!expected.empty());
  QCOMPARE(shown.size(), expected.size());
  for (std::size_t i = 0; i < shown.size(); ++i) {
    QCOMPARE(shown[i].time, expected[i].time);
    QCOMPARE(shown[i].ball, expected[i].ball);
    QCOMPARE(shown[i].other, expected[i].other);
    QCOMPARE(shown[i].point, expected[i].point);
  }
  const double landing = expected.front().time;
  QVERIFY2(std::abs(landing - 2 * 4 / 9.81) < 0.01, qPrintable(QString::number(landing)));

  QTemporaryDir folder;
  const QString with = folder.filePath("with"), without = folder.filePath("without");
  QCOMPARE(exportPngs(with), QString());
  view().setExplosionsEnabled(false);
  QCOMPARE(exportPngs(without), QString());
  const QStringList files = frameFiles(with);
  QCOMPARE(files.size(), 25);
  QCOMPARE(frameFiles(without), files);
  const double step = currentSnapshot()->world.timeStep;
  int differing = 0;
  for (int k = 0; k < files.size(); ++k) {
    const double moment = k / 24.0;
    const QImage a = QImage(QDir(with).filePath(files[k])).convertToFormat(QImage::Format_RGB32);
    const QImage b = QImage(QDir(without).filePath(files[k])).convertToFormat(QImage::Format_RGB32);
    const QString at = QString("frame %1 at %2 s").arg(k + 1).arg(moment);
    if (moment < landing) QVERIFY2(a == b, qPrintable(at));
    if (moment > landing + step) QVERIFY2(a != b, qPrintable(at));
    differing += a != b;
  }
  QVERIFY(differing > 0);
}

void TestVideoExport::mp4HasTheFramesAndDuration() {
  if (!haveFfmpeg()) QSKIP("ffmpeg and ffprobe are not installed (scripts/setup-debian.sh does)");
  runPast(1.0);
  QTemporaryDir folder;
  const QString file = folder.filePath("run.mp4");
  VideoExport& exporter = *videoExport(*window_);
  QSignalSpy finished(&exporter, &VideoExport::finished);
  QCOMPARE(exporter.start(settings(VideoSettings::Format::Mp4, file)), QString());
  const auto [ok, text] = waitForEnd(finished);
  QVERIFY2(ok, qPrintable(text));
  QVERIFY(QFileInfo(file).size() > 0);
  QProcess probe;
  probe.start("ffprobe", {"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                          "stream=nb_read_frames,width,height", "-show_entries", "format=duration",
                          "-of", "json", file});
  QVERIFY(probe.waitForFinished(60000));
  QCOMPARE(probe.exitCode(), 0);
  const QJsonObject json = QJsonDocument::fromJson(probe.readAllStandardOutput()).object();
  const QJsonObject stream = json["streams"].toArray().at(0).toObject();
  QCOMPARE(stream["width"].toInt(), 320);
  QCOMPARE(stream["height"].toInt(), 240);
  QCOMPARE(stream["nb_read_frames"].toString(), QString("25"));
  // 25 frames at 24 fps: 25/24 s.
  const double duration = json["format"].toObject()["duration"].toString().toDouble();
  QVERIFY2(std::abs(duration - 25.0 / 24.0) < 0.02, qPrintable(QString::number(duration)));
}

void TestVideoExport::cancelStopsAndRemovesTheMp4() {
  if (!haveFfmpeg()) QSKIP("ffmpeg and ffprobe are not installed (scripts/setup-debian.sh does)");
  runPast(1.0);
  QTemporaryDir folder;
  const QString file = folder.filePath("cancelled.mp4");
  VideoExport& exporter = *videoExport(*window_);
  QSignalSpy finished(&exporter, &VideoExport::finished);
  int seenAtCancel = -1;
  // Cancel as the user does, with the progress dialog's button, after three frames.
  QMetaObject::Connection canceller;
  canceller = connect(&exporter, &VideoExport::progressed, this, [&](int written, int) {
    if (written != 3) return;
    disconnect(canceller);
    QProgressDialog* progress = exporter.progressDialog();
    QVERIFY(progress);
    QPushButton* button = progress->findChild<QPushButton*>();
    QVERIFY(button);
    button->click();
    seenAtCancel = written;
  });
  QCOMPARE(exporter.start(settings(VideoSettings::Format::Mp4, file)), QString());
  QVERIFY(QFile::exists(file) || exporter.busy());
  const auto [ok, text] = waitForEnd(finished);
  QCOMPARE(seenAtCancel, 3);
  QVERIFY(!ok);
  QVERIFY2(text.contains("cancelled") && text.contains("removed"), qPrintable(text));
  QVERIFY(!exporter.busy());
  QCOMPARE(exporter.framesWritten(), 3);  // stopped at once, no frame after the click
  QVERIFY(!QFile::exists(file));
  QVERIFY(!exporter.progressDialog());
  // The window goes on: the run runs again, and another export works.
  const double stoppedAt = currentSnapshot()->latestTime;
  window_->setRunning(true);
  QTRY_VERIFY(currentSnapshot()->latestTime > stoppedAt);
  window_->setRunning(false);
  QSignalSpy again(&exporter, &VideoExport::finished);
  VideoSettings shorter = settings(VideoSettings::Format::Mp4, file);
  shorter.to = 0.25;
  QCOMPARE(exporter.start(shorter), QString());
  const auto [okAgain, textAgain] = waitForEnd(again);
  QVERIFY2(okAgain, qPrintable(textAgain));
  QVERIFY(QFile::exists(file));
}

void TestVideoExport::cancelLeavesThePngsWritten() {
  runPast(1.0);
  QTemporaryDir folder;
  VideoExport& exporter = *videoExport(*window_);
  QSignalSpy finished(&exporter, &VideoExport::finished);
  connect(&exporter, &VideoExport::progressed, this, [&](int written, int) {
    if (written == 2) exporter.cancel();
  });
  QCOMPARE(exporter.start(settings(VideoSettings::Format::Png, folder.path())), QString());
  const auto [ok, text] = waitForEnd(finished);
  QVERIFY(!ok);
  QVERIFY2(text.startsWith("Video export cancelled after 2 frames"), qPrintable(text));
  QCOMPARE(frameFiles(folder.path()).size(), 2);
}

void TestVideoExport::badInputsAreRefused() {
  runPast(0.3);
  const double latest = currentSnapshot()->latestTime;
  VideoSettings read;
  read.path = "kept";
  using Format = VideoSettings::Format;
  const auto refusal = [&](const char* from, const char* to, const char* fps, const char* width,
                           const char* height, Format format = Format::Png) {
    return VideoExportDialog::read(from, to, fps, width, height, format, latest, true, &read);
  };
  QVERIFY(refusal("x", "0.2", "30", "320", "240").startsWith("Start: must be a number"));
  QVERIFY(refusal("0", "inf", "30", "320", "240").startsWith("End: must be a number"));
  QVERIFY(refusal("-0.1", "0.2", "30", "320", "240").startsWith("Start: must not be before 0"));
  QVERIFY(refusal("0.2", "0.1", "30", "320", "240").startsWith("End: must not be before"));
  QVERIFY(refusal("0", "100", "30", "320", "240").startsWith("End: the run is recorded up to"));
  QVERIFY(refusal("0", "0.2", "0", "320", "240").startsWith("Frames per second: must be"));
  QVERIFY(refusal("0", "0.2", "241", "320", "240").contains("from 1 to 240"));
  QVERIFY(refusal("0", "0.2", "2.5", "320", "240").startsWith("Frames per second"));
  QVERIFY(refusal("0", "0.2", "30", "9000", "240").startsWith("Width: must be between"));
  QVERIFY(refusal("0", "0.2", "30", "321", "240", Format::Mp4).contains("must be even"));
  QVERIFY(VideoExportDialog::read("0", "0.2", "30", "320", "240", Format::Mp4, latest, false, &read)
              .contains("ffmpeg"));
  QCOMPARE(read.path, QString("kept"));  // unchanged by a refusal
  QCOMPARE(read.fps, 30);
  QCOMPARE(refusal(" 0.1", "0.2", "25", "321", "240"), QString());  // odd is fine for PNGs
  QCOMPARE(read.from, 0.1);
  QCOMPARE(read.to, 0.2);
  QCOMPARE(read.fps, 25);
  QCOMPARE(read.size, QSize(321, 240));
  QCOMPARE(read.path, QString("kept"));

  // Paths that cannot be written: refused before anything starts.
  VideoExport& exporter = *videoExport(*window_);
  QTemporaryDir folder;
  QFile blocker(folder.filePath("a-file"));
  QVERIFY(blocker.open(QIODevice::WriteOnly));
  blocker.close();
  VideoSettings bad = settings(Format::Png, folder.filePath("a-file/frames"));
  bad.to = 0.2;
  QVERIFY(exporter.start(bad).startsWith("Could not create the folder"));
  QVERIFY(!exporter.busy());
  bad.format = Format::Mp4;
  bad.path = folder.filePath("a-file/video.mp4");
  if (haveFfmpeg()) QVERIFY(exporter.start(bad).startsWith("Could not write"));
  bad.path = folder.filePath("video.mp4");
  bad.to = latest + 1.0;
  QVERIFY(exporter.start(bad).startsWith("End: the run is recorded up to"));
  QVERIFY(!exporter.busy());
  QVERIFY(!QFile::exists(bad.path));
  QCOMPARE(QDir(folder.path()).entryList(QDir::NoDotAndDotDot | QDir::AllEntries),
           QStringList{"a-file"});
}

// An ffmpeg that fails (a stand-in on the PATH that says why and exits): the export stops with
// what it said, and no video is left.
void TestVideoExport::ffmpegFailingIsSaid() {
  runPast(0.3);
  QTemporaryDir bin;
  QFile fake(bin.filePath("ffmpeg"));
  QVERIFY(fake.open(QIODevice::WriteOnly));
  fake.write("#!/bin/sh\necho 'fake encoder gave up' >&2\nexit 7\n");
  fake.close();
  fake.setPermissions(QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
  const QByteArray path = qgetenv("PATH");
  qputenv("PATH", bin.path().toLocal8Bit() + ":" + path);
  QCOMPARE(VideoExport::ffmpeg(), bin.filePath("ffmpeg"));
  QTemporaryDir folder;
  VideoSettings failing = settings(VideoSettings::Format::Mp4, folder.filePath("failed.mp4"));
  failing.to = 0.25;
  VideoExport& exporter = *videoExport(*window_);
  QSignalSpy finished(&exporter, &VideoExport::finished);
  const QString started = exporter.start(failing);
  qputenv("PATH", path);
  QCOMPARE(started, QString());
  const auto [ok, text] = waitForEnd(finished);
  QVERIFY(!ok);
  QVERIFY2(text.startsWith("ffmpeg failed (exit code 7): fake encoder gave up"), qPrintable(text));
  QCOMPARE(statusMessage(*window_), text);
  QVERIFY(!exporter.busy());
  QVERIFY(!QFile::exists(failing.path));
}

// The menu pauses a running simulation, offers the whole recorded run at 30 fps and the view's
// size, keeps the dialog open on a bad value, then asks for the folder and exports.
void TestVideoExport::menuPausesAsksAndExports() {
  throwTheBall();
  window_->setRunning(true);
  QTRY_VERIFY_WITH_TIMEOUT(currentSnapshot()->latestTime > 0.3, 30000);
  QTemporaryDir folder;
  QString refusal;
  QString offeredFrom, offeredTo, offeredFps;
  QSize offeredSize;
  double recordedThen = 0.0;
  carom::testing::ModalAnswerer<VideoExportDialog> settingsAnswer([&](VideoExportDialog* dialog) {
    const auto field = [&](const char* name) { return dialog->findChild<QLineEdit*>(name); };
    offeredFrom = field("videoFrom")->text();
    offeredTo = field("videoTo")->text();
    offeredFps = field("videoFps")->text();
    offeredSize = QSize(field("videoWidth")->text().toInt(), field("videoHeight")->text().toInt());
    recordedThen = currentSnapshot()->latestTime;
    field("videoFps")->setText("500");
    dialog->accept();  // refused: stays open and says why
    refusal = dialog->error();
    field("videoFps")->setText("10");
    field("videoTo")->setText("0.3");
    field("videoWidth")->setText("160");
    field("videoHeight")->setText("120");
    dialog->findChild<QComboBox*>("videoFormat")->setCurrentIndex(0);
    dialog->accept();
  });
  carom::testing::ModalAnswerer<QFileDialog> folderAnswer([&](QFileDialog* dialog) {
    dialog->setDirectory(folder.path());
    dialog->selectFile(folder.path());
    QMetaObject::invokeMethod(dialog, "accept");
  });
  QSignalSpy finished(videoExport(*window_), &VideoExport::finished);
  QAction* action = window_->findChild<QAction*>("exportVideo");
  QVERIFY(action);
  QCOMPARE(action->text(), QString("Export &Video…"));
  action->trigger();
  QTRY_VERIFY(settingsAnswer.answered() && folderAnswer.answered());
  const auto [ok, text] = waitForEnd(finished);
  QVERIFY2(ok, qPrintable(text));
  QCOMPARE(offeredFrom, QString("0"));
  QCOMPARE(offeredFps, QString("30"));
  QCOMPARE(offeredSize, view().size() * view().devicePixelRatio());
  QVERIFY2(offeredTo.toDouble() > 0.3 && offeredTo.toDouble() <= recordedThen + 1e-6,
           qPrintable(offeredTo));
  QVERIFY2(refusal.startsWith("Frames per second: must be a whole number from 1 to 240"),
           qPrintable(refusal));
  QVERIFY(!currentSnapshot()->running);  // paused by the export
  const QStringList files = frameFiles(folder.path());
  QCOMPARE(files.size(), 4);  // 0, 0.1, 0.2, 0.3
  QCOMPARE(QImage(QDir(folder.path()).filePath(files.first())).size(), QSize(160, 120));
}

// Without ffmpeg on the PATH the MP4 choice is greyed and a note says why.
void TestVideoExport::mp4IsDisabledWithoutFfmpeg() {
  const QByteArray path = qgetenv("PATH");
  qputenv("PATH", "/nonexistent");
  QVERIFY(VideoExport::ffmpeg().isEmpty());
  VideoSettings initial = settings(VideoSettings::Format::Mp4, {});
  VideoExportDialog dialog(initial, 1.0, !VideoExport::ffmpeg().isEmpty());
  qputenv("PATH", path);
  auto* format = dialog.findChild<QComboBox*>("videoFormat");
  QCOMPARE(format->currentIndex(), 0);  // PNG, though MP4 was asked
  auto* model = qobject_cast<QStandardItemModel*>(format->model());
  QVERIFY(model);
  QVERIFY(model->item(0)->isEnabled());
  QVERIFY(!model->item(1)->isEnabled());
  const QLabel* note = dialog.findChild<QLabel*>("videoNote");
  QVERIFY(note);
  QVERIFY2(note->text().contains("ffmpeg") && !note->isHidden(), qPrintable(note->text()));
}

QTEST_MAIN(TestVideoExport)
#include "test_video_export.moc"
