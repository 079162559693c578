#include "sim/exact/event_queue.h"

#include <algorithm>

namespace carom {

void EventQueue::reset(int ballCount) {
  heap_.resize(ballCount);
  position_.resize(ballCount);
  for (int i = 0; i < ballCount; ++i) {
    heap_[i] = {std::numeric_limits<double>::infinity(), i};
    position_[i] = i;
  }
}

void EventQueue::set(int ball, double time) {
  const int pos = position_[ball];
  const double old = heap_[pos].time;
  heap_[pos].time = time;
  if (time < old)
    siftUp(pos);
  else if (time > old)
    siftDown(pos);
}

void EventQueue::siftUp(int pos) {
  const Entry entry = heap_[pos];
  while (pos > 0) {
    const int parent = (pos - 1) / kArity;
    if (!before(entry, heap_[parent])) break;
    heap_[pos] = heap_[parent];
    position_[heap_[pos].ball] = pos;
    pos = parent;
  }
  heap_[pos] = entry;
  position_[entry.ball] = pos;
}

void EventQueue::siftDown(int pos) {
  const Entry entry = heap_[pos];
  const int n = static_cast<int>(heap_.size());
  for (;;) {
    const int first = kArity * pos + 1;
    if (first >= n) break;
    int child = first;
    const int last = std::min(first + kArity, n);
    for (int c = first + 1; c < last; ++c)
      if (before(heap_[c], heap_[child])) child = c;
    if (!before(heap_[child], entry)) break;
    heap_[pos] = heap_[child];
    position_[heap_[pos].ball] = pos;
    pos = child;
  }
  heap_[pos] = entry;
  position_[entry.ball] = pos;
}

}  // namespace carom
