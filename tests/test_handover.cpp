// The two ways data crosses threads in the program, on real threads: the single-slot mailbox
// from the physics worker to the GUI (its notice rule; a writer and readers, each snapshot read
// whole and in order) and the queue of calls the other way (in order, with their data, on the
// queue's thread). Run under ThreadSanitizer by scripts/tsan.sh, where a race would show.

#include "ui/run/call_queue.h"
#include "ui/run/simulation_snapshot.h"

#include <QThread>
#include <QtTest>

#include <atomic>
#include <memory>
#include <numeric>
#include <thread>
#include <vector>

using carom::Vec3;
using carom::ui::CallQueue;
using carom::ui::SimulationSnapshot;
using carom::ui::SnapshotExchange;

namespace {

constexpr int kBalls = 64;

std::shared_ptr<const SimulationSnapshot> snapshotAt(int i) {
  auto snapshot = std::make_shared<SimulationSnapshot>();
  snapshot->time = i;
  snapshot->positions.assign(kBalls, Vec3::Constant(i));
  snapshot->velocities.assign(kBalls, Vec3::Constant(-i));
  snapshot->kineticEnergy = i;
  snapshot->stats.events = static_cast<std::uint64_t>(i);
  return snapshot;
}

// Every field says the same number: a snapshot seen half-written, or freed under the reader,
// would not.
bool whole(const SimulationSnapshot& s) {
  if (s.positions.size() != kBalls || s.velocities.size() != kBalls) return false;
  for (int b = 0; b < kBalls; ++b)
    if (s.positions[b] != Vec3::Constant(s.time) || s.velocities[b] != Vec3::Constant(-s.time))
      return false;
  return s.kineticEnergy == s.time && s.stats.events == static_cast<std::uint64_t>(s.time);
}

}  // namespace

class TestHandover : public QObject {
  Q_OBJECT

 private slots:
  void noticeOnlyAfterTheReaderTook();
  void writerAndReadersOnThreads();
  void callsFromThreadsRunInOrderWithTheirData();
  void callsRunOnTheQueuesThread();
  void callsStillQueuedAreDroppedWithTheQueue();
};

void TestHandover::noticeOnlyAfterTheReaderTook() {
  SnapshotExchange exchange;
  QVERIFY(!exchange.latest());
  QVERIFY(!exchange.take());
  QVERIFY(exchange.publish(snapshotAt(1)));
  // Unread: newer snapshots replace it without another notice.
  QVERIFY(!exchange.publish(snapshotAt(2)));
  QVERIFY(!exchange.publish(snapshotAt(3)));
  QCOMPARE(exchange.latest()->time, 3.0);
  QCOMPARE(exchange.take()->time, 3.0);
  QVERIFY(exchange.publish(snapshotAt(4)));
  // latest() does not mark it read.
  QCOMPARE(exchange.latest()->time, 4.0);
  QVERIFY(!exchange.publish(snapshotAt(5)));
}

void TestHandover::writerAndReadersOnThreads() {
  constexpr int kSnapshots = 20000;
  SnapshotExchange exchange;
  std::atomic<bool> done{false};
  std::atomic<int> notices{0};

  // As the worker does: publish, and count the notices the GUI would get.
  std::thread writer([&] {
    for (int i = 1; i <= kSnapshots; ++i)
      if (exchange.publish(snapshotAt(i))) notices.fetch_add(1);
    done.store(true);
  });
  // The GUI's take() and, beside it, a second reader using latest() only.
  int takes = 0;
  bool takenWhole = true;
  bool takenInOrder = true;
  double lastTaken = 0.0;
  bool peekedWhole = true;  // the peeker's alone until it is joined
  std::thread peeker([&] {
    double last = 0.0;
    while (!done.load()) {
      if (auto s = exchange.latest()) {
        if (!whole(*s) || s->time < last) {
          peekedWhole = false;
          return;
        }
        last = s->time;
      }
    }
  });
  while (!done.load() || lastTaken < kSnapshots) {
    auto s = exchange.take();
    if (!s) continue;
    ++takes;
    takenWhole = takenWhole && whole(*s);
    takenInOrder = takenInOrder && s->time >= lastTaken;
    lastTaken = s->time;
  }
  writer.join();
  peeker.join();

  QVERIFY(takenWhole);
  QVERIFY(takenInOrder);
  QVERIFY(peekedWhole);
  QCOMPARE(lastTaken, double(kSnapshots));
  // At most one notice per take, plus the first.
  QVERIFY(notices.load() >= 1);
  QVERIFY(notices.load() <= takes + 1);
}

// As the speed vs accuracy study does: threads post calls carrying what they computed, and the
// calls run on the queue's (here the test's) thread, each thread's in the order it posted them.
void TestHandover::callsFromThreadsRunInOrderWithTheirData() {
  constexpr int kThreads = 3;
  constexpr int kCalls = 2000;
  CallQueue queue;
  std::vector<std::vector<int>> received(kThreads);  // touched only on this thread
  bool dataWhole = true;
  int ran = 0;
  std::vector<std::thread> posters;
  for (int t = 0; t < kThreads; ++t) {
    posters.emplace_back([&, t] {
      for (int i = 0; i < kCalls; ++i) {
        std::vector<int> data(16);
        std::iota(data.begin(), data.end(), i);  // made on this thread, read on the other
        queue.post([&, t, i, data = std::move(data)] {
          dataWhole = dataWhole && data.size() == 16 && data.front() == i && data.back() == i + 15;
          received[t].push_back(i);
          ++ran;
        });
      }
    });
  }
  for (std::thread& poster : posters) poster.join();
  QTRY_COMPARE(ran, kThreads * kCalls);
  QVERIFY(dataWhole);
  for (const std::vector<int>& calls : received) {
    QCOMPARE(int(calls.size()), kCalls);
    for (int i = 0; i < kCalls; ++i) QCOMPARE(calls[i], i);
  }
}

// As the simulation controller does: the GUI posts calls to a queue living on another thread,
// which runs them there and hands results back.
void TestHandover::callsRunOnTheQueuesThread() {
  QThread thread;
  auto* queue = new CallQueue;
  queue->moveToThread(&thread);
  connect(&thread, &QThread::finished, queue, &QObject::deleteLater);
  thread.start();
  int total = 0;  // the queue's thread's alone until `done`
  std::atomic<bool> onItsThread{true};
  std::atomic<bool> done{false};
  for (int i = 1; i <= 1000; ++i) {
    queue->post([&, i] {
      onItsThread = onItsThread && QThread::currentThread() == &thread;
      total += i;
    });
  }
  queue->post([&] { done = true; });
  QTRY_VERIFY(done.load());
  QVERIFY(onItsThread.load());
  QCOMPARE(total, 1000 * 1001 / 2);
  thread.quit();
  QVERIFY(thread.wait(10000));
}

void TestHandover::callsStillQueuedAreDroppedWithTheQueue() {
  bool ran = false;
  {
    CallQueue queue;
    queue.post([&] { ran = true; });
  }
  QCoreApplication::processEvents();
  QVERIFY(!ran);
}

QTEST_GUILESS_MAIN(TestHandover)
#include "test_handover.moc"
