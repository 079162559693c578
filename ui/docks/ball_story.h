#pragma once
// The recent history of a few watched balls, (time, position, velocity) from the snapshots the
// window shows, for their trails in the view and the Ball story dock. No Qt: plain bookkeeping.
//
// Bounded: samples closer than kMinSpacing in simulated time replace each other (so the newest
// state is always the last sample), and at most kMaxSamples are kept a ball, oldest dropped
// first. Time only moves forward within a story: recording or truncating at an earlier time
// discards the samples after it, as a rewound timeline that runs again discards its future.

#include "sim/model/scene.h"

#include <cstddef>
#include <deque>
#include <optional>
#include <vector>

namespace carom::ui {

class BallStory {
 public:
  struct Sample {
    double time = 0.0;
    Vec3 position = Vec3::Zero();
    Vec3 velocity = Vec3::Zero();
  };

  static constexpr double kMinSpacing = 0.01;  // seconds of simulated time
  static constexpr std::size_t kMaxSamples = 4000;

  // Watches these balls (indices into the scene's balls, in the order given): balls watched
  // before keep their story, balls new to it start empty, the others are forgotten.
  void watch(const std::vector<int>& balls);
  const std::vector<int>& watched() const { return balls_; }
  bool isWatched(int ball) const;

  // The watched balls' states at `time` from the snapshot's arrays (balls beyond them are
  // skipped). A time before the last one recorded first truncates there.
  void record(double time, const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities);
  // Discards every sample later than `time`.
  void truncateAfter(double time);
  // Forgets every sample, keeping the watched balls.
  void clear();

  // The watched ball's samples, oldest first; empty for a ball not watched.
  const std::deque<Sample>& samples(int ball) const;
  // The last sample at or before `time`: the state shown at that moment (none before the first).
  std::optional<Sample> stateAt(int ball, double time) const;
  // The positions of the samples from `from` to `to`, ending at the state at `to`.
  std::vector<Vec3> path(int ball, double from, double to) const;
  // The time of the newest sample of any ball, or none.
  std::optional<double> lastTime() const;

 private:
  int slot(int ball) const;

  std::vector<int> balls_;
  std::vector<std::deque<Sample>> samples_;  // one per watched ball, same order
  std::optional<double> lastTime_;
};

}  // namespace carom::ui
