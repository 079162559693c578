#include "event_queue.h"

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
    const int parent = (pos - 1) / 2;
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
    int child = 2 * pos + 1;
    if (child >= n) break;
    if (child + 1 < n && before(heap_[child + 1], heap_[child])) ++child;
    if (!before(heap_[child], ball)) break;
    heap_[pos] = heap_[child];
    position_[heap_[pos]] = pos;
    pos = child;
  }
  heap_[pos] = ball;
  position_[ball] = pos;
}

}  // namespace carom
