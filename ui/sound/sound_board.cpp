#include "ui/sound/sound_board.h"

#include <QAudioDevice>
#include <QAudioFormat>
#include <QAudioSink>
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
// The sink is fed from the board's event loop: a voice is stopped after two 150 ms waits in
// turn, at least 300 ms and two turns of the loop, so that a loop held up for longer has still
// fed it the whole sound. A stop later than about a second would let the loop come round
// again.
constexpr int kVoiceWaitMs = 150;
}  // namespace

FrameHits hitsOf(const std::vector<CollisionRecord>& collisions) {
  FrameHits hits;
  for (const CollisionRecord& c : collisions) {
    const Sound s = c.kind == ContactKind::BallBall ? Clack : Thud;
    ++hits.count[s];
    hits.hardest[s] = std::max(hits.hardest[s], std::abs(c.normalSpeed));
  }
  return hits;
}

SoundBoard::SoundBoard(QObject* parent) : SoundBoard(Settings{}, parent) {}

SoundBoard::SoundBoard(const Settings& settings, QObject* parent)
    : QObject(parent), settings_(settings) {
  clock_.start();
  // Far enough in the past that the first sound of each kind is never held back.
  lastStartMs_.fill(std::numeric_limits<std::int64_t>::min() / 2);
  outputs_ = !QMediaDevices::audioOutputs().isEmpty();
  // With no output each QSoundEffect would warn, and the watch could open nothing.
  if (!outputs_) return;
  // Never played: they keep the decoded sounds in Qt's cache, so that a voice is ready as soon
  // as it is made, and report a file that cannot be loaded. Loading takes a turn of the event
  // loop; the board is available once both are loaded.
  for (int s = 0; s < SoundCount; ++s) samples_[s] = createVoice(Sound(s));
  watchServer();
}

// The watch's stream (a QPulseAudioSink) runs the event loop in its destructor: done first,
// while the board is whole, since a voice's timer may fire in there.
SoundBoard::~SoundBoard() {
  delete watch_;
}

QSoundEffect* SoundBoard::createVoice(Sound sound) {
  auto* voice = new QSoundEffect(QMediaDevices::defaultAudioOutput(), this);
  voice->setSource(QUrl(QString::fromLatin1(kSources[sound])));
  voice->setLoopCount(QSoundEffect::Infinite);
  connect(voice, &QSoundEffect::statusChanged, this, [this, voice] {
    if (voice->status() == QSoundEffect::Error) loadFailed_ = true;
    updateAvailability();
  });
  return voice;
}

// When the connection to the sound server fails, Qt 6.4 closes every stream, tries once to
// reconnect 3 s later, and if the server is not back by then gives up for the rest of the
// process: its backend's reconnection fails without scheduling another (QPulseAudioEngine's
// prepare(), where pa_context_connect() fails at once on a missing socket). Its list of outputs
// keeps the lost ones and QMediaDevices::audioOutputsChanged is never emitted, so the loss shows
// only in the streams: a voice whose play() opens none is not playing afterwards, and an open,
// corked stream (the watch) is stopped with an error. The board then counts itself unavailable
// for good, and a new process (ui/sound_thread) reconnects.
void SoundBoard::watchServer() {
  QAudioFormat format;
  format.setSampleRate(44100);
  format.setChannelCount(1);
  format.setSampleFormat(QAudioFormat::Int16);
  watch_ = new QAudioSink(QMediaDevices::defaultAudioOutput(), format);
  // Corked at once: it plays nothing, costs the server nothing and keeps no device awake, and
  // is still stopped when the connection fails.
  watch_->start();
  watch_->suspend();
  if (watch_->state() != QAudio::SuspendedState) {
    loseServer();
    return;
  }
  connect(watch_, &QAudioSink::stateChanged, this, [this](QAudio::State state) {
    if (state == QAudio::StoppedState) loseServer();
  });
}

void SoundBoard::loseServer() {
  if (lost_) return;
  lost_ = true;
  updateAvailability();
}

void SoundBoard::updateAvailability() {
  const bool loaded = std::all_of(samples_.begin(), samples_.end(), [](const QSoundEffect* s) {
    return s && s->status() == QSoundEffect::Ready;
  });
  const bool now = loaded && !failed();
  if (now != available_) {
    available_ = now;
    emit availabilityChanged(available_);
  }
  if (failed() && !failureSaid_) {
    failureSaid_ = true;
    emit failure();
  }
}

void SoundBoard::play(const std::vector<CollisionRecord>& collisions) {
  playAt(hitsOf(collisions), clock_.elapsed());
}

void SoundBoard::play(const FrameHits& hits) {
  playAt(hits, clock_.elapsed());
}

void SoundBoard::playAt(const std::vector<CollisionRecord>& collisions, std::int64_t nowMs) {
  playAt(hitsOf(collisions), nowMs);
}

void SoundBoard::playAt(const FrameHits& hits, std::int64_t nowMs) {
  if (!available_) return;
  while (!recentStartsMs_.empty() && recentStartsMs_.front() <= nowMs - 1000)
    recentStartsMs_.pop_front();

  // A frame can hold hundreds of contacts; at most one sound of each kind starts, for the
  // hardest hit of that kind, since the minimum gap would drop any second one anyway.
  const Sound order[] = {hits.hardest[Clack] >= hits.hardest[Thud] ? Clack : Thud,
                         hits.hardest[Clack] >= hits.hardest[Thud] ? Thud : Clack};
  for (Sound s : order) {
    if (hits.count[s] <= 0) continue;
    // Once the server is gone nothing more is counted, as when there never was one.
    if (!available_) return;
    const bool started = start(s, hits.hardest[s], nowMs);
    played_ += started ? 1 : 0;
    dropped_ += hits.count[s] - (started ? 1 : 0);
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
  // The sample is cached, so the voice is ready at once and play() opens its stream there and
  // then: a voice not playing afterwards has none, and the server is gone.
  const bool ready = voice->status() == QSoundEffect::Ready;
  if (ready) voice->play();
  if (!ready || !voice->isPlaying()) {
    voice->deleteLater();
    if (ready) loseServer();
    return false;
  }
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
