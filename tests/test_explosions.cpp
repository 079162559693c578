// The explosion pool on made-up times: its limit, its fade and growth, and that only elapsed
// time matters, not how often it is updated.

#include "ui/render/explosion_pool.h"

#include <QtTest>

#include <cmath>

using carom::Vec3;
using carom::render::ExplosionPool;

class TestExplosions : public QObject {
  Q_OBJECT

 private slots:
  void neverMoreThanTheLimit();
  void fadesAndGrowsOverItsLifetime();
  void removedAfterItsLifetime();
  void drivenByTimeNotUpdates();
  void finishedOnesMakeRoom();
  void loweringTheLimitKeepsTheNewest();
};

void TestExplosions::neverMoreThanTheLimit() {
  ExplosionPool pool;
  QCOMPARE(pool.limit(), 20);
  for (int i = 0; i < 50; ++i) {
    const bool added = pool.add(Vec3(i, 0, 0), 1.0, 0.01 * i);
    QCOMPARE(added, i < 20);
    QVERIFY(pool.count() <= 20);
  }
  QCOMPARE(pool.count(), 20);
  QCOMPARE(pool.dropped(), std::uint64_t{30});
  // The first ones stay: new ones are dropped, old ones are not pushed out.
  QCOMPARE(pool.live().front().centre.x(), 0.0);
  QCOMPARE(pool.live().back().centre.x(), 19.0);

  ExplosionPool small(3);
  for (int i = 0; i < 10; ++i) small.add(Vec3::Zero(), 1.0, 0.0);
  QCOMPARE(small.count(), 3);
  QCOMPARE(small.dropped(), std::uint64_t{7});
}

void TestExplosions::fadesAndGrowsOverItsLifetime() {
  ExplosionPool pool;
  const double start = 10.0;
  const double size = 0.8;
  pool.add(Vec3(1, 2, 3), size, start);
  QCOMPARE(pool.live().size(), std::size_t{1});
  QCOMPARE(pool.live()[0].alpha, 1.0);
  QCOMPARE(pool.live()[0].scale, size);
  QCOMPARE(pool.live()[0].centre, Vec3(1, 2, 3));

  double lastAlpha = 1.0;
  double lastScale = size;
  for (int frame = 1; frame < 96; ++frame) {  // 1.6 s at 60 frames a second
    pool.update(start + frame / 60.0);
    QCOMPARE(pool.count(), 1);
    const ExplosionPool::Live e = pool.live()[0];
    QVERIFY2(e.alpha < lastAlpha && e.alpha > 0.0, qPrintable(QString::number(e.alpha)));
    QVERIFY(e.scale > lastScale);
    // Linear in time: alpha 1 to 0 and scale 1 to 2.8 times the size over the 96 frames.
    QVERIFY(std::abs(e.alpha - (1.0 - frame / 96.0)) < 1e-9);
    QVERIFY(std::abs(e.scale - size * (1.0 + 1.8 * frame / 96.0)) < 1e-9);
    lastAlpha = e.alpha;
    lastScale = e.scale;
  }
  // Nearly gone, and 1 + 1.8 times its size.
  QVERIFY(lastAlpha < 0.02);
  QVERIFY(std::abs(lastScale - size * 2.8) < 0.03);
}

void TestExplosions::removedAfterItsLifetime() {
  ExplosionPool pool;
  pool.add(Vec3::Zero(), 1.0, 0.0);
  pool.add(Vec3::Zero(), 1.0, 0.5);
  pool.update(1.599);
  QCOMPARE(pool.count(), 2);
  pool.update(1.6);
  QCOMPARE(pool.count(), 1);
  QVERIFY(std::abs(pool.live()[0].alpha - (1.0 - 1.1 / 1.6)) < 1e-9);
  pool.update(2.1);
  QVERIFY(pool.empty());
  QVERIFY(pool.live().empty());
  // A clock that goes back does not revive anything.
  pool.update(1.0);
  QVERIFY(pool.empty());
}

void TestExplosions::drivenByTimeNotUpdates() {
  ExplosionPool once;
  ExplosionPool often;
  for (int i = 0; i < 5; ++i) {
    once.add(Vec3(i, 0, 0), 1.0 + i, 0.2 * i);
    often.add(Vec3(i, 0, 0), 1.0 + i, 0.2 * i);
  }
  const double t = 1.7;
  once.update(t);
  for (int step = 0; step <= 1000; ++step) often.update(0.8 + (t - 0.8) * step / 1000.0);
  QCOMPARE(once.count(), often.count());
  QCOMPARE(once.count(), 4);  // the one born at 0 is finished
  const auto a = once.live();
  const auto b = often.live();
  for (std::size_t i = 0; i < a.size(); ++i) {
    QCOMPARE(a[i].centre, b[i].centre);
    QVERIFY(std::abs(a[i].alpha - b[i].alpha) < 1e-12);
    QVERIFY(std::abs(a[i].scale - b[i].scale) < 1e-12);
  }
}

void TestExplosions::finishedOnesMakeRoom() {
  ExplosionPool pool(2);
  QVERIFY(pool.add(Vec3::Zero(), 1.0, 0.0));
  QVERIFY(pool.add(Vec3::Zero(), 1.0, 0.1));
  QVERIFY(!pool.add(Vec3::Zero(), 1.0, 1.0));
  // At 1.65 the first is finished, without anyone calling update.
  QVERIFY(pool.add(Vec3(5, 0, 0), 1.0, 1.65));
  QCOMPARE(pool.count(), 2);
  QCOMPARE(pool.dropped(), std::uint64_t{1});
}

void TestExplosions::loweringTheLimitKeepsTheNewest() {
  ExplosionPool pool;
  for (int i = 0; i < 10; ++i) pool.add(Vec3(i, 0, 0), 1.0, 0.01 * i);
  pool.setLimit(4);
  QCOMPARE(pool.count(), 4);
  QCOMPARE(pool.live().front().centre.x(), 6.0);
  pool.setLimit(-3);
  QCOMPARE(pool.limit(), 0);
  QVERIFY(pool.empty());
  QVERIFY(!pool.add(Vec3::Zero(), 1.0, 1.0));
}

QTEST_APPLESS_MAIN(TestExplosions)
#include "test_explosions.moc"
