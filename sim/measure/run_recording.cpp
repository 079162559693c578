#include "sim/measure/run_recording.h"

#include "sim/simulation.h"

#include <algorithm>

namespace carom {

void apply(const Intervention& what, Simulation& simulation) {
  switch (what.kind) {
    case Intervention::Kind::Grab:
      simulation.grab(what.ball);
      return;
    case Intervention::Kind::Steer:
      simulation.steerGrab(what.vector);
      return;
    case Intervention::Kind::Move:
      simulation.moveGrabbed(what.vector);
      return;
    case Intervention::Kind::Release:
      simulation.releaseGrab(what.vector);
      return;
    case Intervention::Kind::SetWorld:
      simulation.setWorld(what.world);
      return;
  }
}

RunRecording::RunRecording(const Simulation& start, std::size_t budgetBytes,
                           double keyframeSpacingSeconds)
    : budgetBytes_(budgetBytes),
      keyframeSpacing_(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(keyframeSpacingSeconds))) {
  addKeyframe(start);
}

RunRecording::~RunRecording() = default;

void RunRecording::step(Simulation& live) {
  const auto begin = std::chrono::steady_clock::now();
  live.step();
  ++frames_;
  sinceKeyframe_ += std::chrono::steady_clock::now() - begin;
  const auto spacing = keyframeSpacing_.count() > 0
                           ? std::max(keyframeSpacing_, kKeyframeCopyFactor * lastCopy_)
                           : keyframeSpacing_;
  if (sinceKeyframe_ >= spacing) addKeyframe(live);
}

void RunRecording::intervene(const Intervention& what, Simulation& live) {
  apply(what, live);
  const std::size_t before = interventionBytes();
  interventions_.push_back({frames_, what});
  memoryBytes_ += interventionBytes() - before;
  if (memoryBytes_ > budgetBytes_) thin();
}

void RunRecording::addKeyframe(const Simulation& live) {
  const auto begin = std::chrono::steady_clock::now();
  auto copy = std::make_unique<Simulation>(live);
  lastCopy_ = std::chrono::steady_clock::now() - begin;
  // Collisions are the live run's news, for its explosions and sounds; a replay needs none.
  copy->setCollisionLog(false);
  copy->takeCollisions();
  Keyframe keyframe;
  keyframe.frame = frames_;
  keyframe.firstIntervention = interventions_.size();
  keyframe.bytes = copy->memoryBytes();
  keyframe.simulation = std::move(copy);
  // A keyframe at the newest one's frame replaces it (the interventions since are in it).
  if (!keyframes_.empty() && keyframes_.back().frame == frames_ && keyframes_.size() > 1) {
    memoryBytes_ -= keyframes_.back().bytes;
    keyframes_.pop_back();
  }
  memoryBytes_ += keyframe.bytes;
  keyframes_.push_back(std::move(keyframe));
  sinceKeyframe_ = {};
  if (memoryBytes_ > budgetBytes_) thin();
}

// Every second keyframe between the first and the newest goes, as often as the budget needs.
// With two left it stops: a recording can then exceed its budget by those two.
void RunRecording::thin() {
  while (memoryBytes_ > budgetBytes_ && keyframes_.size() > 2) {
    std::vector<Keyframe> kept;
    for (std::size_t k = 0; k < keyframes_.size(); ++k)
      if (k % 2 == 0 || k + 1 == keyframes_.size()) kept.push_back(std::move(keyframes_[k]));
    keyframes_.swap(kept);
    recount();
  }
}

void RunRecording::recount() {
  memoryBytes_ = interventionBytes();
  for (const Keyframe& keyframe : keyframes_) memoryBytes_ += keyframe.bytes;
}

void RunRecording::setBudgetBytes(std::size_t bytes) {
  budgetBytes_ = bytes;
  thin();
}

std::uint64_t RunRecording::keyframeBefore(std::uint64_t frame) const {
  const auto after = std::upper_bound(
      keyframes_.begin(), keyframes_.end(), frame,
      [](std::uint64_t f, const Keyframe& keyframe) { return f < keyframe.frame; });
  return std::prev(after)->frame;
}

std::uint64_t RunRecording::keyframeAtTime(double time) const {
  // Steps only move time forward, so the keyframes are in order of time too.
  const auto after = std::upper_bound(
      keyframes_.begin() + 1, keyframes_.end(), time,
      [](double t, const Keyframe& keyframe) { return t < keyframe.simulation->time(); });
  return std::prev(after)->frame;
}

std::unique_ptr<Simulation> RunRecording::reproduce(std::uint64_t frame) const {
  frame = std::min(frame, frames_);
  const auto after = std::upper_bound(
      keyframes_.begin(), keyframes_.end(), frame,
      [](std::uint64_t f, const Keyframe& keyframe) { return f < keyframe.frame; });
  const Keyframe& keyframe = *std::prev(after);
  auto simulation = std::make_unique<Simulation>(*keyframe.simulation);
  std::size_t next = keyframe.firstIntervention;
  for (std::uint64_t f = keyframe.frame;; ++f) {
    while (next < interventions_.size() && interventions_[next].frame == f)
      apply(interventions_[next++].what, *simulation);
    if (f == frame) break;
    simulation->step();
  }
  return simulation;
}

void RunRecording::replay(Simulation& shown, std::uint64_t from, std::uint64_t to) const {
  to = std::min(to, frames_);
  // Those made at `from` itself are in `shown` already.
  std::size_t next = std::upper_bound(interventions_.begin(), interventions_.end(), from,
                                      [](std::uint64_t f, const Recorded& recorded) {
                                        return f < recorded.frame;
                                      }) -
                     interventions_.begin();
  for (std::uint64_t f = from; f < to;) {
    shown.step();
    ++f;
    while (next < interventions_.size() && interventions_[next].frame == f)
      apply(interventions_[next++].what, shown);
  }
}

void RunRecording::truncate(std::uint64_t frame) {
  if (frame >= frames_) return;
  frames_ = frame;
  while (!interventions_.empty() && interventions_.back().frame > frame) interventions_.pop_back();
  while (keyframes_.size() > 1 && keyframes_.back().frame > frame) keyframes_.pop_back();
  // The newest keyframe may hold fewer interventions than its frame now has: that is as it
  // should be, reproduce() applies the rest.
  sinceKeyframe_ = {};
  recount();
}

}  // namespace carom
