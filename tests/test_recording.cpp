// The timeline (sim/run_recording.h): any recorded moment comes back bit for bit, grabs and
// live settings included; the memory budget holds; truncating lets the run go on from there.

#include "scene_helpers.h"
#include "sim/measure/run_recording.h"
#include "sim/simulation.h"

#include <QTest>

#include <cmath>

using namespace carom;
using namespace carom::testing;

namespace {

struct Moment {
  double time;
  std::vector<BallState> state;
};

Moment momentOf(const Simulation& sim) {
  return {sim.time(), sim.state()};
}

bool same(const Moment& a, const Moment& b) {
  if (a.time != b.time || a.state.size() != b.state.size()) return false;
  for (std::size_t i = 0; i < a.state.size(); ++i)
    if (a.state[i].position != b.state[i].position || a.state[i].velocity != b.state[i].velocity ||
        a.state[i].resting != b.state[i].resting)
      return false;
  return true;
}

// A recorded run of 300 steps with a grab steered, let go, and a live change of gravity and
// time step; `moments` gets the live state at every frame.
void recordRun(RunRecording& recording, Simulation& live, std::vector<Moment>& moments) {
  moments.push_back(momentOf(live));
  for (int k = 1; k <= 300; ++k) {
    recording.step(live);
    if (k == 40) recording.intervene({Intervention::Kind::Grab, 3, {}, {}}, live);
    if (k >= 40 && k < 100)
      recording.intervene(
          {Intervention::Kind::Steer, -1, Vec3(std::cos(0.1 * k), std::sin(0.13 * k), 0.3), {}},
          live);
    if (k == 100) recording.intervene({Intervention::Kind::Release, -1, Vec3(0, 4, 0), {}}, live);
    if (k == 150) {
      World world = live.world();
      world.gravity = Vec3(1, -3, 0);
      world.timeStep = 1.0 / 90.0;
      recording.intervene({Intervention::Kind::SetWorld, -1, {}, world}, live);
    }
    moments.push_back(momentOf(live));
  }
}

}  // namespace

class RecordingTest : public QObject {
  Q_OBJECT

 private slots:
  void everyFrameComesBackBitForBit_data() {
    addMethodRows({Method::Exact, Method::Swept, Method::Discrete});
  }
  void everyFrameComesBackBitForBit() {
    QFETCH(int, method);
    const Scene scene = elasticGasRoom(150, Method(method));
    Simulation live(scene);
    // No keyframe but the start's: every frame is replayed from there.
    RunRecording recording(live, RunRecording::kDefaultBudgetBytes, 1e9);
    std::vector<Moment> moments;
    recordRun(recording, live, moments);
    QCOMPARE(recording.frameCount(), std::uint64_t(300));
    for (std::uint64_t frame : {0, 1, 39, 40, 41, 99, 100, 101, 150, 151, 299, 300}) {
      const std::unique_ptr<Simulation> shown = recording.reproduce(frame);
      QVERIFY2(same(momentOf(*shown), moments[frame]), qPrintable(QString::number(frame)));
    }
    // Replayed on from one frame to a later one, the same again.
    std::unique_ptr<Simulation> shown = recording.reproduce(10);
    recording.replay(*shown, 10, 170);
    QVERIFY(same(momentOf(*shown), moments[170]));
  }

  // A run with nothing done to it is the run a fresh simulation makes, step for step: the
  // recording takes nothing from the physics.
  void recordingChangesNothing() {
    const Scene scene = elasticGasRoom(200, Method::Exact);
    Simulation live(scene), fresh(scene);
    RunRecording recording(live, RunRecording::kDefaultBudgetBytes, 0.0);
    for (int k = 0; k < 240; ++k) {
      recording.step(live);
      fresh.step();
    }
    QVERIFY(same(momentOf(live), momentOf(fresh)));
    QVERIFY(same(momentOf(*recording.reproduce(123)), [&] {
      Simulation again(scene);
      for (int k = 0; k < 123; ++k) again.step();
      return momentOf(again);
    }()));
  }

