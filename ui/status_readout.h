#pragma once
// The status bar's permanent readout: simulated time, the real-time factor, frames and
// collisions per second, the ball count and the energy with its drift, plus the sound's state
// and a warning when the physics falls behind. It shows the latest snapshot a few times a second.

#include <QElapsedTimer>
#include <QLabel>
#include <QTimer>

#include <cstdint>
#include <memory>

namespace carom::ui {

class SoundThread;
struct SimulationSnapshot;

class StatusReadout : public QLabel {
  Q_OBJECT
 public:
  explicit StatusReadout(const SoundThread* sound, QWidget* parent = nullptr);

  // Each snapshot the window shows; the line follows within kRefreshMilliseconds.
  void showSnapshot(std::shared_ptr<const SimulationSnapshot> snapshot);
  // Each frame the view draws.
  void countFrame();
  int framesRendered() const { return framesRendered_; }
  // Another scene: the collision rate starts afresh.
  void restart();

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void refresh();

  // Numbers changing sixty times a second cannot be read, and laying out the status bar each
  // frame costs the GUI thread.
  static constexpr int kRefreshMilliseconds = 200;
  // The collision rate is taken over at least this much simulated time, or of real time spent
  // running when the run is slower (a million balls simulate 0.01 s in a few seconds).
  static constexpr double kRateSeconds = 0.5;
  static constexpr qint64 kRateMilliseconds = 2000;

  const SoundThread* sound_;
  QTimer refreshTimer_;
  std::shared_ptr<const SimulationSnapshot> latest_;
  int framesRendered_ = 0;
  int framesAtLastSample_ = 0;
  QElapsedTimer fpsClock_;
  double framesPerSecond_ = 0.0;
  double lastCollisionTime_ = 0.0;
  QElapsedTimer rateClock_;  // since the collision rate's last sample
  std::uint64_t lastCollisionCount_ = 0;
  double collisionsPerSecond_ = 0.0;
};

}  // namespace carom::ui
