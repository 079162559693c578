// Tests for the contact-time root finder (sim/polynomial.h). The references do not share code with
// it: polynomials built from chosen roots, geometry evaluated directly, and signs evaluated in quad
// precision (__float128) with plain bisection and dense sampling.

#include <QTest>

#include "sim/geometry/polynomial.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <utility>
#include <vector>

using carom::firstEntry;
using carom::firstEntryQuadratic;
using carom::Polynomial;

// QVERIFY with a printf-style message that is only formatted on failure.
#define VERIFY(condition, ...)                                                             \
  do {                                                                                     \
    if (!(condition)) {                                                                    \
      QFAIL(qPrintable(QStringLiteral(#condition ": ") + QString::asprintf(__VA_ARGS__))); \
    }                                                                                      \
  } while (false)

namespace {

using Quad = __float128;
using Vec3 = Eigen::Vector3d;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kUnit = std::numeric_limits<double>::epsilon() / 2;
constexpr int kTop = carom::kMaxPolynomialDegree;

double ulpOf(double x) {
  x = std::abs(x);
  return std::nextafter(x, kInf) - x;
}

Polynomial poly(double c0, double c1 = 0, double c2 = 0, double c3 = 0, double c4 = 0) {
  return Polynomial{{c0, c1, c2, c3, c4}};
}

// f(t) in quad precision: for double coefficients and arguments, exact enough to be the truth.
Quad exactValue(const Polynomial& f, double t) {
  Quad value = f.c[kTop];
  for (int k = kTop - 1; k >= 0; --k) value = value * t + f.c[k];
  return value;
}

// sum |c_k| t^k: the scale of rounding errors in f(t).
double termSize(const Polynomial& f, double t) {
  double size = 0.0;
  for (int k = kTop; k >= 0; --k) size = size * std::abs(t) + std::abs(f.c[k]);
  return size;
}

// lead * prod (t - r) * prod ((t - re)^2 + im^2), expanded in quad precision and rounded once.
// `exact`, when given, tells whether every coefficient was a double already.
Polynomial fromRoots(double lead, const std::vector<double>& roots,
                     const std::vector<std::pair<double, double>>& complexPairs = {},
                     bool* exact = nullptr) {
  std::array<Quad, kTop + 3> c{};
  c[0] = lead;
  auto multiply = [&c](Quad q0, Quad q1, Quad q2) {  // by q0 + q1 t + q2 t^2
    std::array<Quad, kTop + 3> r{};
    for (int k = 0; k < kTop + 3; ++k) {
      r[k] += c[k] * q0;
      if (k >= 1) r[k] += c[k - 1] * q1;
      if (k >= 2) r[k] += c[k - 2] * q2;
    }
    c = r;
  };
  for (const double r : roots) multiply(-Quad(r), 1, 0);
  for (const auto& [re, im] : complexPairs) {
    multiply(Quad(re) * re + Quad(im) * im, -2 * Quad(re), 1);
  }
  Polynomial f;
  for (int k = 0; k <= kTop; ++k) f.c[k] = static_cast<double>(c[k]);
  if (exact) {
    *exact = true;
    for (int k = 0; k < kTop + 3; ++k) *exact = *exact && (k <= kTop ? Quad(f.c[k]) : 0) == c[k];
  }
  return f;
}

// f (t^2 b2 + t b1 + b0), rounded once per coefficient.
Polynomial timesQuadratic(const Polynomial& f, double b0, double b1, double b2) {
  Polynomial g;
  for (int k = 0; k <= kTop; ++k) {
    Quad sum = Quad(f.c[k]) * b0;
    if (k >= 1) sum += Quad(f.c[k - 1]) * b1;
    if (k >= 2) sum += Quad(f.c[k - 2]) * b2;
    g.c[k] = static_cast<double>(sum);
  }
  return g;
}

// The sign of f(t): from quad precision, or exactly from the factors f was built from (near a
// root of high multiplicity quad precision cannot tell).
using SignOf = std::function<int(double)>;

SignOf quadSign(const Polynomial& f) {
  return [&f](double t) {
    const Quad v = exactValue(f, t);
    return v > 0 ? 1 : (v < 0 ? -1 : 0);
  };
}

// lead * prod (t - r) with the complex pairs' factors positive: the sign, exactly.
SignOf factoredSign(double lead, const std::vector<double>& roots) {
  return [lead, roots](double t) {
    int sign = lead > 0 ? 1 : -1;
    for (const double r : roots) sign *= t > r ? 1 : (t < r ? -1 : 0);
    return sign;
  };
}

// Given f(lo) > 0 >= f(hi), bisects to adjacent doubles and returns the lower one.
double exactCrossing(const SignOf& sign, double lo, double hi) {
  for (;;) {
    const double mid = lo + (hi - lo) / 2;
    if (!(mid > lo && mid < hi)) return lo;
    (sign(mid) > 0 ? lo : hi) = mid;
  }
}

double exactCrossing(const Polynomial& f, double lo, double hi) {
  return exactCrossing(quadSign(f), lo, hi);
}

// The rule at t = 0: touching or overlapping and closing in (first non-zero derivative < 0).
bool entersAtZero(const Polynomial& f) {
  if (f.c[0] > 0) return false;
  for (int k = 1; k <= kTop; ++k) {
    if (f.c[k] != 0) return f.c[k] < 0;
  }
  return false;
}

// The first entry of f on [0, tMax] given (approximately) all its real roots: the first root at
// which the exact sign goes from + (just before) to - (just after).
double entryFromRoots(const Polynomial& f, std::vector<double> roots, double tMax,
                      const SignOf& sign) {
  if (entersAtZero(f)) return 0.0;
  std::sort(roots.begin(), roots.end());
  roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
  std::erase_if(roots, [](double r) { return r <= 0; });
  for (std::size_t i = 0; i < roots.size() && roots[i] <= tMax; ++i) {
    const double before = ((i == 0 ? 0.0 : roots[i - 1]) + roots[i]) / 2;
    const double after = (roots[i] + (i + 1 < roots.size() ? roots[i + 1] : 2 * roots[i] + 1)) / 2;
    if (sign(before) > 0 && sign(after) < 0) return exactCrossing(sign, before, after);
  }
  return kInf;
}

double entryFromRoots(const Polynomial& f, const std::vector<double>& roots, double tMax) {
  return entryFromRoots(f, roots, tMax, quadSign(f));
}

// The first entry seen by `samples` evenly spaced exact samples on [0, tMax], bisected. Dips
// narrower than the spacing are missed.
double entryFromSamples(const Polynomial& f, double tMax, int samples) {
  if (entersAtZero(f)) return 0.0;
  bool positive = f.c[0] >= 0;
  double previous = 0.0;
  for (int j = 1; j <= samples; ++j) {
    const double t = j == samples ? tMax : tMax * j / samples;
    const Quad v = exactValue(f, t);
    if (positive && v < 0) return exactCrossing(f, previous, t);
    if (v != 0) positive = v > 0;
    previous = t;
  }
  return kInf;
}

// Whether f really enters at t: not negative there and negative somewhere in (t, limit], looked
// for at geometrically growing distances so that narrow dips are found too.
bool entersAt(const Polynomial& f, double t, double limit) {
  if (exactValue(f, t) < 0) return false;
  for (double step = std::max(ulpOf(t), 1e-300); t + step <= limit; step *= 1.5) {
    if (exactValue(f, t + step) < 0) return true;
  }
  return exactValue(f, limit) < 0;
}

// How far a computed root may be from the exact one: a few ulps, or for ill-conditioned roots the
// distance over which f, grown from its Taylor terms at r, stays within the error of
// double-double evaluation (for a simple root that error divided by the slope).
double rootTolerance(const Polynomial& f, double r) {
  // Twice the finder's own bound for double-double evaluation, 2 (2n u)^2 (n at least 4).
  const double n = std::max(f.degree(), 4);
  const double error = 4 * (2 * n * kUnit) * (2 * n * kUnit) * termSize(f, r);
  double band = kInf;
  for (int k = 1; k <= kTop; ++k) {
    Quad taylor = 0;  // f^(k)(r) / k!, in quad so that the terms of a multiple root cancel
    for (int j = k; j <= kTop; ++j) {
      Quad term = f.c[j];
      for (int i = 0; i < k; ++i) term = term * (j - i) / (i + 1);
      for (int i = k; i < j; ++i) term *= r;
      taylor += term;
    }
    const double size = std::abs(static_cast<double>(taylor));
    if (size != 0) band = std::min(band, std::pow(error / size, 1.0 / k));
  }
  return 4 * ulpOf(r) + band;
}

QByteArray describe(const Polynomial& f, double tMax) {
  QString text = "f = {";
  for (int k = 0; k <= std::max(f.degree(), 0); ++k)
    text += QString::asprintf(k == 0 ? "%.17g" : ", %.17g", f.c[k]);
  return (text + QString::asprintf("}, tMax = %.17g", tMax)).toLatin1();
}

// The entry t matches the exact crossing `expected` and does not lie in overlap.
void checkEntry(const char* what, const Polynomial& f, double tMax, double t, double expected,
                const SignOf& sign = {}) {
  const QByteArray context = describe(f, tMax);
  VERIFY(!std::isnan(t), "%s: NaN (%s)", what, context.data());
  if (std::isinf(expected) || expected == 0) {
    VERIFY(t == expected, "%s: got %.17g, expected %.17g (%s)", what, t, expected, context.data());
    return;
  }
  VERIFY(std::abs(t - expected) <= rootTolerance(f, expected), "%s: got %.17g, expected %.17g (%s)",
         what, t, expected, context.data());
  VERIFY((sign ? sign : quadSign(f))(t) >= 0, "%s: %.17g is in overlap (%s)", what, t,
         context.data());
}

// A ball centre on a parabola, p(t) = p0 + v t + g t^2 / 2.
struct Flight {
  Vec3 start;
  Vec3 velocity;
  Vec3 gravity;
  Vec3 at(double t) const { return start + velocity * t + 0.5 * t * t * gravity; }
};

// The line of a cylinder; direction is a unit vector.
struct Axis {
  Vec3 point;
  Vec3 direction;
  Vec3 across(const Vec3& w) const { return w - direction * direction.dot(w); }
  double distance(const Vec3& x) const { return across(x - point).norm(); }
};

// |P(p(t) - c)|^2 - rho^2 with P the projector orthogonal to the axis.
Polynomial gapPolynomial(const Flight& ball, const Axis& axis, double rho) {
  const Vec3 u0 = axis.across(ball.start - axis.point);
  const Vec3 u1 = axis.across(ball.velocity);
  const Vec3 u2 = axis.across(0.5 * ball.gravity);
  return poly(u0.squaredNorm() - rho * rho, 2 * u0.dot(u1), u1.squaredNorm() + 2 * u0.dot(u2),
              2 * u1.dot(u2), u2.squaredNorm());
}

// Smallest distance of the flight from the axis over [0, window]: dense sampling, then golden
// section around the best sample. Also returns when it happens.
std::pair<double, double> closestApproach(const Flight& ball, const Axis& axis, double window) {
  const int samples = 20000;
  int best = 0;
  double bestDistance = kInf;
  for (int j = 0; j <= samples; ++j) {
    const double d = axis.distance(ball.at(window * j / samples));
    if (d < bestDistance) {
      bestDistance = d;
      best = j;
    }
  }
  double lo = window * std::max(best - 1, 0) / samples;
  double hi = window * std::min(best + 1, samples) / samples;
  const double golden = (std::sqrt(5.0) - 1) / 2;
  for (int i = 0; i < 200; ++i) {
    const double x1 = hi - golden * (hi - lo);
    const double x2 = lo + golden * (hi - lo);
    (axis.distance(ball.at(x1)) < axis.distance(ball.at(x2)) ? hi : lo) = (x1 + x2) / 2;
  }
  const double t = (lo + hi) / 2;
  return {std::min(bestDistance, axis.distance(ball.at(t))), t};
}

// The ball at the returned time t is at distance rho from the axis, just before it is farther,
// and nowhere on [0, t) closer.
void checkFlightEntry(const char* what, const Flight& ball, const Axis& axis, double rho, double t,
                      double tMax) {
  VERIFY(std::isfinite(t) && t >= 0 && t <= tMax, "%s: t = %.17g", what, t);
  const double d = axis.distance(ball.at(t));
  VERIFY(std::abs(d - rho) <= 1e-9 * rho, "%s: distance %.17g at t = %.17g, rho %.17g", what, d, t,
         rho);
  if (t > 0) {
    const double before = t - std::max(1e-7 * t, 1e-300);
    const double dBefore = axis.distance(ball.at(before));
    VERIFY(dBefore > rho, "%s: distance %.17g before t = %.17g, rho %.17g", what, dBefore, t, rho);
  }
  const int samples = 20000;
  for (int j = 0; j < samples; ++j) {
    const double s = t * j / samples;
    const double ds = axis.distance(ball.at(s));
    VERIFY(ds > rho * (1 - 1e-12), "%s: earlier overlap at %.17g (distance %.17g, rho %.17g)", what,
           s, ds, rho);
  }
}

}  // namespace

class TestPolynomial : public QObject {
  Q_OBJECT

 private slots:
  void evaluatesAndDifferentiates();
  void quadraticKnownCases();
  void quadraticStability();
  void quarticKnownRoots();
  void touchingAtStart();
  void degenerateAndExtreme();
  void ballUnderGravityVsTiltedCylinder();
  void randomExactRoots();
  void randomSeparatedRoots();
  void randomCoefficientsAgainstSampling();
  void generalPathMatchesClosedForm();
  void extremeInputsStaySane();
};

void TestPolynomial::evaluatesAndDifferentiates() {
  const Polynomial f = poly(1, 2, 3, 4, 5);
  QCOMPARE(f(2.0), 1.0 + 4 + 12 + 32 + 80);
  QCOMPARE(f(0.0), 1.0);
  const Polynomial d = f.derivative();
  QCOMPARE(d.c, (std::array<double, kTop + 1>{2, 6, 12, 20, 0}));
  Polynomial octic;
  octic.c[8] = 1;
  octic.c[5] = -2;
  QCOMPARE(octic(2.0), 256.0 - 64);
  QCOMPARE(octic.degree(), 8);
  QCOMPARE(octic.derivative().c, (std::array<double, kTop + 1>{0, 0, 0, 0, -10, 0, 0, 8, 0}));
  QCOMPARE(d.derivative().derivative().derivative().derivative().degree(), -1);
  QCOMPARE(f.degree(), 4);
  QCOMPARE(poly(1, 2, 3).degree(), 2);
  QCOMPARE(poly(0, 0, 0, 1e-300).degree(), 3);
  QCOMPARE(poly(-2).degree(), 0);
  QCOMPARE(poly(0).degree(), -1);
}

void TestPolynomial::quadraticKnownCases() {
  struct Case {
    const char* name;
    double a, b, c, tMax, expected;
  };
  const double below1 = std::nextafter(1.0, 0.0);
  const Case cases[] = {
      {"falls through the smaller root", 1, -3, 2, kInf, 1},
      {"both roots in the past", 1, 3, 2, kInf, kInf},
      {"opening downwards: the larger root", -1, 2, 3, kInf, 3},
      {"linear approaching", 0, -2, 4, kInf, 2},
      {"linear receding", 0, 2, 4, kInf, kInf},
      {"constant apart", 0, 0, 1, kInf, kInf},
      {"constant overlap", 0, 0, -1, kInf, kInf},
      {"zero polynomial", 0, 0, 0, kInf, kInf},
      {"tangential touch", 1, -2, 1, kInf, kInf},
      {"tangential touch at 1.5", 4, -12, 9, kInf, kInf},
      {"tangential touch at a non-representable time", 9, -6, 1, kInf, kInf},
      {"tangential touch, tiny scale", 0x1p-60, -6 * 0x1p-60, 9 * 0x1p-60, kInf, kInf},
      {"minimum 2^-40 below zero", 1, -2, 1 - 0x1p-40, kInf, 1 - 0x1p-20},
      {"minimum just above zero", 1, -2, 1 + 0x1p-52, kInf, kInf},
      {"clustered roots 1 and 1 + 2^-30", 1, -(2 + 0x1p-30), 1 + 0x1p-30, kInf, 1},
      {"crossing exactly at the horizon", 1, -3, 2, 1, 1},
      {"horizon an ulp before the crossing", 1, -3, 2, below1, kInf},
      {"zero horizon", 1, -3, 2, 0, kInf},
      {"overlap opening, then re-entering", -2, 3, -1, kInf, 1},
      {"overlap opening for good", 1, 1, -1, kInf, kInf},
      {"overlap opening, horizon before re-entry", -2, 3, -1, 0.75, kInf},
      {"overlap approaching", 1, -1, -1, kInf, 0},
      {"touching approaching", 1, -1, 0, kInf, 0},
      {"touching approaching by curvature", -1, 0, 0, kInf, 0},
      {"touching approaching, zero horizon", 1, -1, 0, 0, 0},
      {"touching opening", 1, 1, 0, kInf, kInf},
      {"touching at a minimum", 1, 0, 0, kInf, kInf},
      {"touching opening, then falling", -1, 1, 0, kInf, 1},
      {"huge coefficients", 0x1p1000, -3 * 0x1p1000, 2 * 0x1p1000, kInf, 1},
      {"tiny coefficients", 0x1p-1000, -3 * 0x1p-1000, 2 * 0x1p-1000, kInf, 1},
      {"subnormal coefficients", 0x1p-1072, -3 * 0x1p-1072, 2 * 0x1p-1072, kInf, 1},
      {"negative horizon", 1, -3, 2, -1, kInf},
      {"NaN horizon", 1, -3, 2, std::nan(""), kInf},
      {"NaN coefficient", std::nan(""), -3, 2, kInf, kInf},
      {"infinite coefficient", 1, -kInf, 2, kInf, kInf},
  };
  for (const Case& k : cases) {
    const Polynomial f = poly(k.c, k.b, k.a);
    checkEntry(k.name, f, k.tMax, firstEntryQuadratic(k.a, k.b, k.c, k.tMax), k.expected);
    if (QTest::currentTestFailed()) return;
    checkEntry(k.name, f, k.tMax, firstEntry(f, k.tMax), k.expected);
    if (QTest::currentTestFailed()) return;
  }
}

void TestPolynomial::quadraticStability() {
  // Rounded coefficients: the reference is the exact crossing of the double polynomial, found by
  // quad-precision bisection in a bracket around the intended root.
  struct Case {
    const char* name;
    double a, b, c, lo, hi;
  };
  const Case cases[] = {
      {"roots 1e-12 and 1e12", 1, -(1e12 + 1e-12), 1, 0.5e-12, 2e-12},
      {"root 1e-14 next to 1", 1, -(1 + 1e-14), 1e-14, 0.5e-14, 2e-14},
      {"root 1e-300 next to 1", 1, -1, 1e-300, 0.5e-300, 2e-300},
      {"subnormal root", 1, -1, 1e-310, 0.5e-310, 2e-310},
      {"a = 1e-30: roots 1 and 1e30", 1e-30, -1, 1, 0.5, 2},
      {"a = 1e30: roots 1e-15 and 2e-15", 1e30, -3e15, 2, 0.5e-15, 1.5e-15},
      {"a = -1e-30, b = 1e30: root 1e60", -1e-30, 1e30, 1, 0.5e60, 2e60},
      {"minimum 2^-53 below zero", 1, -2, 1 - 0x1p-53, 0.99, 1},
      {"minimum 1e-12 below zero, scaled 1e-30", 1e-30, -2e-30, 1e-30 * (1 - 1e-12), 0.99, 1},
      {"minimum 1e-12 below zero, scaled 1e30", 1e30, -2e30, 1e30 * (1 - 1e-12), 0.99, 1},
  };
  for (const Case& k : cases) {
    const Polynomial f = poly(k.c, k.b, k.a);
    QVERIFY2(exactValue(f, k.lo) > 0 && exactValue(f, k.hi) < 0, k.name);
    const double expected = exactCrossing(f, k.lo, k.hi);
    checkEntry(k.name, f, kInf, firstEntryQuadratic(k.a, k.b, k.c, kInf), expected);
    if (QTest::currentTestFailed()) return;
    checkEntry(k.name, f, kInf, firstEntry(f, kInf), expected);
    if (QTest::currentTestFailed()) return;
  }
  QCOMPARE(firstEntryQuadratic(1e-30, 1e30, 1, kInf), kInf);   // both roots negative
  QCOMPARE(firstEntryQuadratic(1e30, -1, 1e-30, kInf), kInf);  // no real root
}

void TestPolynomial::quarticKnownRoots() {
  struct Case {
    const char* name;
    Polynomial f;
    double tMax;
    double expected;
  };
  const double below1 = std::nextafter(1.0, 0.0);
  const Case cases[] = {
      {"four roots: the first descending one", fromRoots(1, {1, 2, 3, 4}), kInf, 1},
      {"four roots, overlapping at 0: the second", fromRoots(-1, {1, 2, 3, 4}), kInf, 2},
      {"four roots, crossing at the horizon", fromRoots(1, {1, 2, 3, 4}), 1, 1},
      {"four roots, horizon an ulp early", fromRoots(1, {1, 2, 3, 4}), below1, kInf},
      {"four roots, zero horizon", fromRoots(1, {1, 2, 3, 4}), 0, kInf},
      {"four small roots: the second descending", fromRoots(-1, {0.25, 0.5, 0.75, 1}), kInf, 0.5},
      {"cubic overlapping and opening", fromRoots(1, {1, 2, 3}), kInf, 2},
      {"cubic overlapping and opening, short horizon", fromRoots(1, {1, 2, 3}), 1.5, kInf},
      {"cubic falling", fromRoots(-1, {1, 2, 3}), kInf, 1},
      {"double root touches, then a crossing", fromRoots(1, {1, 1, 3, 4}), kInf, 3},
      {"double root touches only", fromRoots(1, {1, 1, -1, -2}), kInf, kInf},
      {"double root touched from below", fromRoots(-1, {1, 1, -1, -2}), kInf, kInf},
      {"triple root crossing", fromRoots(-1, {1, 1, 1, -2}), kInf, 1},
      {"quadruple root touch", fromRoots(1, {0.5, 0.5, 0.5, 0.5}), kInf, kInf},
      {"quadruple root touched from below", fromRoots(-1, {0.5, 0.5, 0.5, 0.5}), kInf, kInf},
      {"dip 2^-40 below a double root", fromRoots(1, {1 - 0x1p-20, 1 + 0x1p-20, -1, -2}), kInf,
       1 - 0x1p-20},
      {"clustered roots 1 and 1 + 2^-30", fromRoots(1, {1, 1 + 0x1p-30, 4, 5}), kInf, 1},
      {"far root 1e9", fromRoots(-1, {1e9, -1, -2, -3}), kInf, 1e9},
      {"far root 1e9, horizon short of it", fromRoots(-1, {1e9, -1, -2, -3}), 0.999e9, kInf},
      {"touch at 1/3 only", poly(2, -9, 1, 21, 9), kInf, kInf},        // (3t - 1)^2 (t + 1)(t + 2)
      {"touch at 1/3, crossing at 2", poly(2, -13, 24, -9), kInf, 2},  // (3t - 1)^2 (2 - t)
      {"leading zero coefficient", poly(-6, 11, -6, 1, 0), kInf, 2},
      {"no real roots", fromRoots(2, {}, {{1, 0.5}, {3, 0.25}}), kInf, kInf},
      {"pure quartic, touching", poly(0, 0, 0, 0, 1), kInf, kInf},
  };
  for (const Case& k : cases) {
    checkEntry(k.name, k.f, k.tMax, firstEntry(k.f, k.tMax), k.expected);
    if (QTest::currentTestFailed()) return;
  }

  // Rounded coefficients: the reference decides with exact signs between the intended roots.
  struct Rounded {
    const char* name;
    double lead;
    std::vector<double> roots;
  };
  const Rounded rounded[] = {
      {"root 1e-14", 1, {1e-14, 1, 2, 3}},
      {"root 1e-14, overlapping", -1, {1e-14, 1, 2, 3}},
      {"clustered roots 1 and 1 + 1e-9", 1, {1, 1 + 1e-9, 4, 5}},
      {"clustered roots 0.1 and 0.1 + 1e-7", 1, {0.1, 0.1 + 1e-7, 0.3, 0.7}},
      {"roots 1/3, 2/3, 5/7", -3, {1.0 / 3, 2.0 / 3, 5.0 / 7, -0.1}},
      {"roots spread 1e-6 to 1e6", 1, {1e-6, 1e-3, 1e3, 1e6}},
  };
  for (const Rounded& k : rounded) {
    const Polynomial f = fromRoots(k.lead, k.roots);
    const double expected = entryFromRoots(f, k.roots, kInf);
    QVERIFY2(std::isfinite(expected), k.name);
    checkEntry(k.name, f, kInf, firstEntry(f, kInf), expected);
    if (QTest::currentTestFailed()) return;
  }
}

void TestPolynomial::touchingAtStart() {
  // Touching or overlapping and approaching fires at once, whatever the derivative that decides.
  const Polynomial approaching[] = {
      poly(0, -1, 0, 0, 1),  poly(0, 0, -1, 0, 1),         poly(0, 0, 0, -1, 1),
      poly(0, 0, 0, 0, -1),  poly(-0.0, -1, 5, 5, 5),      poly(-1, -1, 0, 0, 1),
      poly(-1, 0, -1, 1, 1), poly(-1e-300, -1e-300, 0, 1), poly(0, -1e-300, 1e300, 1e300, 1e300),
  };
  for (const Polynomial& f : approaching) {
    QCOMPARE(firstEntry(f, kInf), 0.0);
    QCOMPARE(firstEntry(f, 0.0), 0.0);
    QCOMPARE(firstEntry(f, 1e-300), 0.0);
  }
  QCOMPARE(firstEntryQuadratic(1, -1, 0, kInf), 0.0);
  QCOMPARE(firstEntryQuadratic(-1, 0, 0, kInf), 0.0);
  QCOMPARE(firstEntryQuadratic(0, -1, -0.0, 0.0), 0.0);

  // Touching and opening does not fire; a later crossing does.
  QCOMPARE(firstEntry(fromRoots(-1, {0, 1, -2}), kInf), 1.0);  // t (1 - t)(t + 2)
  QCOMPARE(firstEntry(poly(0, 0, 1, -1), kInf), 1.0);          // t^2 (1 - t)
  QCOMPARE(firstEntry(poly(0, 0, 0, 1, -1), kInf), 1.0);       // t^3 (1 - t)
  QCOMPARE(firstEntry(poly(0, 1, 0, 0, 1), kInf), kInf);       // opening for good
  // Opening for 1e-300, then falling: near that crossing f is ~1e-600, far below the doubles.
  const Polynomial slowly = poly(0, 1e-300, -1, 0, 0.5);
  checkEntry("opening for 1e-300", slowly, kInf, firstEntry(slowly, kInf),
             exactCrossing(slowly, 0.5e-300, 2e-300));
  if (QTest::currentTestFailed()) return;
  QCOMPARE(firstEntryQuadratic(-1, 1, 0, kInf), 1.0);

  // Overlapping and opening skips to the next entry after f has been positive.
  QCOMPARE(firstEntry(fromRoots(1, {1, 2, 3}), kInf), 2.0);
  QCOMPARE(firstEntry(fromRoots(-1, {1, 2, 3, 4}), kInf), 2.0);
  QCOMPARE(firstEntry(fromRoots(-1, {1, 2, 3, 4}), 1.99), kInf);
  QCOMPARE(firstEntry(poly(-1, 1, 0, 0, 1), kInf), kInf);  // opening for good
  QCOMPARE(firstEntryQuadratic(-2, 3, -1, kInf), 1.0);
}

void TestPolynomial::degenerateAndExtreme() {
  QCOMPARE(firstEntry(Polynomial{}, kInf), kInf);
  QCOMPARE(firstEntry(Polynomial{}, 0.0), kInf);
  QCOMPARE(firstEntryQuadratic(0, 0, 0, kInf), kInf);

  // Scaling the coefficients changes nothing, from 1e-300 to 1e300.
  for (const double scale : {1e-300, 1e-30, 1.0, 1e30, 1e300}) {
    Polynomial f = fromRoots(1, {1, 2, 3, 4});
    for (double& c : f.c) c *= scale;  // rounded: the roots move by round-off
    checkEntry("scaled coefficients", f, kInf, firstEntry(f, kInf), exactCrossing(f, 0.5, 1.5));
    if (QTest::currentTestFailed()) return;
    for (double& c : f.c) c = -c;
    checkEntry("scaled coefficients, overlapping", f, kInf, firstEntry(f, kInf),
               exactCrossing(f, 1.5, 2.5));
    if (QTest::currentTestFailed()) return;
  }
  // Scaling time: roots lambda * {1, 2, 3, 4}, coefficients spanning lambda^4.
  for (const double lambda : {1e-8, 1e-3, 1e3, 1e8}) {
    const Polynomial f = fromRoots(1, {lambda, 2 * lambda, 3 * lambda, 4 * lambda});
    const double expected = exactCrossing(f, 0.5 * lambda, 1.5 * lambda);
    checkEntry("scaled time", f, kInf, firstEntry(f, kInf), expected);
    if (QTest::currentTestFailed()) return;
  }

  // Leading coefficients tiny next to the others. A touch made a shallow crossing by a tiny
  // negative quartic term, and the far crossing that term causes.
  {
    const Polynomial f = poly(1, -2, 1, 0, -1e-20);  // (t - 1)^2 - 1e-20 t^4
    checkEntry("tiny negative quartic term", f, kInf, firstEntry(f, kInf),
               exactCrossing(f, 0.5, 1.0));
    if (QTest::currentTestFailed()) return;
    const Polynomial g = poly(2, -3, 1, 0, 1e-30);  // (t - 1)(t - 2) + 1e-30 t^4
    checkEntry("tiny positive quartic term", g, kInf, firstEntry(g, kInf), 1.0);
    if (QTest::currentTestFailed()) return;
    const Polynomial h = poly(1, 1, 0, 1e-40, -1e-60);  // crossing near 1e20
    const double expected = exactCrossing(h, 1e19, 1e21);
    checkEntry("tiny quartic term, huge root", h, kInf, firstEntry(h, kInf), expected);
    if (QTest::currentTestFailed()) return;
    const Polynomial k = poly(2, -3, 1, 1e-300, 1e-320);  // subnormal leading coefficient
    checkEntry("subnormal leading coefficient", k, kInf, firstEntry(k, kInf), 1.0);
    if (QTest::currentTestFailed()) return;
  }

  // Coefficients spanning more than the double range at one scale: terms overflow or underflow
  // away from the crossing (found by stress testing).
  {
    const Polynomial f = poly(9.5517330598169835e+242, -7.8211496984216139e+295,
                              2.0208054541038458e-202, 6.3445517040667159e+40,
                              -2.4267875899985811e-95);  // crossing near 1.2e-53
    const double tMax = 9.2442764238009618e+152;
    checkEntry("extreme span, early crossing", f, tMax, firstEntry(f, tMax),
               exactCrossing(f, 1e-53, 1.5e-53));
    if (QTest::currentTestFailed()) return;
    const Polynomial g = poly(5.1146429974981216e+251, 1.7691481983110929e+151, 0,
                              -3.5526588354887071e-295, -2.68640371793766e-254);
    checkEntry("extreme span, far crossing", g, kInf, firstEntry(g, kInf),
               exactCrossing(g, 1e134, 1e136));
    if (QTest::currentTestFailed()) return;
    // Always negative (4ac outweighs b^2 by 1e31), though b^2 alone would suggest two roots.
    QCOMPARE(firstEntryQuadratic(-5.3864964915851905e+296, 2.4716324949458143e+41,
                                 -5.5285268417156413e-184, kInf),
             kInf);
  }

  // Horizons: zero, infinite, invalid.
  const Polynomial f = fromRoots(1, {1, 2, 3, 4});
  QCOMPARE(firstEntry(f, 0.0), kInf);
  QCOMPARE(firstEntry(f, kInf), 1.0);
  QCOMPARE(firstEntry(f, -1.0), kInf);
  QCOMPARE(firstEntry(f, std::nan("")), kInf);
  QCOMPARE(firstEntry(f, -kInf), kInf);
  // Non-finite coefficients.
  for (int k = 0; k <= kTop; ++k) {
    for (const double bad : {std::nan(""), kInf, -kInf}) {
      Polynomial g = f;
      g.c[k] = bad;
      QCOMPARE(firstEntry(g, kInf), kInf);
      QCOMPARE(firstEntry(g, 10.0), kInf);
    }
  }
}

void TestPolynomial::ballUnderGravityVsTiltedCylinder() {
  const Vec3 gravity(0, -9.81, 0);
  const Vec3 centre(0.3, -0.2, 0.7);
  auto tilted = [](double tilt, double azimuth) {
    return Vec3(std::sin(tilt) * std::cos(azimuth), std::cos(tilt),
                std::sin(tilt) * std::sin(azimuth));
  };
  const Vec3 directions[] = {
      Vec3::UnitY(),     tilted(1e-7, 0.4), tilted(0.4, 0.3), tilted(0.9, 2.0),
      tilted(1.3, -1.1), Vec3::UnitX(),     Vec3::UnitZ(),    tilted(1.5707, 0.7),
  };
  int hits = 0;
  for (const Vec3& direction : directions) {
    const Axis axis{centre, direction.normalized()};
    // Two unit vectors across the axis.
    const Vec3 e1 = axis.direction.cross(Vec3(0.3, 0.5, 0.8)).normalized();
    const Vec3 e2 = axis.direction.cross(e1);

    // Head-on throws from two sides, unlimited horizon.
    const Flight headOn[] = {
        {centre + 4 * e1 + 0.5 * axis.direction, -10 * e1 + 0.3 * e2 + axis.direction, gravity},
        {centre - 6 * e2, 15 * e2 - 2 * axis.direction + 0.5 * e1, gravity},
        {centre + 3 * e1 + 3 * e2, -8 * e1 - 8 * e2, gravity},
    };
    for (const Flight& ball : headOn) {
      const double rho = 1.0;
      const double t = firstEntry(gapPolynomial(ball, axis, rho), kInf);
      checkFlightEntry("head-on", ball, axis, rho, t, kInf);
      if (QTest::currentTestFailed()) return;
      ++hits;
    }

    // Grazing: radius sums just above and just below the closest approach in the window.
    const Flight passing[] = {
        {centre + 5 * e1 + 1.5 * e2, -8 * e1 + 0.2 * axis.direction, gravity},
        {centre - 4 * e2 + 0.8 * e1, 6 * e2 - 0.5 * e1 + axis.direction, gravity},
    };
    for (const Flight& ball : passing) {
      const double window = 1.2;
      const auto [closest, when] = closestApproach(ball, axis, window);
      QVERIFY(closest > 1e-3 && when > 0.01 && when < window - 0.01);
      const double rhoHit = closest * (1 + 1e-6);
      const double tHit = firstEntry(gapPolynomial(ball, axis, rhoHit), window);
      checkFlightEntry("grazing hit", ball, axis, rhoHit, tHit, window);
      if (QTest::currentTestFailed()) return;
      QVERIFY(std::abs(tHit - when) < 0.05);
      ++hits;
      const double rhoMiss = closest * (1 - 1e-6);
      QCOMPARE(firstEntry(gapPolynomial(ball, axis, rhoMiss), window), kInf);
    }

    // Starting in contact: approaching fires at once, opening does not.
    const double rho = 0.75;
    const Flight touching{centre + rho * e1 + 0.2 * axis.direction, -3 * e1 + axis.direction,
                          gravity};
    QVERIFY(firstEntry(gapPolynomial(touching, axis, rho), kInf) <= 1e-12);
    const Flight leaving{centre + rho * e1 + 0.2 * axis.direction, 3 * e1 + axis.direction,
                         gravity};
    const double tLeave = firstEntry(gapPolynomial(leaving, axis, rho), kInf);
    QVERIFY(tLeave > 0.01);
    if (std::isfinite(tLeave)) {  // fell back onto the cylinder
      checkFlightEntry("falling back", leaving, axis, rho, tLeave, kInf);
      if (QTest::currentTestFailed()) return;
    }
  }
  QCOMPARE(hits, 5 * static_cast<int>(std::size(directions)));
}

void TestPolynomial::randomExactRoots() {
  // Roots k/8 scaled by a power of two: every coefficient is exact, so double and touching roots
  // are what they claim to be, and roots at 0 test the rule at t = 0. Above degree 4 the
  // numerators are smaller, so that products of eight of them stay exact too.
  std::mt19937_64 rng(20240611);
  std::uniform_int_distribution<int> wideNumerator(-16, 96);
  std::uniform_int_distribution<int> narrowNumerator(-4, 24);
  std::uniform_int_distribution<int> exponent(-20, 20);
  std::uniform_int_distribution<int> degreeOf(2, kTop);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int entries = 0;
  for (int i = 0; i < 6000; ++i) {
    const double scale = std::ldexp(1.0, exponent(rng));
    const int degree = degreeOf(rng);
    const auto numerator = [&](std::mt19937_64& g) {
      return degree <= 4 ? wideNumerator(g) : narrowNumerator(g);
    };
    std::vector<double> roots;
    std::vector<std::pair<double, double>> pairs;
    while (static_cast<int>(roots.size() + 2 * pairs.size()) < degree) {
      const double u = unit(rng);
      if (u < 0.15 && roots.size() + 2 * pairs.size() + 2 <= static_cast<std::size_t>(degree)) {
        pairs.emplace_back(scale * numerator(rng) / 8, scale * (1 + numerator(rng) % 4 + 16) / 8);
      } else if (u < 0.35 && !roots.empty()) {
        roots.push_back(roots.back());  // a repeated root
      } else {
        roots.push_back(scale * numerator(rng) / 8);
      }
    }
    const double lead = (unit(rng) < 0.5 ? -1 : 1) * std::ldexp(1.0, exponent(rng) / 2);
    bool exact = false;
    const Polynomial f = fromRoots(lead, roots, pairs, &exact);
    VERIFY(exact, "coefficients rounded (%s)", describe(f, kInf).data());
    double tMax = kInf;
    const double u = unit(rng);
    if (u < 0.2 && !roots.empty()) {
      tMax = std::abs(roots[0]);  // a root exactly at the horizon
    } else if (u < 0.5) {
      tMax = scale * 12 * unit(rng);
    }
    const SignOf sign = factoredSign(lead, roots);
    const double expected = entryFromRoots(f, roots, tMax, sign);
    const double t = firstEntry(f, tMax);
    checkEntry("random exact roots", f, tMax, t, expected, sign);
    if (QTest::currentTestFailed()) return;
    if (f.degree() <= 2) {
      checkEntry("random exact roots (closed form)", f, tMax,
                 firstEntryQuadratic(f.c[2], f.c[1], f.c[0], tMax), expected, sign);
      if (QTest::currentTestFailed()) return;
    }
    entries += std::isfinite(expected) && expected > 0;
  }
  QVERIFY(entries > 500);  // the sample exercises crossings, not just misses
}

void TestPolynomial::randomSeparatedRoots() {
  // Arbitrary double roots, at least 1e-3 of the scale apart, at scales from 1e-6 to 1e6.
  std::mt19937_64 rng(987654321);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> degreeOf(2, kTop);
  int entries = 0;
  for (int i = 0; i < 5000; ++i) {
    const double scale = std::pow(10.0, -6 + 12 * unit(rng));
    const int degree = degreeOf(rng);
    std::vector<double> roots;
    std::vector<std::pair<double, double>> pairs;
    if (degree >= 2 && unit(rng) < 0.25) {
      pairs.emplace_back(scale * (-1 + 11 * unit(rng)), scale * (0.05 + unit(rng)));
    }
    while (static_cast<int>(roots.size() + 2 * pairs.size()) < degree) {
      const double r = scale * (-1 + 11 * unit(rng));
      bool separated = std::abs(r) > 1e-3 * scale;
      for (const double other : roots) separated = separated && std::abs(r - other) > 1e-3 * scale;
      if (separated) roots.push_back(r);
    }
    const double lead = (unit(rng) < 0.5 ? -1 : 1) * std::pow(10.0, -8 + 16 * unit(rng));
    const Polynomial f = fromRoots(lead, roots, pairs);
    double tMax = unit(rng) < 0.5 ? kInf : scale * 10 * unit(rng);
    for (const double r : roots) {
      if (std::abs(r - tMax) < 1e-4 * scale) tMax = kInf;  // keep the horizon off the roots
    }
    const double expected = entryFromRoots(f, roots, tMax);
    checkEntry("random separated roots", f, tMax, firstEntry(f, tMax), expected);
    if (QTest::currentTestFailed()) return;
    entries += std::isfinite(expected) && expected > 0;
  }
  QVERIFY(entries > 500);
}

void TestPolynomial::randomCoefficientsAgainstSampling() {
  std::mt19937_64 rng(1234567);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int samples = 1500;
  int entries = 0;
  int narrowDips = 0;
  for (int i = 0; i < 7000; ++i) {
    Polynomial f;
    const int degree = 2 + i % (kTop - 1);
    const double tMax = 0.5 + 20 * unit(rng);
    if (i % 4 == 3) {
      // Near touches: (t - r)^2 (t^2 + p t + q) + delta, a dip or a gap of size |delta| that
      // is usually narrower than the sample spacing.
      const double r = tMax * unit(rng);
      const double p = 4 * unit(rng) - 2;
      const double q = p * p / 4 + 0.1 + unit(rng);
      const double delta = (unit(rng) < 0.5 ? -1 : 1) * std::pow(10.0, -12 + 8 * unit(rng));
      f = poly(r * r * q, -2 * r * q + r * r * p, q - 2 * r * p + r * r, p - 2 * r, 1);
      // Higher degrees: times quadratics that are positive everywhere, which keeps the touch.
      for (int extra = 4; extra + 2 <= degree; extra += 2) {
        const double s = 4 * unit(rng) - 2;
        f = timesQuadratic(f, s * s / 4 + 0.1 + unit(rng), s, 1);
      }
      f.c[0] += delta;
    } else {
      for (int k = 0; k <= degree; ++k) {
        if (k > 0 && k < degree && unit(rng) < 0.15) continue;  // some zero coefficients
        const double sign = (k == 0 ? unit(rng) < 0.2 : unit(rng) < 0.5) ? -1 : 1;
        f.c[k] = sign * std::pow(10.0, -2 + 4 * unit(rng));
      }
    }
    const double reference = entryFromSamples(f, tMax, samples);
    const double t = firstEntry(f, tMax);
    const QByteArray context = describe(f, tMax);
    VERIFY(t == 0 || t == kInf || (t > 0 && t <= tMax), "t = %.17g (%s)", t, context.data());
    if (f.degree() <= 2) {
      const double closed = firstEntryQuadratic(f.c[2], f.c[1], f.c[0], tMax);
      VERIFY(closed == t, "closed form %.17g, general %.17g (%s)", closed, t, context.data());
    }
    if (reference == 0) {
      VERIFY(t == 0, "t = %.17g, expected 0 (%s)", t, context.data());
      continue;
    }
    // Never later than the first sampled crossing; earlier only at a genuine entry that the
    // samples stepped over.
    const double limit = std::isfinite(reference) ? reference : tMax;
    if (std::isinf(reference) && std::isinf(t)) {
      // agreed: no entry
    } else if (std::isfinite(reference) && std::abs(t - reference) <= rootTolerance(f, reference)) {
      ++entries;
    } else {
      VERIFY(t < limit && entersAt(f, t, std::min(limit, t + tMax / samples)),
             "t = %.17g, sampled %.17g (%s)", t, reference, context.data());
      ++narrowDips;
    }
    // And no sample before t goes from + to -: every sampled crossing is at or after t.
    if (std::isfinite(t)) {
      const double earlier = entryFromSamples(f, t, samples);
      VERIFY(earlier == kInf || earlier >= t - rootTolerance(f, t),
             "sampled crossing %.17g before t = %.17g (%s)", earlier, t, context.data());
    }
  }
  qInfo("%d sampled entries matched, %d narrow dips found between samples", entries, narrowDips);
  QVERIFY(entries > 2000);
  QVERIFY(narrowDips > 350);
}

void TestPolynomial::generalPathMatchesClosedForm() {
  // Multiplying a quadratic by t + K or t^2 + K (K > 0) keeps its sign on t >= 0, so the cubic
  // and quartic must enter where the quadratic does.
  std::mt19937_64 rng(55555);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0;
  for (int i = 0; i < 3000; ++i) {
    const double a = (unit(rng) < 0.5 ? -1 : 1) * std::pow(10.0, -3 + 6 * unit(rng));
    const double b = (unit(rng) < 0.5 ? -1 : 1) * std::pow(10.0, -3 + 6 * unit(rng));
    const double c = i % 10 == 0 ? 0.0 : std::pow(10.0, -3 + 6 * unit(rng));
    const double tMax = unit(rng) < 0.5 ? kInf : std::pow(10.0, -3 + 6 * unit(rng));
    const double K = std::ldexp(1.0, static_cast<int>(6 * unit(rng)));
    const double d = b * b - 4 * a * c;
    if (std::abs(d) < 1e-6 * (b * b + std::abs(4 * a * c))) continue;  // near touch: ambiguous
    const double expected = firstEntryQuadratic(a, b, c, tMax);
    if (std::isfinite(expected) && expected > tMax * (1 - 1e-9)) continue;  // at the horizon
    const Polynomial cubic = poly(c * K, b * K + c, a * K + b, a);
    const Polynomial quartic = poly(c * K, b * K, a * K + c, b, a);
    for (const Polynomial& f : {cubic, quartic}) {
      const double t = firstEntry(f, tMax);
      const QByteArray context = describe(f, tMax);
      if (std::isinf(expected) || expected == 0) {
        VERIFY(t == expected, "%.17g vs closed form %.17g (%s)", t, expected, context.data());
      } else {
        VERIFY(std::abs(t - expected) <= 1e-9 * expected, "%.17g vs closed form %.17g (%s)", t,
               expected, context.data());
      }
    }
    ++compared;
  }
  QVERIFY(compared > 2000);
}

void TestPolynomial::extremeInputsStaySane() {
  // Coefficients anywhere from 1e-300 to 1e300, any signs, some zero: a time in [0, tMax] or
  // +infinity, never NaN, never in overlap (other than the entry at 0), and no hang.
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    Polynomial f;
    for (double& c : f.c) {
      if (unit(rng) < 0.2) continue;
      c = (unit(rng) < 0.5 ? -1 : 1) * std::pow(10.0, -300 + 600 * unit(rng));
    }
    const double u = unit(rng);
    const double tMax = u < 0.1 ? 0.0 : (u < 0.5 ? kInf : std::pow(10.0, -300 + 600 * unit(rng)));
    const double t = firstEntry(f, tMax);
    const QByteArray context = describe(f, tMax);
    VERIFY(t == kInf || (t >= 0 && t <= tMax), "t = %.17g (%s)", t, context.data());
    if (t > 0 && t < kInf) {
      VERIFY(exactValue(f, t) >= 0, "overlap at t = %.17g (%s)", t, context.data());
    }
    const double q = firstEntryQuadratic(f.c[2], f.c[1], f.c[0], tMax);
    VERIFY(q == kInf || (q >= 0 && q <= tMax), "q = %.17g (%s)", q, context.data());
  }
}

QTEST_APPLESS_MAIN(TestPolynomial)
#include "test_polynomial.moc"