  // Over budget, keyframes thin out, never the first nor the newest, and every frame still
  // comes back exactly.
  void memoryBudgetHolds() {
    const Scene scene = elasticGasRoom(100, Method::Exact);
    Simulation live(scene);
    const std::size_t keyframeBytes = live.memoryBytes();
    const std::size_t budget = 12 * keyframeBytes;
    RunRecording recording(live, budget, 0.0);  // a keyframe each step
    std::vector<Moment> moments;
    recordRun(recording, live, moments);
    QVERIFY2(recording.memoryBytes() <= budget,
             qPrintable(QString("%1 > %2").arg(recording.memoryBytes()).arg(budget)));
    QVERIFY(recording.keyframeCount() >= 3);
    QVERIFY(recording.keyframeCount() <= 12);
    QCOMPARE(recording.keyframeBefore(0), std::uint64_t(0));
    QCOMPARE(recording.keyframeBefore(300), std::uint64_t(300));
    for (std::uint64_t frame : {7, 77, 155, 299})
      QVERIFY(same(momentOf(*recording.reproduce(frame)), moments[frame]));
    // A smaller budget thins at once.
    recording.setBudgetBytes(4 * keyframeBytes);
    QVERIFY(recording.memoryBytes() <= 4 * keyframeBytes);
    QVERIFY(same(momentOf(*recording.reproduce(211)), moments[211]));
  }

  // The keyframe a replay from a moment starts at: the latest not after it, by simulated time
  // (the time step changes at frame 150), and frame 0 before the start.
  void keyframeAtTime() {
    const Scene scene = elasticGasRoom(40, Method::Swept);
    Simulation live(scene);
    const std::size_t keyframeBytes = live.memoryBytes();
    RunRecording recording(live, 40 * keyframeBytes, 0.0);  // thinned: keyframes irregular
    std::vector<Moment> moments;
    recordRun(recording, live, moments);
    QVERIFY(recording.keyframeCount() > 3);
    QCOMPARE(recording.keyframeAtTime(-1.0), std::uint64_t(0));
    QCOMPARE(recording.keyframeAtTime(0.0), std::uint64_t(0));
    QCOMPARE(recording.keyframeAtTime(1e9), std::uint64_t(300));
    for (std::uint64_t frame = 1; frame < moments.size(); frame += 7) {
      const double time = moments[frame].time;
      const std::uint64_t key = recording.keyframeAtTime(time);
      QVERIFY2(key <= frame, qPrintable(QString("%1 > %2").arg(key).arg(frame)));
      QCOMPARE(key, recording.keyframeBefore(frame));  // no later keyframe is at or before it
      // A little before the frame's time, the keyframe is at most the previous frame's.
      QVERIFY(recording.keyframeAtTime(time - 1e-12) <= frame - 1 ||
              moments[frame - 1].time == time);
    }
  }

  // Going back and on from there forgets the old future and records the new one.
  void truncateAndGoOn() {
    const Scene scene = elasticGasRoom(80, Method::Swept);
    Simulation live(scene);
    RunRecording recording(live, RunRecording::kDefaultBudgetBytes, 1e9);
    std::vector<Moment> moments;
    recordRun(recording, live, moments);
    std::unique_ptr<Simulation> resumed = recording.reproduce(60);  // mid-grab
    recording.truncate(60);
    QCOMPARE(recording.frameCount(), std::uint64_t(60));
    std::vector<Moment> future{momentOf(*resumed)};
    for (int k = 0; k < 50; ++k) {
      recording.step(*resumed);
      if (k == 10)
        recording.intervene({Intervention::Kind::Release, -1, Vec3(0, -1, 0), {}}, *resumed);
      future.push_back(momentOf(*resumed));
    }
    QVERIFY(same(momentOf(*recording.reproduce(30)), moments[30]));
    QVERIFY(same(momentOf(*recording.reproduce(60)), moments[60]));
    for (int k : {1, 11, 12, 50})
      QVERIFY2(same(momentOf(*recording.reproduce(60 + k)), future[k]),
               qPrintable(QString::number(k)));
    // The old future's release at frame 100 is gone.
    QVERIFY(!same(momentOf(*recording.reproduce(110)), moments[110]));
  }
};

QTEST_APPLESS_MAIN(RecordingTest)
#include "test_recording.moc"
