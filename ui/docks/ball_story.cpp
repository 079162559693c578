#include "ui/docks/ball_story.h"

#include <algorithm>

namespace carom::ui {
namespace {

const std::deque<BallStory::Sample> kNoSamples;

// The first sample later than `time`.
std::deque<BallStory::Sample>::const_iterator after(const std::deque<BallStory::Sample>& samples,
                                                    double time) {
  return std::upper_bound(
      samples.begin(), samples.end(), time,
      [](double t, const BallStory::Sample& sample) { return t < sample.time; });
}

}  // namespace

void BallStory::watch(const std::vector<int>& balls) {
  std::vector<std::deque<Sample>> samples;
  samples.reserve(balls.size());
  for (int ball : balls) {
    const int old = slot(ball);
    samples.push_back(old >= 0 ? std::move(samples_[old]) : std::deque<Sample>());
  }
  balls_ = balls;
  samples_ = std::move(samples);
}

bool BallStory::isWatched(int ball) const {
  return slot(ball) >= 0;
}

int BallStory::slot(int ball) const {
  const auto found = std::find(balls_.begin(), balls_.end(), ball);
  return found == balls_.end() ? -1 : static_cast<int>(found - balls_.begin());
}

void BallStory::record(double time, const std::vector<Vec3>& positions,
                       const std::vector<Vec3>& velocities) {
  if (lastTime_ && time < *lastTime_) truncateAfter(time);
  for (std::size_t k = 0; k < balls_.size(); ++k) {
    const auto ball = static_cast<std::size_t>(balls_[k]);
    if (ball >= positions.size() || ball >= velocities.size()) continue;
    std::deque<Sample>& samples = samples_[k];
    const Sample sample{time, positions[ball], velocities[ball]};
    // The newest state always shows, but samples stay at least kMinSpacing apart: the last one
    // is replaced while the one before it is too close.
    const std::size_t n = samples.size();
    if (n > 0 && samples.back().time == time)
      samples.back() = sample;
    else if (n >= 2 && time - samples[n - 2].time < kMinSpacing)
      samples.back() = sample;
    else
      samples.push_back(sample);
    if (samples.size() > kMaxSamples) samples.pop_front();
  }
  lastTime_ = time;
}

void BallStory::truncateAfter(double time) {
  for (std::deque<Sample>& samples : samples_) samples.erase(after(samples, time), samples.end());
  if (lastTime_ && *lastTime_ > time) lastTime_ = time;
}

void BallStory::clear() {
  for (std::deque<Sample>& samples : samples_) samples.clear();
  lastTime_.reset();
}

const std::deque<BallStory::Sample>& BallStory::samples(int ball) const {
  const int k = slot(ball);
  return k >= 0 ? samples_[k] : kNoSamples;
}

std::optional<BallStory::Sample> BallStory::stateAt(int ball, double time) const {
  const std::deque<Sample>& samples = this->samples(ball);
  const auto next = after(samples, time);
  if (next == samples.begin()) return std::nullopt;
  return *std::prev(next);
}

std::vector<Vec3> BallStory::path(int ball, double from, double to) const {
  const std::deque<Sample>& samples = this->samples(ball);
  auto first = std::lower_bound(samples.begin(), samples.end(), from,
                                [](const Sample& sample, double t) { return sample.time < t; });
  const auto last = after(samples, to);
  std::vector<Vec3> points;
  for (auto it = first; it < last; ++it) points.push_back(it->position);
  return points;
}

std::optional<double> BallStory::lastTime() const {
  return lastTime_;
}

}  // namespace carom::ui
