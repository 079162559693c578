#include "sound_board.h"

#include <QAudioDevice>
#include <QMediaDevices>
#include <QSoundEffect>
#include <QUrl>

#include <algorithm>
#include <cmath>
#include <limits>

namespace carom {

double volumeForSpeed(double speed, double referenceSpeed) {
  // !(x > 0) also catches NaN, which must not reach the audio backend.
  if (!(speed > 0.0)) return 0.0;
  if (!(referenceSpeed > 0.0)) return 1.0;
  if (std::isinf(speed)) return 1.0;
  return speed / (speed + referenceSpeed);
}

namespace {
const char* const kSources[] = {"qrc:/sounds/ball-ball.wav", "qrc:/sounds/ball-wall.wav"};
// Both sounds last under half a second. Played a few times a second, about one QSoundEffect in
// five on Qt 6.4's PulseAudio backend never leaves "playing" (its stream's drain fails) and stays
// silent even when stopped and played again: within seconds every voice was stuck and Carom went
// quiet. A voice still "playing" this long after it began is replaced by a new one.
constexpr std::int64_t kStuckVoiceMs = 1000;
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
  connect(voice, &QSoundEffect::statusChanged, this, [this, voice] {
    if (voice->status() == QSoundEffect::Error) {
      loadFailed_ = true;
      updateAvailability();
    }
  });
  return voice;
}

void SoundBoard::createVoices() {
  for (int s = 0; s < SoundCount; ++s) {
    for (int v = 0; v < std::max(1, settings_.voicesPerSound); ++v) {
      voices_[s].push_back(createVoice(Sound(s)));
      voiceStartMs_[s].push_back(0);
    }
  }
}

void SoundBoard::useDefaultOutput() {
  const QAudioDevice device = QMediaDevices::defaultAudioOutput();
  for (auto& pool : voices_)
    for (QSoundEffect* voice : pool) voice->setAudioDevice(device);
}

void SoundBoard::updateAvailability() {
  const bool outputs = !QMediaDevices::audioOutputs().isEmpty();
  // Voices are made only once there is an output: with none, each QSoundEffect would warn.
  if (outputs && voices_[Clack].empty()) createVoices();
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
  // A voice still sounding is left alone; cutting it off would click.
  std::vector<QSoundEffect*>& pool = voices_[sound];
  std::size_t free = 0;
  while (free < pool.size() && pool[free]->isPlaying() &&
         nowMs - voiceStartMs_[sound][free] < kStuckVoiceMs)
    ++free;
  if (free == pool.size()) return false;
  if (pool[free]->isPlaying()) {
    pool[free]->deleteLater();
    pool[free] = createVoice(sound);
    ++unstuck_;
  }
  QSoundEffect* voice = pool[free];
  const double volume = settings_.masterVolume * volumeForSpeed(speed, settings_.referenceSpeed);
  voice->setVolume(static_cast<float>(std::clamp(volume, 0.0, 1.0)));
  voice->play();
  voiceStartMs_[sound][free] = nowMs;
  lastStartMs_[sound] = nowMs;
  recentStartsMs_.push_back(nowMs);
  return true;
}

}  // namespace carom
