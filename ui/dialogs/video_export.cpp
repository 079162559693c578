#include "ui/dialogs/video_export.h"

#include "ui/dialogs/image_export.h"
#include "ui/editor/number_text.h"
#include "ui/run/run_session.h"
#include "ui/run/video_frames.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMessageBox>
#include <QProgressDialog>
#include <QSettings>
#include <QStandardItemModel>
#include <QStandardPaths>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace carom::ui {
namespace {

constexpr const char* kFolderKey = "export/videoFolder";
constexpr const char* kFpsKey = "export/videoFps";
constexpr const char* kFormatKey = "export/videoFormat";
// The end may be typed as shown, rounded a little past the newest recorded moment.
constexpr double kEndSlackSeconds = 1e-6;
// The GUI renders for about this long at a turn, then lets the window breathe.
constexpr qint64 kPumpMilliseconds = 40;
constexpr int kPumpIntervalMilliseconds = 5;
// ffmpeg reads at its own pace: no more than this waits in the pipe for it, or a single frame
// when that is larger.
constexpr qint64 kEncoderBacklogBytes = qint64(32) << 20;

// In the user's locale ("1,5" in German) or plainly, and finite.
bool readNumber(const QString& text, double* value) {
  bool ok = false;
  *value = QLocale().toDouble(text.trimmed(), &ok);
  if (!ok) *value = text.trimmed().toDouble(&ok);
  return ok && std::isfinite(*value);
}

bool readWhole(const QString& text, int* value) {
  bool ok = false;
  *value = QLocale().toInt(text.trimmed(), &ok);
  if (!ok) *value = text.trimmed().toInt(&ok);
  return ok;
}

QString seconds(double value) {
  return editor::formatNumber(value, 'g', 12);
}

}  // namespace

