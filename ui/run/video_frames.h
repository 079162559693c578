#pragma once
// The video export's hand-over from the physics thread to the GUI: the worker replays the
// recorded run and pushes each video frame's ball positions; the GUI takes them in batches,
// renders and writes them. First in, first out, and bounded: the worker makes no more than
// the room left, so a long stretch never sits in memory whole. Std only, like the snapshots.

#include "sim/dynamics/run_stats.h"
#include "sim/model/scene.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <mutex>
#include <utility>
#include <vector>

namespace carom::ui {

// Video frame k of a stretch shows the moment from + k / fps, for every such moment not after
// the stretch's end (a millionth of a frame's slack for rounding).
inline int videoFrameCount(double from, double to, int fps) {
  if (!(to >= from) || fps <= 0) return 0;
  return static_cast<int>(std::floor((to - from) * fps + 1e-6)) + 1;
}
inline double videoFrameTime(double from, int fps, int frame) {
  return from + static_cast<double>(frame) / fps;
}

struct VideoFrame {
  int index = 0;              // from 0
  double time = 0.0;          // the moment it shows
  double recordedTime = 0.0;  // the recorded frame it shows: the latest at or before `time`
  std::vector<Vec3> positions;
  // The collisions of the recorded steps first shown by this frame (for frame 0, those from the
  // keyframe the replay began at), oldest first: the video's explosions.
  std::vector<CollisionRecord> collisions;
};

class VideoFrameQueue {
 public:
  // Frames are made ahead of the GUI by at most this many.
  static constexpr std::size_t kCapacity = 32;

  explicit VideoFrameQueue(int count) : count_(count) {}

  // The frames the stretch has in all.
  int count() const { return count_; }

  // The worker's side.
  std::size_t room() const {
    std::lock_guard lock(mutex_);
    return kCapacity - std::min(kCapacity, frames_.size());
  }
  void push(VideoFrame frame) {
    std::lock_guard lock(mutex_);
    frames_.push_back(std::move(frame));
  }
  // The run the frames come from was reset or went on from an earlier frame: no more come.
  void abandon() { abandoned_.store(true); }
  bool cancelled() const { return cancelled_.load(); }

  // The GUI's side.
  std::vector<VideoFrame> take() {
    std::vector<VideoFrame> taken;
    std::lock_guard lock(mutex_);
    taken.swap(frames_);
    return taken;
  }
  // The worker stops at its next turn.
  void cancel() { cancelled_.store(true); }
  bool abandoned() const { return abandoned_.load(); }

 private:
  const int count_;
  mutable std::mutex mutex_;
  std::vector<VideoFrame> frames_;  // guarded by mutex_
  std::atomic<bool> cancelled_{false};
  std::atomic<bool> abandoned_{false};
};

}  // namespace carom::ui
