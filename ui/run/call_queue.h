#pragma once
// Calls handed from one thread to another, to run in order on the thread the queue lives in.
// The functions and what they captured cross under a std::mutex; Qt's queued event, which only
// says that there is something to run, carries nothing. So the hand-over does not rest on the
// lock inside Qt's event queue: Debian's Qt is not built with ThreadSanitizer, which cannot see
// that lock, and would otherwise take every call's captured data for a race (scripts/tsan.sh).

#include <QObject>

#include <functional>
#include <mutex>
#include <vector>

namespace carom::ui {

class CallQueue : public QObject {
  Q_OBJECT
 public:
  explicit CallQueue(QObject* parent = nullptr);
  ~CallQueue() override;

  // From any thread, until the queue is destroyed; never waits for the calls already queued to
  // run. Calls still queued when the queue is destroyed are dropped, as events for a deleted
  // object are.
  void post(std::function<void()> call);

 private:
  Q_INVOKABLE void runPending();

  std::mutex mutex_;
  std::vector<std::function<void()>> pending_;  // guarded by mutex_
};

}  // namespace carom::ui