VideoExportDialog::VideoExportDialog(const VideoSettings& initial, double latestTime,
                                     bool ffmpegFound, QWidget* parent)
    : QDialog(parent),
      latestTime_(latestTime),
      ffmpegFound_(ffmpegFound),
      from_(new QLineEdit),
      to_(new QLineEdit),
      fps_(new QLineEdit),
      width_(new QLineEdit),
      height_(new QLineEdit),
      format_(new QComboBox),
      error_(new QLabel),
      chosen_(initial) {
  setObjectName("videoExportDialog");
  setWindowTitle(tr("Export Video"));
  from_->setObjectName("videoFrom");
  to_->setObjectName("videoTo");
  fps_->setObjectName("videoFps");
  width_->setObjectName("videoWidth");
  height_->setObjectName("videoHeight");
  format_->setObjectName("videoFormat");
  from_->setText(seconds(initial.from));
  to_->setText(seconds(initial.to));
  fps_->setText(QString::number(initial.fps));
  width_->setText(QString::number(initial.size.width()));
  height_->setText(QString::number(initial.size.height()));
  format_->addItem(tr("PNG images in a folder"));
  format_->addItem(tr("MP4 video (ffmpeg)"));
  format_->setCurrentIndex(initial.format == VideoSettings::Format::Mp4 && ffmpegFound ? 1 : 0);
  auto* recorded = new QLabel(tr("The run is recorded from 0 to %1 s. Each video frame shows "
                                 "the recorded step that ended at its moment or last before it.")
                                  .arg(seconds(latestTime)));
  recorded->setWordWrap(true);
  auto* note = new QLabel;
  note->setObjectName("videoNote");
  note->setWordWrap(true);
  if (!ffmpegFound) {
    // The choice stays in the list, greyed, so that the note has something to explain.
    if (auto* model = qobject_cast<QStandardItemModel*>(format_->model()))
      model->item(1)->setEnabled(false);
    note->setText(
        tr("MP4 needs ffmpeg, which was not found on the PATH (scripts/setup-debian.sh "
           "installs it); PNG images need nothing more."));
  } else {
    note->hide();
  }
  error_->setObjectName("videoError");
  error_->setWordWrap(true);
  error_->setStyleSheet("color: #d04040");
  error_->hide();
  auto* form = new QFormLayout;
  form->addRow(tr("Start (s)"), from_);
  form->addRow(tr("End (s)"), to_);
  form->addRow(tr("Frames per second"), fps_);
  form->addRow(tr("Width (pixels)"), width_);
  form->addRow(tr("Height (pixels)"), height_);
  form->addRow(tr("Format"), format_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  connect(buttons, &QDialogButtonBox::accepted, this, &VideoExportDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &VideoExportDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(recorded);
  layout->addLayout(form);
  layout->addWidget(note);
  layout->addWidget(error_);
  layout->addWidget(buttons);
}

QString VideoExportDialog::read(const QString& from, const QString& to, const QString& fps,
                                const QString& width, const QString& height,
                                VideoSettings::Format format, double latestTime, bool ffmpegFound,
                                VideoSettings* settings) {
  VideoSettings read = *settings;
  if (!readNumber(from, &read.from))
    return tr("Start: must be a number of seconds (got \"%1\")").arg(from);
  if (!readNumber(to, &read.to)) return tr("End: must be a number of seconds (got \"%1\")").arg(to);
  if (!readWhole(fps, &read.fps))
    return tr("Frames per second: must be a whole number from %1 to %2 (got \"%3\")")
        .arg(VideoSettings::kMinFps)
        .arg(VideoSettings::kMaxFps)
        .arg(fps);
  const QString sizeError = ImageSizeDialog::readSize(width, height, &read.size);
  if (!sizeError.isEmpty()) return sizeError;
  read.format = format;
  const QString error = VideoExport::check(read, latestTime, ffmpegFound);
  if (!error.isEmpty()) return error;
  *settings = read;
  return {};
}

QString VideoExportDialog::error() const {
  return error_->isVisible() ? error_->text() : QString();
}

void VideoExportDialog::accept() {
  const auto format =
      format_->currentIndex() == 1 ? VideoSettings::Format::Mp4 : VideoSettings::Format::Png;
  VideoSettings settings = chosen_;
  const QString error = read(from_->text(), to_->text(), fps_->text(), width_->text(),
                             height_->text(), format, latestTime_, ffmpegFound_, &settings);
  if (!error.isEmpty()) {
    // The dialog stays open with what was typed, to be corrected or cancelled.
    error_->setText(error);
    error_->show();
    return;
  }
  chosen_ = settings;
  QDialog::accept();
}

VideoExport::VideoExport(render::SceneView* view, RunSession* run, QWidget* dialogParent,
                         QObject* parent)
    : QObject(parent),
      view_(view),
      run_(run),
      dialogParent_(dialogParent),
      timer_(new QTimer(this)) {
  timer_->setInterval(kPumpIntervalMilliseconds);
  connect(timer_, &QTimer::timeout, this, &VideoExport::pump);
}

VideoExport::~VideoExport() {
  if (busy()) stop(true);
}

QString VideoExport::ffmpeg() {
  return QStandardPaths::findExecutable("ffmpeg");
}

QString VideoExport::check(const VideoSettings& settings, double latestTime, bool ffmpegFound) {
  if (!(settings.from >= 0.0))
    return tr("Start: must not be before 0 s (got %1 s)").arg(seconds(settings.from));
  if (!(settings.to >= settings.from))
    return tr("End: must not be before the start, %1 s (got %2 s)")
        .arg(seconds(settings.from), seconds(settings.to));
  if (settings.to > latestTime + kEndSlackSeconds)
    return tr("End: the run is recorded up to %1 s only (got %2 s)")
        .arg(seconds(latestTime), seconds(settings.to));
  if (settings.fps < VideoSettings::kMinFps || settings.fps > VideoSettings::kMaxFps)
    return tr("Frames per second: must be a whole number from %1 to %2 (got \"%3\")")
        .arg(VideoSettings::kMinFps)
        .arg(VideoSettings::kMaxFps)
        .arg(settings.fps);
  QSize size;
  const QString sizeError = ImageSizeDialog::readSize(
      QString::number(settings.size.width()), QString::number(settings.size.height()), &size);
  if (!sizeError.isEmpty()) return sizeError;
  if (settings.format == VideoSettings::Format::Mp4) {
    if (!ffmpegFound)
      return tr(
          "MP4 needs ffmpeg, which was not found on the PATH: choose PNG images, or "
          "install ffmpeg.");
    // H.264 in yuv420p, which every player reads, halves the colour resolution both ways.
    if (size.width() % 2 != 0 || size.height() % 2 != 0)
      return tr("MP4: the width and height must be even (got %1×%2)")
          .arg(size.width())
          .arg(size.height());
  }
  return {};
}

bool VideoExport::exportVideo() {
  if (busy()) return false;
  emit pauseRequested();
  const std::shared_ptr<const SimulationSnapshot> latest = run_->latest();
  const double latestTime = latest ? latest->latestTime : 0.0;
  const bool ffmpegFound = !ffmpeg().isEmpty();
  QSettings stored;
  VideoSettings initial;
  initial.to = latestTime;
  initial.fps = stored.value(kFpsKey, 30).toInt();
  if (initial.fps < VideoSettings::kMinFps || initial.fps > VideoSettings::kMaxFps)
    initial.fps = 30;
  const double ratio = view_->devicePixelRatioF();
  initial.size = QSize(static_cast<int>(std::lround(view_->width() * ratio)),
                       static_cast<int>(std::lround(view_->height() * ratio)));
  initial.format = stored.value(kFormatKey).toString() == "mp4" ? VideoSettings::Format::Mp4
                                                                : VideoSettings::Format::Png;
  VideoExportDialog dialog(initial, latestTime, ffmpegFound, dialogParent_);
  if (dialog.exec() != QDialog::Accepted) return false;
  VideoSettings chosen = dialog.chosen();
  const bool mp4 = chosen.format == VideoSettings::Format::Mp4;
  stored.setValue(kFpsKey, chosen.fps);
  stored.setValue(kFormatKey, mp4 ? "mp4" : "png");

  const QString folder =
      stored.value(kFolderKey, QStandardPaths::writableLocation(QStandardPaths::MoviesLocation))
          .toString();
  if (mp4) {
    QString file =
        QFileDialog::getSaveFileName(dialogParent_, tr("Export Video"),
                                     QDir(folder).filePath("carom.mp4"), tr("MP4 videos (*.mp4)"));
    if (file.isEmpty()) return false;
    if (QFileInfo(file).suffix().isEmpty()) file += ".mp4";
    stored.setValue(kFolderKey, QFileInfo(file).absolutePath());
    chosen.path = file;
  } else {
    const QString chosenFolder = QFileDialog::getExistingDirectory(
        dialogParent_, tr("Export Video: Folder for the Frames"), folder);
    if (chosenFolder.isEmpty()) return false;
    stored.setValue(kFolderKey, chosenFolder);
    chosen.path = chosenFolder;
  }
  const QString error = begin(chosen, true);
  if (!error.isEmpty()) {
    QMessageBox::warning(dialogParent_, tr("Cannot Export Video"), error);
    return false;
  }
  return true;
}

QString VideoExport::start(const VideoSettings& settings) {
  return begin(settings, false);
}

QString VideoExport::begin(const VideoSettings& settings, bool interactive) {
  if (busy()) return tr("A video is being exported already.");
  emit pauseRequested();
  const std::shared_ptr<const SimulationSnapshot> latest = run_->latest();
  if (!latest) return tr("There is no run to export yet.");
  const QString ffmpegPath = ffmpeg();
  const QString error = check(settings, latest->latestTime, !ffmpegPath.isEmpty());
  if (!error.isEmpty()) return error;
  const QString shownPath = QDir::toNativeSeparators(settings.path);
  if (settings.path.isEmpty()) return tr("No folder or file was chosen.");
  if (settings.format == VideoSettings::Format::Png) {
    if (!QDir().mkpath(settings.path) || !QFileInfo(settings.path).isDir())
      return tr("Could not create the folder %1.").arg(shownPath);
    if (!QFileInfo(settings.path).isWritable())
      return tr("Could not write into the folder %1.").arg(shownPath);
    // Frames of an earlier export would mix with these.
    if (!QDir(settings.path).entryList({"frame_*.png"}, QDir::Files).isEmpty())
      return tr("The folder %1 already holds frames (frame_*.png): choose another folder or "
                "remove them first.")
          .arg(shownPath);
  } else {
    const QFileInfo folder(QFileInfo(settings.path).absolutePath());
    if (!folder.isDir() || !folder.isWritable())
      return tr("Could not write %1: its folder does not exist or cannot be written.")
          .arg(shownPath);
    if (QFileInfo(settings.path).isDir())
      return tr("Could not write %1: it is a folder.").arg(shownPath);
  }

  settings_ = settings;
  total_ = videoFrameCount(settings.from, settings.to, settings.fps);
  written_ = 0;
  pending_.clear();
  nextPending_ = 0;
  // The view's camera and scene as they are now, without what belongs to the editor (handles,
  // the selection's highlight) or to the moment shown; the video's explosions are its own.
  picture_ = view_->picture();
  picture_.explosions.clear();
  picture_.trails.clear();
  picture_.velocityArrows.clear();
  picture_.handleArrows.clear();
  picture_.highlights = false;
  explosions_ = render::ExplosionPool(view_->explosionLimit());
  showExplosions_ = view_->explosionsEnabled();

  if (settings.format == VideoSettings::Format::Mp4) {
    encoder_ = new QProcess(this);
    const QString size = QString("%1x%2").arg(settings.size.width()).arg(settings.size.height());
    // Raw RGBA frames on stdin, so nothing is compressed twice; yuv420p for every player.
    const QStringList arguments = {
        "-hide_banner", "-loglevel", "error",      "-y",
        "-f",           "rawvideo",  "-pix_fmt",   "rgba",
        "-video_size",  size,        "-framerate", QString::number(settings.fps),
        "-i",           "-",         "-an",        "-c:v",
        "libx264",      "-pix_fmt",  "yuv420p",    settings.path};
    encoder_->setProgram(ffmpegPath);
    encoder_->setArguments(arguments);
    encoder_->setStandardOutputFile(QProcess::nullDevice());
    encoder_->start();
    if (!encoder_->waitForStarted()) {
      const QString reason = encoder_->errorString();
      delete encoder_;
      encoder_ = nullptr;
      return tr("Could not start ffmpeg: %1").arg(reason);
    }
    connect(encoder_, &QProcess::finished, this, &VideoExport::encoderFinished);
  }

  queue_ = std::make_shared<VideoFrameQueue>(total_);
  run_->controls().exportVideo(queue_, settings.from, settings.to, settings.fps);
  state_ = State::Writing;
  interactive_ = interactive;
  progress_ = new QProgressDialog(tr("Exporting %n video frame(s)…", nullptr, total_), tr("Cancel"),
                                  0, total_, dialogParent_);
  progress_->setObjectName("videoProgress");
  progress_->setWindowTitle(tr("Export Video"));
  progress_->setWindowModality(Qt::WindowModal);
  progress_->setMinimumDuration(0);
  progress_->setAutoClose(false);
  progress_->setAutoReset(false);
  connect(progress_, &QProgressDialog::canceled, this, &VideoExport::cancel);
  progress_->setValue(0);
  timer_->start();
  return {};
}

void VideoExport::pump() {
  // A modal progress dialog lets events through as its value is set: no turn inside a turn.
  if (pumping_ || state_ != State::Writing) return;
  pumping_ = true;
  const qint64 frameBytes = qint64(settings_.size.width()) * settings_.size.height() * 4;
  QElapsedTimer turn;
  turn.start();
  while (state_ == State::Writing && turn.elapsed() < kPumpMilliseconds) {
    if (nextPending_ >= pending_.size()) {
      pending_ = queue_->take();
      nextPending_ = 0;
      if (pending_.empty()) {
        if (queue_->abandoned())
          fail(
              tr("The run was reset or went on from an earlier frame during the export, "
                 "which stopped after %n frame(s).",
                 nullptr, written_));
        break;
      }
    }
    if (encoder_ && encoder_->bytesToWrite() > 0 &&
        encoder_->bytesToWrite() + frameBytes > std::max(kEncoderBacklogBytes, frameBytes))
      break;
    const QString error = writeFrame(pending_[nextPending_++]);
    if (!error.isEmpty()) {
      fail(error);
      break;
    }
    ++written_;
    emit progressed(written_, total_);  // which may cancel
    if (state_ == State::Writing && written_ == total_) {
      if (encoder_) {
        state_ = State::Encoding;  // ffmpeg finishes the file; encoderFinished() follows
        encoder_->closeWriteChannel();
        if (progress_) progress_->setLabelText(tr("Finishing the video…"));
      } else {
        succeed();
      }
    }
  }
  if (progress_ && state_ != State::Idle) progress_->setValue(written_);
  pumping_ = false;
}

QString VideoExport::writeFrame(const VideoFrame& frame) {
  picture_.ballPositions = frame.positions;
  if (showExplosions_) {
    // Born at their collisions' simulated moments (or the frame before, for those of a step that
    // began before it), they fade over ExplosionPool::kLifetime of simulated time.
    for (const CollisionRecord& collision : frame.collisions)
      explosions_.add(collision.point,
                      render::SceneView::explosionSize(picture_.scene.get(), collision),
                      collision.time);
    explosions_.update(frame.time);
    picture_.explosions = explosions_.live();
  }
  const QImage image = view_->renderPicture(picture_, settings_.size);
  if (image.isNull())
    return tr("The graphics driver could not draw a %1×%2 picture.")
        .arg(settings_.size.width())
        .arg(settings_.size.height());
  if (settings_.format == VideoSettings::Format::Png) {
    const QString file =
        QDir(settings_.path)
            .filePath(QString("frame_%1.png").arg(frame.index + 1, 6, 10, QLatin1Char('0')));
    return ImageExport::writePng(image, file);
  }
  // Byte order R, G, B, A whatever the machine's, and rows without padding.
  const QImage rgba = image.convertToFormat(QImage::Format_RGBA8888);
  const qint64 bytes = rgba.sizeInBytes();
  if (encoder_->write(reinterpret_cast<const char*>(rgba.constBits()), bytes) != bytes)
    return ffmpegError();
  return {};
}

void VideoExport::encoderFinished(int exitCode, QProcess::ExitStatus status) {
  if (state_ == State::Encoding && status == QProcess::NormalExit && exitCode == 0) {
    succeed();
  } else if (state_ != State::Idle) {
    fail(ffmpegError());
  }
}

QString VideoExport::ffmpegError() {
  if (encoder_->state() != QProcess::NotRunning) encoder_->waitForFinished(3000);
  QString said = QString::fromLocal8Bit(encoder_->readAllStandardError()).trimmed();
  if (said.isEmpty()) said = encoder_->errorString();
  const int code = encoder_->state() == QProcess::NotRunning ? encoder_->exitCode() : -1;
  return tr("ffmpeg failed (exit code %1): %2").arg(code).arg(said);
}

void VideoExport::succeed() {
  const QString text = tr("Exported %n video frame(s) of %1×%2 at %3 fps to %4", nullptr, written_)
                           .arg(settings_.size.width())
                           .arg(settings_.size.height())
                           .arg(settings_.fps)
                           .arg(QDir::toNativeSeparators(settings_.path));
  stop(false);
  emit message(text);
  emit finished(true, text);
}

void VideoExport::fail(const QString& reason) {
  const bool interactive = interactive_;
  QString text = reason;
  if (settings_.format == VideoSettings::Format::Png && written_ > 0)
    text += "\n" + tr("The %n frame(s) written before were left in %1.", nullptr, written_)
                       .arg(QDir::toNativeSeparators(settings_.path));
  stop(true);
  emit message(text);
  if (interactive) {
    // Opened, not run: the export's end should not wait on a click.
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Cannot Export Video"), text,
                                QMessageBox::Ok, dialogParent_);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
  }
  emit finished(false, text);
}

void VideoExport::cancel() {
  if (!busy()) return;
  const QString text =
      settings_.format == VideoSettings::Format::Mp4
          ? tr("Video export cancelled; the unfinished video was removed.")
          : tr("Video export cancelled after %n frame(s); they were left in %1.", nullptr, written_)
                .arg(QDir::toNativeSeparators(settings_.path));
  stop(true);
  emit message(text);
  emit finished(false, text);
}

void VideoExport::stop(bool removeVideo) {
  if (queue_) queue_->cancel();  // the worker drops the job at its next tick
  queue_.reset();
  timer_->stop();
  pending_.clear();
  nextPending_ = 0;
  if (encoder_) {
    encoder_->disconnect(this);
    if (encoder_->state() != QProcess::NotRunning) {
      encoder_->kill();
      encoder_->waitForFinished();
    }
    encoder_->deleteLater();
    encoder_ = nullptr;
  }
  if (removeVideo && settings_.format == VideoSettings::Format::Mp4) QFile::remove(settings_.path);
  if (progress_) {
    progress_->disconnect(this);
    progress_->hide();
    progress_->deleteLater();  // it may be the one whose Cancel brought us here
    progress_ = nullptr;
  }
  state_ = State::Idle;
  interactive_ = false;
}

}  // namespace carom::ui
