#pragma once
// Hand-overs between threads that go through Qt's own locks, said so to ThreadSanitizer, which
// cannot see them (Debian's Qt is not built with it; QMutex waits on a futex of its own).
//
// Ending a worker thread hands it over twice through Qt: quit() to the thread, and its end back
// to wait(). With the thread as the mark: what the GUI did before quit() comes before the
// worker is deleted on its thread (handOver before quit(), takeOver in a direct connection to
// QThread::finished), and what the worker did comes before wait() returns (handOver in that
// connection, takeOver after wait()). They do nothing outside a ThreadSanitizer build.

#include <QThread>

#if defined(__SANITIZE_THREAD__)
#include <sanitizer/tsan_interface.h>
#endif

namespace carom::ui {

// Everything this thread did so far comes before what follows a takeOver() of the same `mark`
// on another thread.
inline void handOver([[maybe_unused]] const void* mark) {
#if defined(__SANITIZE_THREAD__)
  __tsan_release(const_cast<void*>(mark));
#endif
}

inline void takeOver([[maybe_unused]] const void* mark) {
#if defined(__SANITIZE_THREAD__)
  __tsan_acquire(const_cast<void*>(mark));
#endif
}

}  // namespace carom::ui
