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

void SoundBoard::createVoices() {
  for (int s = 0; s < SoundCount; ++s) {
    for (int v = 0; v < std::max(1, settings_.voicesPerSound); ++v) {
      auto* voice = new QSoundEffect(this);
      voice->setSource(QUrl(QString::fromLatin1(kSources[s])));
      connect(voice, &QSoundEffect::statusChanged, this, [this, voice] {
        if (voice->status() == QSoundEffect::Error) {
          loadFailed_ = true;
          updateAvailability();
        }
      });
      voices_[s].push_back(voice);
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
  auto free = std::find_if(voices_[sound].begin(), voices_[sound].end(),
                           [](const QSoundEffect* v) { return !v->isPlaying(); });
  if (free == voices_[sound].end()) return false;
  const double volume = settings_.masterVolume * volumeForSpeed(speed, settings_.referenceSpeed);
  (*free)->setVolume(static_cast<float>(std::clamp(volume, 0.0, 1.0)));
  (*free)->play();
  lastStartMs_[sound] = nowMs;
  recentStartsMs_.push_back(nowMs);
  return true;
}

}  // namespace carom
