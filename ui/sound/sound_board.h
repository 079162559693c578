#pragma once
// Collision sounds: turns the collisions of a frame into a few short, rate-limited clicks.

#include "sim/dynamics/run_stats.h"

#include <QElapsedTimer>
#include <QObject>

#include <array>
#include <cstdint>
#include <deque>
#include <vector>

class QAudioSink;
class QSoundEffect;

namespace carom::sound {

// Loudness for an impact: rises smoothly from 0 and approaches 1 for speeds well above the
// reference, so hard hits are loud without ever clipping. Pure, for tests.
double volumeForSpeed(double speed, double referenceSpeed);

enum Sound { Clack, Thud, SoundCount };  // ball–ball; ball–wall or cylinder

// A frame's collisions as the board uses them: how many call for each sound, and the hardest
// hit (normal speed, m/s) of each.
struct FrameHits {
  std::array<int, SoundCount> count{};
  std::array<double, SoundCount> hardest{};
};
FrameHits hitsOf(const std::vector<CollisionRecord>& collisions);

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

  // A frame's collisions. Starts at most a few sounds and returns at once; the rest are
  // counted as dropped. Nothing is counted while the board is not available.
  void play(const std::vector<CollisionRecord>& collisions);
  void play(const FrameHits& hits);
  // As play(), at a given time on the board's clock (milliseconds), so tests can replay time.
  void playAt(const std::vector<CollisionRecord>& collisions, std::int64_t nowMs);
  void playAt(const FrameHits& hits, std::int64_t nowMs);

  // True once there is an audio output and both sounds are loaded, until the sound server is
  // lost. A board never gets its server back: Qt 6.4's audio backend gives up on it for the
  // rest of the process (sound_board.cpp says how); a new process reconnects.
  bool available() const { return available_; }
  // True when the board will never play: there was no output when it was made, a sound could
  // not be loaded, or the server has been lost since.
  bool failed() const { return !outputs_ || loadFailed_ || lost_; }

  // Sounds that started playing (Qt opened their stream), and the rest. One whose stream could
  // not open (the server gone) is dropped, not played.
  int playedCount() const { return played_; }
  int droppedCount() const { return dropped_; }
  const Settings& settings() const { return settings_; }

 signals:
  void availabilityChanged(bool available);
  // Once, when failed() turns true after the board was made.
  void failure();

 private:
  QSoundEffect* createVoice(Sound sound);
  void watchServer();
  void loseServer();
  void updateAvailability();
  // Whether the sound started playing.
  bool start(Sound sound, double speed, std::int64_t nowMs);

  Settings settings_;
  bool outputs_ = false;  // an audio output was there when the board was made
  std::array<QSoundEffect*, SoundCount> samples_{};
  QAudioSink* watch_ = nullptr;  // corked; Qt stops it when the connection to the server fails
  std::array<std::vector<QSoundEffect*>, SoundCount> voices_;  // sounding now
  std::array<std::int64_t, SoundCount> lastStartMs_;
  std::deque<std::int64_t> recentStartsMs_;  // starts within the last second, oldest first
  QElapsedTimer clock_;
  bool loadFailed_ = false;
  bool lost_ = false;
  bool failureSaid_ = false;
  bool available_ = false;
  int played_ = 0;
  int dropped_ = 0;
};

}  // namespace carom::sound
