#pragma once
// An independent reference for contact times against finite shapes: it samples the true gap of
// the ball on its path finely and bisects, sharing nothing with the solver but the gap function
// the test gives it.

#include "sim/geometry/contact_time.h"

#include <QString>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace carom::testing {

// The gap between the ball's surface and the shape's for a ball centred at the given point.
using GapOf = std::function<double(const Vec3& centre)>;

inline Vec3 at(const BallPath& b, double t) {
  return b.position + b.velocity * t + 0.5 * b.acceleration * t * t;
}

// The first time the sampled gap is <= 0 (from > 0 at 0), narrowed by bisection; infinity if no
// sample finds one.
inline double referenceContact(const BallPath& b, const GapOf& gap, double horizon, int samples) {
  double previous = 0.0;
  for (int k = 1; k <= samples; ++k) {
    const double t = horizon * k / samples;
    if (gap(at(b, t)) <= 0.0) {
      double lo = previous, hi = t;
      for (int i = 0; i < 200 && hi - lo > 1e-15 * std::max(1.0, hi); ++i) {
        const double mid = 0.5 * (lo + hi);
        (gap(at(b, mid)) <= 0.0 ? hi : lo) = mid;
      }
      return lo;
    }
    previous = t;
  }
  return std::numeric_limits<double>::infinity();
}

// Whether the gap goes below -depth somewhere within `width` after t: a real entry that the
// coarse samples of the reference stepped over.
inline bool dipsBelow(const BallPath& b, const GapOf& gap, double t, double width, double depth) {
  for (int k = 0; k <= 20000; ++k)
    if (gap(at(b, t + width * k / 20000)) < -depth) return true;
  return false;
}

// Tallies of a series of throws compared with the reference.
struct ThrowTally {
  int hits = 0;   // throws the reference saw hit
  int finer = 0;  // contacts the solver found between the reference's samples
};

// The solver's contact time agrees with the reference to 1e-9 (relative beyond 1 s), and no
// contact the reference finds is missed; where the solver is earlier than the reference, or
// finds a contact it did not, the gap must be zero there and dip below it just after. Fails the
// current test otherwise (check QTest::currentTestFailed()).
inline void compareWithReference(const BallPath& ball, const GapOf& gap, double solved,
                                 double horizon, int samples, int throwNumber, ThrowTally& tally) {
  const double never = std::numeric_limits<double>::infinity();
  const double reference = referenceContact(ball, gap, horizon, samples);
  if (reference < never) {
    ++tally.hits;
    const double tolerance = 1e-9 * std::max(1.0, reference);
    QVERIFY2(solved <= reference + tolerance,
             qPrintable(QString("throw %1: solved %2, reference %3")
                            .arg(throwNumber)
                            .arg(solved, 0, 'g', 17)
                            .arg(reference, 0, 'g', 17)));
    if (solved >= reference - tolerance) return;
  } else if (solved == never) {
    return;
  }
  ++tally.finer;
  QVERIFY2(std::abs(gap(at(ball, solved))) < 1e-9 &&
               dipsBelow(ball, gap, solved, horizon / samples, 0.0),
           qPrintable(QString("throw %1: solved %2 (gap %3), reference %4")
                          .arg(throwNumber)
                          .arg(solved, 0, 'g', 17)
                          .arg(gap(at(ball, solved)))
                          .arg(reference, 0, 'g', 17)));
}

}  // namespace carom::testing
