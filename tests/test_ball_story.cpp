// The Ball story's record of watched balls: what it keeps, how it forgets, and the state it
// reports at a moment, with made-up times (no window, no simulation).

#include "sim/dynamics/energy.h"
#include "ui/docks/ball_story.h"

#include <QtTest>

using carom::Vec3;
using carom::ui::BallStory;

namespace {

// Three balls, ball i at height t + i, moving up at 1 + i.
void recordAt(BallStory& story, double t) {
  std::vector<Vec3> positions, velocities;
  for (int i = 0; i < 3; ++i) {
    positions.emplace_back(0, t + i, 0);
    velocities.emplace_back(0, 1 + i, 0);
  }
  story.record(t, positions, velocities);
}

}  // namespace

class TestBallStory : public QObject {
  Q_OBJECT

 private slots:
  void recordsOnlyTheWatchedBalls() {
    BallStory story;
    story.watch({2, 0});
    for (int k = 0; k <= 10; ++k) recordAt(story, 0.1 * k);
    QCOMPARE(story.samples(2).size(), std::size_t(11));
    QCOMPARE(story.samples(0).size(), std::size_t(11));
    QVERIFY(story.samples(1).empty());
    QCOMPARE(story.samples(2).back().position.y(), 3.0);
    QCOMPARE(story.samples(2).back().velocity.y(), 3.0);
    QCOMPARE(*story.lastTime(), 1.0);
  }

  void newBallsStartFromWhenTheyAreWatched() {
    BallStory story;
    story.watch({0});
    recordAt(story, 0.0);
    recordAt(story, 0.5);
    story.watch({0, 1});
    recordAt(story, 1.0);
    QCOMPARE(story.samples(0).size(), std::size_t(3));
    QCOMPARE(story.samples(1).size(), std::size_t(1));
    QCOMPARE(story.samples(1).front().time, 1.0);
    story.watch({1});  // ball 0 is forgotten
    QVERIFY(story.samples(0).empty());
    QVERIFY(!story.isWatched(0));
  }

  void closeSamplesReplaceEachOtherAndTheNewestIsKept() {
    BallStory story;
    story.watch({0});
    recordAt(story, 0.0);
    recordAt(story, 0.001);
    recordAt(story, 0.002);
    recordAt(story, 0.003);
    QCOMPARE(story.samples(0).size(), std::size_t(2));
    QCOMPARE(story.samples(0).back().time, 0.003);
    recordAt(story, 0.02);
    QCOMPARE(story.samples(0).size(), std::size_t(3));
  }

  void memoryIsBounded() {
    BallStory story;
    story.watch({0, 1, 2});
    const int records = static_cast<int>(BallStory::kMaxSamples) + 500;
    for (int k = 0; k < records; ++k) recordAt(story, k * 0.05);
    QCOMPARE(story.samples(1).size(), BallStory::kMaxSamples);
    QCOMPARE(story.samples(1).back().time, (records - 1) * 0.05);
    QCOMPARE(story.samples(1).front().time, 500 * 0.05);  // the oldest went first
  }

  void stateAtIsTheLastSampleAtOrBefore() {
    BallStory story;
    story.watch({1});
    for (int k = 0; k <= 10; ++k) recordAt(story, 0.1 * k);
    QVERIFY(!story.stateAt(1, -0.5));
    QCOMPARE(story.stateAt(1, 0.35)->time, 0.3);
    QCOMPARE(story.stateAt(1, 0.35)->position.y(), 1.3);
    QCOMPARE(story.stateAt(1, 5.0)->time, 1.0);
    QVERIFY(!story.stateAt(0, 0.5));  // not watched
  }

  void pathRunsUpToTheShownMoment() {
    BallStory story;
    story.watch({0});
    for (int k = 0; k <= 10; ++k) recordAt(story, 0.1 * k);
    const std::vector<Vec3> path = story.path(0, 0.25, 0.65);
    QCOMPARE(path.size(), std::size_t(4));  // 0.3 .. 0.6
    QCOMPARE(path.front().y(), 0.3);
    QCOMPARE(path.back().y(), 0.6);
  }

  void truncatingDiscardsTheFuture() {
    BallStory story;
    story.watch({0, 1});
    for (int k = 0; k <= 10; ++k) recordAt(story, 0.1 * k);
    story.truncateAfter(0.45);
    QCOMPARE(story.samples(0).size(), std::size_t(5));
    QCOMPARE(story.samples(1).back().time, 0.4);
    QCOMPARE(*story.lastTime(), 0.45);
    // Running again from the rewound moment continues the story from there.
    recordAt(story, 0.5);
    QCOMPARE(story.samples(0).size(), std::size_t(6));
  }

  void recordingAnEarlierTimeTruncatesThere() {
    BallStory story;
    story.watch({0});
    for (int k = 0; k <= 10; ++k) recordAt(story, 0.1 * k);
    recordAt(story, 0.0);  // a reset
    QCOMPARE(story.samples(0).size(), std::size_t(1));
    QCOMPARE(story.samples(0).front().time, 0.0);
    story.clear();
    QVERIFY(story.samples(0).empty());
    QVERIFY(!story.lastTime());
    QVERIFY(story.isWatched(0));
  }

  void ballEnergiesAddUpToTheSystems() {
    carom::Bodies bodies;
    bodies.mass = {2.0, 0.5};
    const Vec3 gravity(0, -9.81, 0);
    const std::vector<Vec3> positions = {Vec3(1, 2, 3), Vec3(-1, 0.5, 0)};
    const std::vector<Vec3> velocities = {Vec3(0, 3, 4), Vec3(1, 0, 0)};
    QCOMPARE(carom::ballKineticEnergy(2.0, velocities[0]), 25.0);
    QCOMPARE(carom::ballPotentialEnergy(2.0, gravity, positions[0]), 2.0 * 9.81 * 2.0);
    QCOMPARE(
        carom::ballKineticEnergy(2.0, velocities[0]) + carom::ballKineticEnergy(0.5, velocities[1]),
        carom::kineticEnergy(bodies, velocities));
    QCOMPARE(carom::ballPotentialEnergy(2.0, gravity, positions[0]) +
                 carom::ballPotentialEnergy(0.5, gravity, positions[1]),
             carom::potentialEnergy(bodies, gravity, positions));
  }
};

QTEST_APPLESS_MAIN(TestBallStory)
#include "test_ball_story.moc"
