#pragma once
// Collision sounds: turns the collisions of a frame into a few short, rate-limited clicks.

#include "sim/run_stats.h"

#include <QElapsedTimer>
#include <QObject>

#include <array>
#include <atomic>
#include <cstdint>
#include <deque>
#include <vector>

class QMediaDevices;
class QSoundEffect;

namespace carom::sound {

// Loudness for an impact: rises smoothly from 0 and approaches 1 for speeds well above the
// reference, so hard hits are loud without ever clipping. Pure, for tests.
double volumeForSpeed(double speed, double referenceSpeed);

class SoundBoard : public QObject {
  Q_OBJECT

 public:
  struct Settings {
    double referenceSpeed = 2.0;  // m/s at which an impact plays at half volume
    double minimumSpeed = 0.05;   // m/s; softer touches (resting jitter) make no sound
    int maxPerSecond = 30;        // sounds started in any one-second window, all kinds
    int minimumGapMs = 15;        // between two starts of the same sound
    int voicesPerSound = 8;       // sounds of one kind at once (a QSoundEffect each)
    double masterVolume = 0.5;    // headroom: two hard hits at once must not clip
  };

  explicit SoundBoard(QObject* parent = nullptr);
  explicit SoundBoard(const Settings& settings, QObject* parent = nullptr);
  ~SoundBoard() override;

  // The collisions since the last frame, on the GUI thread. Starts at most a few sounds and
  // returns at once; the rest are counted as dropped.
  void play(const std::vector<CollisionRecord>& collisions);
  // As play(), at a given time on the board's clock (milliseconds), so tests can replay time.
  void playAt(const std::vector<CollisionRecord>& collisions, std::int64_t nowMs);

  void setMuted(bool muted) { muted_ = muted; }
  bool muted() const { return muted_; }

  // False when there is no audio output (no device or no sound server) or a sound failed to
  // load; play() then does nothing.
  bool available() const { return available_; }

  int playedCount() const { return played_; }
  int droppedCount() const { return dropped_; }
  const Settings& settings() const { return settings_; }

 signals:
  void availabilityChanged(bool available);

 private:
  enum Sound { Clack, Thud, SoundCount };

  QSoundEffect* createVoice(Sound sound);
  void updateAvailability();
  void useDefaultOutput();
  bool start(Sound sound, double speed, std::int64_t nowMs);

  Settings settings_;
  QMediaDevices* devices_ = nullptr;
  std::array<QSoundEffect*, SoundCount> samples_{};
  std::array<std::vector<QSoundEffect*>, SoundCount> voices_;  // sounding now
  std::array<std::int64_t, SoundCount> lastStartMs_;
  std::deque<std::int64_t> recentStartsMs_;  // starts within the last second, oldest first
  QElapsedTimer clock_;
  // Atomic: ui::SoundThread reads them from the GUI thread.
  std::atomic<bool> muted_ = false;
  std::atomic<bool> available_ = false;
  bool loadFailed_ = false;
  std::atomic<int> played_ = 0;
  std::atomic<int> dropped_ = 0;
};

}  // namespace carom::sound
