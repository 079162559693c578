#pragma once
// The timeline of a run: every step and every intervention (grabs, live world settings) in
// order, with keyframes, whole copies of the simulation, every so often. Any earlier moment is
// reproduced bit for bit by copying the nearest keyframe before it and doing again what was
// done since, since a copy goes on exactly as the original (Simulation's copy constructor).
//
// Moments are frames: frame k is the state after the run's k-th step and every intervention
// made before the next step. Keyframes are spaced by the work of the steps between them (a
// replay costs about kKeyframeSpacingSeconds, or kKeyframeCopyFactor copies of a scene so
// large that copying it takes longer than that); when the recording outgrows its memory budget,
// every second keyframe is dropped, never the first nor the newest, so older stretches replay
// more slowly and the newest stays quick.

#include "sim/model/scene.h"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace carom {

class Simulation;

// What the user did to the running state between two steps.
struct Intervention {
  enum class Kind { Grab, Steer, Move, Release, SetWorld };
  Kind kind = Kind::Grab;
  int ball = -1;               // Grab
  Vec3 vector = Vec3::Zero();  // Steer, Release: a velocity; Move: the target
  World world;                 // SetWorld
};

// Does `what` to `simulation`, as the live run did.
void apply(const Intervention& what, Simulation& simulation);

class RunRecording {
 public:
  static constexpr std::size_t kDefaultBudgetBytes = std::size_t(256) << 20;
  // Real seconds of stepping between keyframes: the longest a replay of the newest stretch
  // takes.
  static constexpr double kKeyframeSpacingSeconds = 0.05;
  // And at least this many times what the last keyframe's copy took: a million balls take over
  // a second to copy, and a keyframe after every step would double the run's cost.
  static constexpr int kKeyframeCopyFactor = 10;

  // Starts recording at `start`'s present state: frame 0. A keyframe follows each
  // `keyframeSpacingSeconds` of stepping, or kKeyframeCopyFactor times the last copy's time if
  // that is longer (0: every step).
  explicit RunRecording(const Simulation& start, std::size_t budgetBytes = kDefaultBudgetBytes,
                        double keyframeSpacingSeconds = kKeyframeSpacingSeconds);
  ~RunRecording();
  RunRecording(const RunRecording&) = delete;
  RunRecording& operator=(const RunRecording&) = delete;

  // Takes one step of `live` (the simulation being recorded) and records it.
  void step(Simulation& live);
  // Does `what` to `live` and records it, at the current frame.
  void intervene(const Intervention& what, Simulation& live);

  // The frame the live run is at (steps taken since the start).
  std::uint64_t frameCount() const { return frames_; }
  // A fresh simulation at frame `frame` (<= frameCount()), exactly as the live run was then.
  std::unique_ptr<Simulation> reproduce(std::uint64_t frame) const;
  // Takes `shown`, a simulation reproduce() gave at frame `from`, on to frame `to` (>= from).
  void replay(Simulation& shown, std::uint64_t from, std::uint64_t to) const;
  // The keyframe a replay to `frame` would start from.
  std::uint64_t keyframeBefore(std::uint64_t frame) const;
  // The latest keyframe at a simulated time not after `time` (frame 0 when none is): where a
  // replay of the run from that time on starts, without stepping from the very start.
  std::uint64_t keyframeAtTime(double time) const;
  // Forgets everything after frame `frame` (the run goes on from there).
  void truncate(std::uint64_t frame);

  std::size_t budgetBytes() const { return budgetBytes_; }
  void setBudgetBytes(std::size_t bytes);
  std::size_t memoryBytes() const { return memoryBytes_; }
  std::size_t keyframeCount() const { return keyframes_.size(); }

 private:
  struct Keyframe {
    std::uint64_t frame = 0;
    std::size_t firstIntervention = 0;  // the first intervention made after it
    std::unique_ptr<const Simulation> simulation;
    std::size_t bytes = 0;
  };
  struct Recorded {
    std::uint64_t frame = 0;  // made after this many steps
    Intervention what;
  };
  void addKeyframe(const Simulation& live);
  void thin();
  std::size_t interventionBytes() const { return interventions_.capacity() * sizeof(Recorded); }
  void recount();

  std::size_t budgetBytes_;
  std::chrono::steady_clock::duration keyframeSpacing_;
  std::uint64_t frames_ = 0;
  std::vector<Keyframe> keyframes_;  // by frame; the first is frame 0
  std::vector<Recorded> interventions_;
  std::size_t memoryBytes_ = 0;
  // Real time spent stepping since the newest keyframe.
  std::chrono::steady_clock::duration sinceKeyframe_{};
  std::chrono::steady_clock::duration lastCopy_{};  // what the newest keyframe's copy took
};

}  // namespace carom
