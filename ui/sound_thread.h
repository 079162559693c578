#pragma once
// The collision sounds on a thread of their own. Starting a sound opens a PulseAudio stream,
// round trips to the server that cost the GUI thread tens of milliseconds a second under a
// gas's 10,000 collisions a second (the stress run's 99th-percentile stall fell from 91 to
// 38 ms without them); and Qt feeds each voice from its thread's event loop, which a long
// frame on the GUI thread would hold up. The SoundBoard is made, used and deleted on that
// thread only: the GUI posts it each frame's collisions (CallQueue) and reads its counters,
// which are atomic.

#include "sim/run_stats.h"

#include <QObject>
#include <QThread>

#include <atomic>
#include <vector>

namespace carom::sound {
class SoundBoard;
}

namespace carom::ui {

class CallQueue;

class SoundThread : public QObject {
  Q_OBJECT
 public:
  explicit SoundThread(QObject* parent = nullptr);
  ~SoundThread() override;

  // The collisions since the last frame; returns at once (the board decides on its thread).
  void play(const std::vector<CollisionRecord>& collisions);
  void setMuted(bool muted);
  bool muted() const { return muted_; }
  // As SoundBoard's: false until the board has found an output on its thread. Read when
  // needed (the status line reads it with each snapshot); there is no signal to follow.
  bool available() const;
  int playedCount() const;
  int droppedCount() const;

 private:
  QThread* thread_;                          // a child named "sound"
  CallQueue* calls_;                         // on thread_: runs the posted calls there
  std::atomic<sound::SoundBoard*> board_{};  // made by the first call on thread_
  std::atomic<bool> muted_ = false;
};

}  // namespace carom::ui
