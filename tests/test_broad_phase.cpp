// The broad phase of discrete steps and measurements (sim/broad_phase.h) against all pairs:
// every pair of balls within reach is a candidate, once, whatever the mix of sizes (one class,
// radius ratios up to 1e6, balls far outside a class's grid), and one size class keeps the
// order in which pairs were always visited.

#include "sim/stepped/broad_phase.h"

#include <QtTest>

#include <random>
#include <set>
#include <utility>
#include <vector>

namespace {

struct Balls {
  std::vector<carom::Vec3> centres;
  std::vector<double> radii;
};

// `count` balls in a cube of side `side`, radii drawn on a log scale from `smallest` to
// `largest`; overlaps allowed (measurements look at runs gone wrong too).
Balls randomBalls(int count, double side, double smallest, double largest, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Balls balls;
  for (int i = 0; i < count; ++i) {
    balls.centres.emplace_back(side * unit(random), side * unit(random), side * unit(random));
    balls.radii.push_back(smallest * std::pow(largest / smallest, unit(random)));
  }
  return balls;
}

using Pairs = std::set<std::pair<int, int>>;

Pairs pairsWithinReach(const Balls& balls, double margin) {
  Pairs pairs;
  const int n = static_cast<int>(balls.centres.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if ((balls.centres[i] - balls.centres[j]).norm() < balls.radii[i] + balls.radii[j] + margin)
        pairs.insert({i, j});
  return pairs;
}

}  // namespace

class TestBroadPhase : public QObject {
  Q_OBJECT

 private slots:
  void everyPairWithinReachOnce_data() {
    QTest::addColumn<double>("smallest");
    QTest::addColumn<double>("largest");
    QTest::addColumn<double>("margin");
    QTest::newRow("one size") << 0.1 << 0.1 << 0.0;
    QTest::newRow("one class") << 0.1 << 0.19 << 0.05;
    QTest::newRow("ratio 10") << 0.02 << 0.2 << 0.0;
    QTest::newRow("ratio 1e3") << 1e-3 << 1.0 << 0.0;
    QTest::newRow("ratio 1e6") << 1e-6 << 1.0 << 1e-3;
  }
  void everyPairWithinReachOnce() {
    QFETCH(double, smallest);
    QFETCH(double, largest);
    QFETCH(double, margin);
    for (unsigned seed = 1; seed <= 5; ++seed) {
      const Balls balls = randomBalls(600, 4.0, smallest, largest, seed);
      const Pairs expected = pairsWithinReach(balls, margin);
      carom::BallBins bins;
      bins.build(balls.centres, balls.radii, margin);
      Pairs seen;
      int visits = 0;
      bins.forEachCandidatePair([&](int i, int j) {
        QVERIFY(i < j);
        ++visits;
        seen.insert({i, j});
      });
      QCOMPARE(visits, int(seen.size()));  // no pair twice
      for (const auto& pair : expected)
        QVERIFY2(seen.count(pair), qPrintable(QString("%1-%2").arg(pair.first).arg(pair.second)));
      // And each ball's candidates, as the discrete steps' later passes ask for them.
      for (int i = 0; i < int(balls.centres.size()); ++i) {
        std::set<int> of;
        bins.forEachCandidateOf(i, [&](int j) {
          QVERIFY(j != i);
          of.insert(j);
        });
        for (const auto& [a, b] : expected)
          if (a == i || b == i) QVERIFY(of.count(a == i ? b : a));
      }
    }
  }

  void aBallFarFromTheOthersClassesHasNoCandidates() {
    // A huge ball far away from a cloud of small ones: the small class's grid lies wholly outside
    // its reach, and cells far outside a grid are no cells at all (no wrap, no overflow).
    Balls balls = randomBalls(200, 1.0, 0.01, 0.01, 3);
    balls.centres.emplace_back(1e15, -1e15, 1e15);
    balls.radii.push_back(10.0);
    carom::BallBins bins;
    bins.build(balls.centres, balls.radii, 0.0);
    int candidates = 0;
    bins.forEachCandidateOf(200, [&](int) { ++candidates; });
    QCOMPARE(candidates, 0);
    Pairs seen;
    bins.forEachCandidatePair([&](int i, int j) { seen.insert({i, j}); });
    for (const auto& pair : pairsWithinReach(balls, 0.0)) QVERIFY(seen.count(pair));
    for (const auto& pair : seen) QVERIFY(pair.second != 200);
  }

  void oneSizeVisitsPairsInCellOrder() {
    // One class: the pairs come ball by ball in index order, each ball's partners cell by cell,
    // as the discrete steps always took them (their results depend on it).
    const Balls balls = randomBalls(300, 2.0, 0.05, 0.05, 11);
    carom::BallBins bins;
    bins.build(balls.centres, balls.radii, 0.0);
    int lastFirst = -1;
    bins.forEachCandidatePair([&](int i, int) {
      QVERIFY(i >= lastFirst);
      lastFirst = i;
    });
  }
};

QTEST_APPLESS_MAIN(TestBroadPhase)
#include "test_broad_phase.moc"
