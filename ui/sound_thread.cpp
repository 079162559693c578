#include "ui/sound_thread.h"

#include "ui/run/call_queue.h"
#include "ui/run/thread_handover.h"
#include "ui/sound/sound_player.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QTimer>

#include <algorithm>
#include <cstdio>

namespace carom::ui {

namespace {
// After a player has gone, the next starts after the first wait, and each that cannot play
// doubles it up to the longest: a server back within a few seconds is found soon, and a
// machine with none pays for a short-lived process (about 15 ms of CPU) every few seconds.
constexpr int kFirstRetryMs = 500;
constexpr int kLongestRetryMs = 4000;
// A player says it is ready, or exits, within this of its start, and answers each frame within
// this of the last answer; otherwise it is stuck, and is killed.
constexpr int kAnswerMs = 5000;
// At the end the player's input is closed, on which it exits at once; one that has not within
// this is killed.
constexpr int kQuitMs = 2000;

// carom-sound, in the build tree and installed alike at the same place relative to this
// program's folder (CMakeLists.txt).
QString playerProgram() {
  return QDir::cleanPath(QDir(QCoreApplication::applicationDirPath())
                             .absoluteFilePath(QStringLiteral(CAROM_SOUND_PLAYER_FROM_BINDIR)));
}
}  // namespace

// The running player and the next start, on the sound thread.
class SoundThread::Player {
 public:
  explicit Player(SoundThread* owner) : owner_(owner), program_(playerProgram()) {
    retry_.setSingleShot(true);
    QObject::connect(&retry_, &QTimer::timeout, &retry_, [this] { start(); });
    answer_.setSingleShot(true);
    QObject::connect(&answer_, &QTimer::timeout, &answer_, [this] {
      if (process_) process_->kill();  // its end is then taken as any other
    });
    if (!QFileInfo(program_).isExecutable()) {
      std::fprintf(stderr, "carom: no sound: %s not found\n", qPrintable(program_));
      return;
    }
    start();
  }

  ~Player() {
    if (!process_) return;
    process_->disconnect();
    process_->closeWriteChannel();
    if (!process_->waitForFinished(kQuitMs)) {
      process_->kill();
      process_->waitForFinished(kQuitMs);
    }
    delete process_;
  }

  void play(const sound::FrameHits& hits) {
    if (!process_ || !ready_) return;
    process_->write(sound::hitsLine(hits) + '\n');
    if (unanswered_++ == 0) answer_.start(kAnswerMs);
  }

 private:
  void start() {
    process_ = new QProcess;
    process_->setProgram(program_);
    // Its warnings go where the window's go; its answers come here.
    process_->setProcessChannelMode(QProcess::ForwardedErrorChannel);
    QObject::connect(process_, &QProcess::readyReadStandardOutput, process_,
                     [this] { readAnswers(); });
    QObject::connect(process_, &QProcess::finished, process_, [this] { gone(); });
    QObject::connect(process_, &QProcess::errorOccurred, process_,
                     [this](QProcess::ProcessError error) {
                       if (error == QProcess::FailedToStart) gone();
                     });
    process_->start();
    answer_.start(kAnswerMs);
  }

  void readAnswers() {
    pending_ += process_->readAllStandardOutput();
    qsizetype end;
    while ((end = pending_.indexOf('\n')) >= 0) {
      const QByteArray line = pending_.left(end);
      pending_.remove(0, end + 1);
      if (line == sound::kReadyLine) {
        ready_ = true;
        retryMs_ = kFirstRetryMs;
        if (unanswered_ == 0) answer_.stop();
        setAvailable(true);
      } else if (const auto counts = sound::parseCountsLine(line)) {
        current_ = *counts;
        owner_->played_ = earlier_.played + current_.played;
        owner_->dropped_ = earlier_.dropped + current_.dropped;
        if (unanswered_ > 0 && --unanswered_ == 0)
          answer_.stop();
        else
          answer_.start(kAnswerMs);
      }
    }
  }

  // The player exited, crashed, was killed or never started: no sound until another can play.
  void gone() {
    answer_.stop();
    process_->disconnect();
    process_->deleteLater();
    process_ = nullptr;
    ready_ = false;
    unanswered_ = 0;
    pending_.clear();
    earlier_.played += current_.played;
    earlier_.dropped += current_.dropped;
    current_ = {};
    setAvailable(false);
    retry_.start(retryMs_);
    retryMs_ = std::min(2 * retryMs_, kLongestRetryMs);
  }

  void setAvailable(bool available) {
    if (owner_->available_.exchange(available) != available)
      emit owner_->availabilityChanged(available);
  }

  SoundThread* owner_;
  const QString program_;
  QProcess* process_ = nullptr;
  bool ready_ = false;
  int unanswered_ = 0;           // frames sent that the player has not answered yet
  QByteArray pending_;           // its output up to an unfinished line
  sound::PlayerCounts current_;  // the running player's totals
  sound::PlayerCounts earlier_;  // all the players' before it
  QTimer retry_;
  QTimer answer_;
  int retryMs_ = kFirstRetryMs;
};

SoundThread::SoundThread(QObject* parent)
    : QObject(parent), thread_(new QThread(this)), calls_(new CallQueue) {
  thread_->setObjectName("sound");
  calls_->moveToThread(thread_);
  // Emitted on the sound thread once its event loop has ended: the player and the queue go
  // there, before wait() returns.
  connect(
      thread_, &QThread::finished, thread_,
      [this] {
        takeOver(thread_);
        delete player_;
        player_ = nullptr;
        delete calls_;
        handOver(thread_);
      },
      Qt::DirectConnection);
  thread_->start();
  // Made on its thread, so that its process and timers belong to it from the start.
  calls_->post([this] { player_ = new Player(this); });
}

SoundThread::~SoundThread() {
  handOver(thread_);
  thread_->quit();
  thread_->wait();
  takeOver(thread_);
}

void SoundThread::play(const std::vector<CollisionRecord>& collisions) {
  if (collisions.empty() || muted_ || !available_) return;
  const sound::FrameHits hits = sound::hitsOf(collisions);
  calls_->post([this, hits] {
    if (player_) player_->play(hits);
  });
}

}  // namespace carom::ui
