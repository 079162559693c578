#pragma once
// File > Export Video: a stretch of the recorded run rendered frame by frame at a chosen frame
// rate and size (SceneView::renderPicture, not a capture of the screen, so every frame is there
// however slow the machine), written as a folder of PNGs or as an MP4 encoded by ffmpeg. The
// physics thread replays the run and hands over the ball positions (ui/video_frames.h); this
// side renders and writes them, with a progress dialog and Cancel.

#include "ui/render/scene_view.h"

#include <QDialog>
#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QProcess>
#include <QProgressDialog>
#include <QSize>
#include <QString>

#include <memory>
#include <vector>

class QComboBox;
class QLabel;
class QLineEdit;
class QTimer;

namespace carom::ui {

class RunSession;
class VideoFrameQueue;
struct VideoFrame;

struct VideoSettings {
  enum class Format { Png, Mp4 };
  static constexpr int kMinFps = 1;
  static constexpr int kMaxFps = 240;
  double from = 0.0;  // simulated seconds
  double to = 0.0;
  int fps = 30;
  QSize size;
  Format format = Format::Png;
  QString path;  // the folder of the frames (PNG) or the video file (MP4)
};

// The stretch, frame rate, size and format, typed; OK with a bad value says why and keeps the
// dialog open.
class VideoExportDialog : public QDialog {
  Q_OBJECT
 public:
  // `latestTime`: the newest recorded moment; without ffmpeg the MP4 choice is disabled, and
  // a note says why.
  VideoExportDialog(const VideoSettings& initial, double latestTime, bool ffmpegFound,
                    QWidget* parent = nullptr);

  // What was accepted (its path empty: the folder or file is asked for next).
  VideoSettings chosen() const { return chosen_; }
  QString error() const;
  // The texts typed, read in the user's locale or plainly: empty and `settings` filled (its
  // path left as it was), or the reason, with `settings` unchanged.
  static QString read(const QString& from, const QString& to, const QString& fps,
                      const QString& width, const QString& height, VideoSettings::Format format,
                      double latestTime, bool ffmpegFound, VideoSettings* settings);

  void accept() override;

 private:
  double latestTime_;
  bool ffmpegFound_;
  QLineEdit* from_;
  QLineEdit* to_;
  QLineEdit* fps_;
  QLineEdit* width_;
  QLineEdit* height_;
  QComboBox* format_;
  QLabel* error_;
  VideoSettings chosen_;
};

class VideoExport : public QObject {
  Q_OBJECT
 public:
  // Dialogs open over `dialogParent`.
  VideoExport(render::SceneView* view, RunSession* run, QWidget* dialogParent,
              QObject* parent = nullptr);
  ~VideoExport() override;

  // ffmpeg's path on the PATH, or empty when it is not installed.
  static QString ffmpeg();
  // The settings' numbers checked against the run recorded up to `latestTime`: empty, or the
  // reason.
  static QString check(const VideoSettings& settings, double latestTime, bool ffmpegFound);

  // The menu's way: pauses the run, asks for the settings and then the folder or file, and
  // starts. False when cancelled or refused (a dialog says why).
  bool exportVideo();
  // Pauses the run and starts exporting the stretch as `settings` say, from the view's current
  // camera and scene (no editor handles, trails or arrows; the run's explosions, when the view
  // shows them): empty when started, otherwise the reason, and nothing was written. finished()
  // follows.
  QString start(const VideoSettings& settings);
  bool busy() const { return state_ != State::Idle; }
  // Stops at once: a half-written MP4 is removed, PNGs written are left and counted.
  void cancel();

  int framesWritten() const { return written_; }
  int frameTotal() const { return total_; }
  // While exporting.
  QProgressDialog* progressDialog() const { return progress_.data(); }

 signals:
  // Before an export starts and before the menu's dialog: the window pauses the run.
  void pauseRequested();
  void progressed(int written, int total);
  // The export ended: done (`ok`), failed or cancelled; `text` says which.
  void finished(bool ok, const QString& text);
  void message(const QString& text);

 private:
  enum class State { Idle, Writing, Encoding };

  QString begin(const VideoSettings& settings, bool interactive);
  void pump();
  // Renders and writes one frame; empty or the reason it could not.
  QString writeFrame(const VideoFrame& frame);
  void encoderFinished(int exitCode, QProcess::ExitStatus status);
  void succeed();
  void fail(const QString& reason);
  // Stops the worker, ffmpeg and the progress; removes a half-written MP4.
  void stop(bool removeVideo);
  // What ffmpeg (running or just ended) said as it failed, waiting a moment for it to end so
  // that it has said it.
  QString ffmpegError();

  render::SceneView* view_;
  RunSession* run_;
  QWidget* dialogParent_;
  State state_ = State::Idle;
  bool pumping_ = false;
  bool interactive_ = false;  // started from the menu: failures get a dialog
  VideoSettings settings_;
  render::SceneView::Picture picture_;
  // The video's own explosions, on its simulated clock, as the view's settings were at the
  // start (View > Explosions and the limit).
  render::ExplosionPool explosions_;
  bool showExplosions_ = true;
  std::shared_ptr<VideoFrameQueue> queue_;
  std::vector<VideoFrame> pending_;  // taken from the queue, not yet written
  std::size_t nextPending_ = 0;
  int written_ = 0;
  int total_ = 0;
  QProcess* encoder_ = nullptr;
  QTimer* timer_;
  QPointer<QProgressDialog> progress_;
};

}  // namespace carom::ui
