#pragma once
// The window's collision sounds, played by a process of their own, carom-sound
// (ui/sound/sound_player.h), which a thread of this class's starts, feeds, and starts again.
// A process, because Qt 6.4's audio backend gives up for good on a sound server that stays away
// for more than 3 s and only a new process reconnects: a player that has lost its server exits,
// and another is started every few seconds until one can play. One that stops answering (Qt
// can wait for ever to open a stream on a server that has stopped) is killed and replaced. A
// thread, because the pipe to the player is written from its thread's event loop, which a long
// frame on the GUI thread must not hold up; the GUI posts it each frame's hits (CallQueue) and
// reads the counters, which are atomic.

#include "sim/dynamics/run_stats.h"

#include <QObject>
#include <QThread>

#include <atomic>
#include <vector>

namespace carom::ui {

class CallQueue;

class SoundThread : public QObject {
  Q_OBJECT
 public:
  explicit SoundThread(QObject* parent = nullptr);
  ~SoundThread() override;

  // The collisions since the last frame; returns at once. Nothing is sent, nor counted, while
  // muted or with no sound.
  void play(const std::vector<CollisionRecord>& collisions);
  void setMuted(bool muted) { muted_ = muted; }
  bool muted() const { return muted_; }
  // True while a player can play: false until the first says so, and from the moment one
  // loses its server until another can play.
  bool available() const { return available_; }
  // Over all the players so far: sounds that played (Qt opened their stream) and sounds
  // dropped by the limits (SoundBoard::Settings).
  int playedCount() const { return played_; }
  int droppedCount() const { return dropped_; }

 signals:
  // From the sound thread: queued to receivers on other threads.
  void availabilityChanged(bool available);

 private:
  class Player;

  QThread* thread_;           // a child named "sound"
  CallQueue* calls_;          // on thread_: runs the posted calls there
  Player* player_ = nullptr;  // made, used and deleted on thread_
  std::atomic<bool> muted_ = false;
  std::atomic<bool> available_ = false;
  std::atomic<int> played_ = 0;
  std::atomic<int> dropped_ = 0;
};

}  // namespace carom::ui
