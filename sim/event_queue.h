#pragma once
// The event calendar: one pending time per ball in an indexed 4-ary heap (shallower than a binary
// one, so fewer cache misses), so the earliest event is found in O(1) and a ball's time changes
// in O(log N). Ties go to the lower ball index, which
// keeps runs deterministic.

#include <limits>
#include <vector>

namespace carom {

class EventQueue {
 public:
  void reset(int ballCount);  // every ball at +infinity
  void set(int ball, double time);
  int top() const { return heap_[0]; }
  double topTime() const { return time_[heap_[0]]; }
  double timeOf(int ball) const { return time_[ball]; }
  bool empty() const { return heap_.empty(); }

 private:
  bool before(int a, int b) const {
    return time_[a] < time_[b] || (time_[a] == time_[b] && a < b);
  }
  void siftUp(int pos);
  void siftDown(int pos);

  static constexpr int kArity = 4;
  std::vector<int> heap_;      // ball indices in heap order
  std::vector<int> position_;  // position of each ball in heap_
  std::vector<double> time_;
};

}  // namespace carom
