#include "ui/sound_thread.h"

#include "ui/call_queue.h"
#include "ui/sound/sound_board.h"
#include "ui/thread_handover.h"

namespace carom::ui {

SoundThread::SoundThread(QObject* parent)
    : QObject(parent), thread_(new QThread(this)), calls_(new CallQueue) {
  thread_->setObjectName("sound");
  calls_->moveToThread(thread_);
  // Emitted on the sound thread once its event loop has ended: the board and the queue go
  // there, before wait() returns.
  connect(
      thread_, &QThread::finished, thread_,
      [this] {
        takeOver(thread_);
        delete board_.exchange(nullptr);
        delete calls_;
        handOver(thread_);
      },
      Qt::DirectConnection);
  thread_->start();
  // Made on its thread, so that every QSoundEffect belongs to it from the start.
  calls_->post([this] {
    auto* board = new sound::SoundBoard;
    board->setMuted(muted_);
    board_ = board;
  });
}

SoundThread::~SoundThread() {
  handOver(thread_);
  thread_->quit();
  thread_->wait();
  takeOver(thread_);
}

void SoundThread::play(const std::vector<CollisionRecord>& collisions) {
  if (collisions.empty() || muted_ || !available()) return;
  calls_->post([this, collisions] { board_.load()->play(collisions); });
}

void SoundThread::setMuted(bool muted) {
  muted_ = muted;
  calls_->post([this, muted] {
    if (sound::SoundBoard* board = board_) board->setMuted(muted);
  });
}

bool SoundThread::available() const {
  const sound::SoundBoard* board = board_;
  return board && board->available();
}

int SoundThread::playedCount() const {
  const sound::SoundBoard* board = board_;
  return board ? board->playedCount() : 0;
}

int SoundThread::droppedCount() const {
  const sound::SoundBoard* board = board_;
  return board ? board->droppedCount() : 0;
}

}  // namespace carom::ui
