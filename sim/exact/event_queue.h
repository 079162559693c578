#pragma once
// The event calendar: one pending time per ball in an indexed 4-ary heap (shallower than a binary
// one, so fewer cache misses), so the earliest event is found in O(1) and a ball's time changes
// in O(log N). Ties go to the lower ball index, which
// keeps runs deterministic.

#include "sim/core/memory_bytes.h"

#include <cstddef>
#include <limits>
#include <vector>

namespace carom {

class EventQueue {
 public:
  void reset(int ballCount);  // every ball at +infinity
  void set(int ball, double time);
  int top() const { return heap_[0].ball; }
  double topTime() const { return heap_[0].time; }
  double timeOf(int ball) const { return heap_[position_[ball]].time; }
  bool empty() const { return heap_.empty(); }
  std::size_t memoryBytes() const {
    return carom::memoryBytes(heap_) + carom::memoryBytes(position_);
  }

 private:
  // Each heap slot keeps its key, so sifting reads one array.
  struct Entry {
    double time;
    int ball;
  };
  static bool before(const Entry& a, const Entry& b) {
    return a.time < b.time || (a.time == b.time && a.ball < b.ball);
  }
  void siftUp(int pos);
  void siftDown(int pos);

  static constexpr int kArity = 4;
  std::vector<Entry> heap_;
  std::vector<int> position_;  // where each ball is in heap_
};

}  // namespace carom
