#include "ui/sound/sound_board.h"

#include <QAudioDevice>
#include <QMediaDevices>
#include <QSoundEffect>
#include <QTimer>
#include <QUrl>

#include <algorithm>
#include <cmath>
#include <limits>

namespace carom::sound {

double volumeForSpeed(double speed, double referenceSpeed) {
  // !(x > 0) also catches NaN, which must not reach the audio backend.
  if (!(speed > 0.0)) return 0.0;
  if (!(referenceSpeed > 0.0)) return 1.0;
  if (std::isinf(speed)) return 1.0;
  return speed / (speed + referenceSpeed);
}

namespace {
const char* const kSources[] = {"qrc:/sounds/ball-ball.wav", "qrc:/sounds/ball-wall.wav"};
// Every sound gets a QSoundEffect of its own, which plays it as an endless loop and is stopped
// and deleted in the silence that ends both sound files (scripts/make-sounds.py). Qt 6.4's
// PulseAudio sink goes wrong when a QSoundEffect is reused or left to end a sound itself: each
// reopening of its stream asks for three quarters of the previous buffer, and after five or six
// plays the buffer is smaller than one 20 ms period, so nothing is ever written again (Carom
// fell silent within seconds); and a drain completing after the sink was stopped leaves it idle
// with no stream, which crashed in pa_stream_writable_size after a few minutes. A fresh,
// looping QSoundEffect has neither.
//
// The sink is fed from this thread's event loop: a voice is stopped after two 150 ms waits in
// turn, at least 300 ms and two turns of the loop, so that a GUI thread stalled for longer has
// still fed it the whole sound. A stop later than about a second would let the loop come round
// again.
constexpr int kVoiceWaitMs = 150;
}  // namespace

SoundBoard::SoundBoard(QObject* parent) : SoundBoard(Settings{}, parent) {}

SoundBoard::SoundBoard(const Settings& settings, QObject* parent)
    : QObject(parent), settings_(settings) {
  clock_.start();
  // Far enough in the past that the first sound of each kind is never held back.
  lastStartMs_.fill(std::numeric_limits<std::int64_t>::min() / 2);
  devices_ = new QMediaDevices(this);
  // A server or device that comes or goes later (PulseAudio restarted, USB headset) is followed.
  connect(devices_, &QMediaDevices::audioOutputsChanged, this, [this] {
    useDefaultOutput();
    updateAvailability();
  });
  updateAvailability();
}

SoundBoard::~SoundBoard() = default;

QSoundEffect* SoundBoard::createVoice(Sound sound) {
  auto* voice = new QSoundEffect(QMediaDevices::defaultAudioOutput(), this);
  voice->setSource(QUrl(QString::fromLatin1(kSources[sound])));
  voice->setLoopCount(QSoundEffect::Infinite);
  connect(voice, &QSoundEffect::statusChanged, this, [this, voice] {
    if (voice->status() == QSoundEffect::Error) {
      loadFailed_ = true;
      updateAvailability();
    }
  });
  return voice;
}

void SoundBoard::useDefaultOutput() {
  const QAudioDevice device = QMediaDevices::defaultAudioOutput();
  for (QSoundEffect* sample : samples_) sample->setAudioDevice(device);
}

void SoundBoard::updateAvailability() {
  const bool outputs = !QMediaDevices::audioOutputs().isEmpty();
  // The samples are loaded only once there is an output: with none, each QSoundEffect would
  // warn. They are never played; they keep the decoded sounds in Qt's cache for the voices and
  // report a file that cannot be loaded.
  if (outputs && !samples_[Clack])
    for (int s = 0; s < SoundCount; ++s) samples_[s] = createVoice(Sound(s));
  const bool now = outputs && !loadFailed_;
  if (now == available_) return;
  available_ = now;
  emit availabilityChanged(available_);
}

void SoundBoard::play(const std::vector<CollisionRecord>& collisions) {
  playAt(collisions, clock_.elapsed());
}

void SoundBoard::playAt(const std::vector<CollisionRecord>& collisions, std::int64_t nowMs) {
  if (muted_ || !available_ || collisions.empty()) return;
  while (!recentStartsMs_.empty() && recentStartsMs_.front() <= nowMs - 1000)
    recentStartsMs_.pop_front();

  // A frame can hold hundreds of contacts; at most one sound of each kind starts, for the
  // hardest hit of that kind, since the minimum gap would drop any second one anyway.
  std::array<int, SoundCount> count{};
  std::array<double, SoundCount> hardest{};
  for (const CollisionRecord& c : collisions) {
    const Sound s = c.kind == ContactKind::BallBall ? Clack : Thud;
    ++count[s];
    hardest[s] = std::max(hardest[s], std::abs(c.normalSpeed));
  }
  const Sound order[] = {hardest[Clack] >= hardest[Thud] ? Clack : Thud,
                         hardest[Clack] >= hardest[Thud] ? Thud : Clack};
  for (Sound s : order) {
    if (count[s] == 0) continue;
    const bool started = start(s, hardest[s], nowMs);
    played_ += started ? 1 : 0;
    dropped_ += count[s] - (started ? 1 : 0);
  }
}

bool SoundBoard::start(Sound sound, double speed, std::int64_t nowMs) {
  if (speed < settings_.minimumSpeed) return false;
  if (static_cast<int>(recentStartsMs_.size()) >= settings_.maxPerSecond) return false;
  if (nowMs - lastStartMs_[sound] < settings_.minimumGapMs) return false;
  // Voices still sounding are left alone; cutting one off would click.
  std::vector<QSoundEffect*>& sounding = voices_[sound];
  if (static_cast<int>(sounding.size()) >= std::max(1, settings_.voicesPerSound)) return false;
  QSoundEffect* voice = createVoice(sound);
  const double volume = settings_.masterVolume * volumeForSpeed(speed, settings_.referenceSpeed);
  voice->setVolume(static_cast<float>(std::clamp(volume, 0.0, 1.0)));
  voice->play();
  sounding.push_back(voice);
  // Two waits of kVoiceWaitMs in turn: at least 300 ms, and two turns of the event loop.
  QTimer::singleShot(kVoiceWaitMs, voice, [this, voice, sound] {
    QTimer::singleShot(kVoiceWaitMs, voice, [this, voice, sound] {
      voice->stop();
      std::erase(voices_[sound], voice);
      voice->deleteLater();
    });
  });
  lastStartMs_[sound] = nowMs;
  recentStartsMs_.push_back(nowMs);
  return true;
}

}  // namespace carom::sound
