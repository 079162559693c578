#include "ui/run/call_queue.h"

namespace carom::ui {

CallQueue::CallQueue(QObject* parent) : QObject(parent) {}

// Taking the lock orders the destruction after every post() and runPending() that finished
// before it, on whichever thread the queue is destroyed.
CallQueue::~CallQueue() {
  std::lock_guard lock(mutex_);
  pending_.clear();
}

void CallQueue::post(std::function<void()> call) {
  std::lock_guard lock(mutex_);
  const bool first = pending_.empty();
  pending_.push_back(std::move(call));
  // One notice per batch: runPending() takes everything queued by the time it runs. Posted
  // under the lock, which nothing takes while Qt holds its event queue's.
  if (first) QMetaObject::invokeMethod(this, "runPending", Qt::QueuedConnection);
}

void CallQueue::runPending() {
  std::vector<std::function<void()>> calls;
  {
    std::lock_guard lock(mutex_);
    calls.swap(pending_);
  }
  for (auto& call : calls) call();
}

}  // namespace carom::ui
