#include "event_queue.h"

#include <algorithm>

namespace carom {

void EventQueue::reset(int ballCount) {
  heap_.resize(ballCount);
  position_.resize(ballCount);
  time_.assign(ballCount, std::numeric_limits<double>::infinity());
  for (int i = 0; i < ballCount; ++i) heap_[i] = position_[i] = i;
}

void EventQueue::set(int ball, double time) {
  const double old = time_[ball];
  time_[ball] = time;
  if (time < old)
    siftUp(position_[ball]);
  else if (time > old)
    siftDown(position_[ball]);
}

void EventQueue::siftUp(int pos) {
  const int ball = heap_[pos];
  while (pos > 0) {
    const int parent = (pos - 1) / kArity;
    if (!before(ball, heap_[parent])) break;
    heap_[pos] = heap_[parent];
    position_[heap_[pos]] = pos;
    pos = parent;
  }
  heap_[pos] = ball;
  position_[ball] = pos;
}

void EventQueue::siftDown(int pos) {
  const int ball = heap_[pos];
  const int n = static_cast<int>(heap_.size());
  for (;;) {
    const int first = kArity * pos + 1;
    if (first >= n) break;
    int child = first;
    const int last = std::min(first + kArity, n);
    for (int c = first + 1; c < last; ++c)
      if (before(heap_[c], heap_[child])) child = c;
    if (!before(heap_[child], ball)) break;
    heap_[pos] = heap_[child];
    position_[heap_[pos]] = pos;
    pos = child;
  }
  heap_[pos] = ball;
  position_[ball] = pos;
}

}  // namespace carom
