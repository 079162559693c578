#include "sim/geometry/polynomial.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace carom {

double Polynomial::operator()(double t) const {
  double value = c[kMaxPolynomialDegree];
  for (int k = kMaxPolynomialDegree - 1; k >= 0; --k) value = value * t + c[k];
  return value;
}

Polynomial Polynomial::derivative() const {
  Polynomial d;
  for (int k = 1; k <= kMaxPolynomialDegree; ++k) d.c[k - 1] = k * c[k];
  return d;
}

int Polynomial::degree() const {
  for (int k = kMaxPolynomialDegree; k >= 0; --k) {
    if (c[k] != 0.0) return k;
  }
  return -1;
}

namespace {

using Coefficients = std::array<double, kMaxPolynomialDegree + 1>;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kUnit = std::numeric_limits<double>::epsilon() / 2;  // unit round-off
// Horner's rounding error is at most gamma_2n * sum |c_k| t^k (about 2n u for degree n); twice
// that leaves room for the rounding of the sum itself. Degrees below 4 keep the bound of 4.
constexpr double hornerError(int degree) {
  return 4 * std::max(degree, 4) * kUnit;
}
// Compensated Horner is off by at most u |f| + gamma_2n^2 * sum |c_k| t^k.
constexpr double compensatedError(int degree) {
  return 2 * (2 * std::max(degree, 4) * kUnit) * (2 * std::max(degree, 4) * kUnit);
}
// Products in the subnormal range lose up to half the smallest subnormal each.
constexpr double kUnderflowError = 16 * std::numeric_limits<double>::denorm_min();
// A refinement halves the bit width of its bracket (at most 64 bits) at least every second step,
// so 128 steps close any bracket; the cap is a backstop against the unforeseen.
constexpr int kMaxSteps = 160;
// Relative margin for the tangent bounds, far above their rounding.
constexpr double kTangentMargin = 1e-12;

struct Sample {
  // NaN where the terms leave the double range: then only the sign is known.
  double value;  // f(t); in twice the precision when plain Horner cannot tell its sign
  double slope;  // f'(t)
  double bend;   // f''(t) / 2
  int sign;      // of f(t): +1, -1, or 0 when within the evaluation error of 0
};

// A polynomial of known degree with the evaluations the root finder needs (for t >= 0).
class Poly {
 public:
  Poly(const Coefficients& c, int degree) : c_(c), n_(degree) {}

  int degree() const { return n_; }
  double operator[](int k) const { return c_[k]; }

  // A quarter of the derivative: same roots and signs, and it cannot overflow.
  Poly derivative() const {
    Coefficients d{};
    for (int k = 1; k <= n_; ++k) d[k - 1] = 0.25 * c_[k] * k;
    return Poly(d, std::max(n_ - 1, 0));
  }

  Sample sample(double t) const {
    double value = c_[n_];
    double slope = 0.0;
    double bend = 0.0;
    double size = std::abs(c_[n_]);  // sum |c_k| t^k, the scale of the rounding error
    for (int k = n_ - 1; k >= 0; --k) {
      bend = bend * t + slope;
      slope = slope * t + value;
      value = value * t + c_[k];
      size = size * t + std::abs(c_[k]);
    }
    // Terms beyond the double range (or so small that the error bound underflows) leave only
    // the sign, from an exactly rescaled copy.
    if (!(size >= 0x1p-900 && size <= 0x1p1000)) return {kNaN, kNaN, kNaN, rescaledSign(t)};
    if (std::abs(value) > hornerError(n_) * size) return {value, slope, bend, value > 0 ? 1 : -1};
    // Near a root the sign of plain Horner is noise; compensated Horner resolves touches and
    // clustered roots down to about u^2 of the terms' size.
    const double accurate = compensated(t);
    const double error =
        2 * kUnit * std::abs(accurate) + compensatedError(n_) * size + kUnderflowError;
    return {accurate, slope, bend, accurate > error ? 1 : (accurate < -error ? -1 : 0)};
  }

 private:
  // The sign of f(t) from f(t) / 2^E = sum c_k 2^(k e - E) m^k, where t = m 2^e with m in [1, 2)
  // and 2^E is about the largest term: all exact, and the terms that matter are of order 1.
  int rescaledSign(double t) const;

  // Horner carrying the exact rounding error of every product (fma) and sum (TwoSum) along, as
  // if evaluated in twice the working precision (Graillat, Langlois and Louvet).
  double compensated(double t) const {
    double value = c_[n_];
    double error = 0.0;
    for (int k = n_ - 1; k >= 0; --k) {
      const double product = value * t;
      const double productError = std::fma(value, t, -product);
      const double sum = product + c_[k];
      const double part = sum - product;
      const double sumError = (product - (sum - part)) + (c_[k] - part);
      error = error * t + (productError + sumError);
      value = sum;
    }
    return value + error;
  }

  Coefficients c_;
  int n_;
};

std::uint64_t bitsOf(double t) {
  return std::bit_cast<std::uint64_t>(t);
}

// floor(log2 |x|) for finite non-zero x, from the bits: std::ilogb is a library call.
int exponentOf(double x) {
  const int biased = static_cast<int>((bitsOf(x) >> 52) & 0x7ff);
  return biased != 0 ? biased - 1023 : std::ilogb(x);
}

int Poly::rescaledSign(double t) const {
  if (t == 0) return c_[0] > 0 ? 1 : (c_[0] < 0 ? -1 : 0);
  const int e = exponentOf(t);
  int largest = std::numeric_limits<int>::min();
  for (int k = 0; k <= n_; ++k) {
    if (c_[k] != 0) largest = std::max(largest, exponentOf(c_[k]) + k * e);
  }
  if (largest == std::numeric_limits<int>::min()) return 0;
  Coefficients d{};
  for (int k = 0; k <= n_; ++k) d[k] = std::ldexp(c_[k], k * e - largest);
  return Poly(d, n_).sample(std::ldexp(t, -e)).sign;
}

// Halves 0 <= lo < hi in bit space: the arithmetic midpoint within a binade, roughly the
// geometric one across binades, so that even [0, 1e300] closes in 64 halvings.
double split(double lo, double hi) {
  return std::bit_cast<double>(bitsOf(lo) + (bitsOf(hi) - bitsOf(lo)) / 2);
}

// Narrows [lo, hi], where dir * p is >= 0 at lo (value vlo) and <= 0 at hi (vhi), to adjacent
// doubles around the crossing and returns the lower end: lo as given, or a point where dir * p
// is positive beyond doubt. A sign lost in round-off or underflow counts as past the crossing,
// so that the answer errs early.
double refine(const Poly& p, int dir, double lo, double hi, double vlo, double vhi) {
  double t = lo + (hi - lo) * (vlo / (vlo - vhi));  // regula falsi for a start
  for (int iteration = 0; iteration < kMaxSteps; ++iteration) {
    const std::uint64_t before = bitsOf(hi) - bitsOf(lo);
    if (before <= 1) break;
    if (!(t > lo && t < hi)) t = split(lo, hi);
    const Sample s = p.sample(t);
    const bool before0 = dir * s.sign > 0;
    (before0 ? lo : hi) = t;
    // Step to the nearer root of the local quadratic model f + f' d + (f''/2) d^2 (the
    // cancellation-free form), which unlike Newton is not slowed down by a root next to an
    // extremum; Newton where the model misses 0.
    const double toward = before0 ? kInf : -kInf;
    const double disc = s.slope * s.slope - 4 * s.bend * s.value;
    const double step = disc >= 0
                            ? -2 * s.value / (s.slope + std::copysign(std::sqrt(disc), s.slope))
                            : -s.value / s.slope;
    double next = t + step;
    if (next == t) next = std::nextafter(t, toward);
    // Converging from one side, a probe one more step on lands just past the root and closes the
    // bracket from the other side as well.
    if (next > lo && next < hi) {
      double probe = next + step;
      if (probe == next) probe = std::nextafter(next, toward);
      if (probe > lo && probe < hi) (dir * p.sample(probe).sign > 0 ? lo : hi) = probe;
    }
    // A step that does not halve the bracket is not converging: bisect instead.
    if (bitsOf(hi) - bitsOf(lo) > before / 2) next = split(lo, hi);
    t = next;
  }
  return lo;
}

double largestMagnitude(const Coefficients& c) {
  double largest = 0.0;
  for (const double x : c) largest = std::max(largest, std::abs(x));
  return largest;
}

Coefficients shifted(Coefficients c, int shift) {
  for (double& x : c) x = std::ldexp(x, shift);
  return c;
}

// For the root formula of c0 + c1 t + c2 t^2: rescaled by a power of two (roots unchanged) that
// brings the larger of c1^2 and c0 c2, which the discriminant compares, near 1. Neither can then
// overflow, and whatever underflows is negligible next to the other. No coefficient is taken
// within 2^4 of overflow, leaving room for the small factors of derivatives.
Coefficients forFormula(const Coefficients& c) {
  int e = std::numeric_limits<int>::min();
  if (c[1] != 0.0) e = 2 * exponentOf(c[1]);
  if (c[0] != 0.0 && c[2] != 0.0) e = std::max(e, exponentOf(c[0]) + exponentOf(c[2]));
  if (e == std::numeric_limits<int>::min() || (e > -900 && e < 900)) return c;
  int top = std::numeric_limits<int>::min();
  for (int k = 0; k < 3; ++k) {
    if (c[k] != 0.0) top = std::max(top, exponentOf(c[k]));
  }
  return shifted(c, std::min(-e / 2, 1019 - top));
}

// For evaluation: coefficients of extreme size rescaled by a power of two towards 1, so that
// values and their error bounds stay in range, but never so far that a coefficient, however
// small, leaves the normal range: coefficients can span more than the doubles' range at one
// scale, and a tiny leading one still rules at large t.
Coefficients forEvaluation(const Coefficients& c) {
  const double magnitude = largestMagnitude(c);
  if (magnitude == 0.0 || (magnitude >= 0x1p-500 && magnitude < 0x1p501)) return c;
  const int largest = exponentOf(magnitude);
  int smallest = largest;
  for (const double x : c) {
    if (x != 0.0) smallest = std::min(smallest, exponentOf(x));
  }
  return shifted(c, largest > 0 ? std::min(0, std::max(-largest, -1022 - smallest)) : -largest);
}

// A bound on the positive roots (Kioustelidis): beyond 2 max |c_k / c_n|^(1/(n-k)), taken over
// the c_k of sign opposite to c_n, the leading term outweighs them all. From the exponents
// alone: no overflow and no pow. Infinite when beyond the double range, 0 when nothing opposes.
double positiveRootBound(const Poly& p) {
  const int n = p.degree();
  const int top = exponentOf(p[n]);
  int largest = std::numeric_limits<int>::min();
  for (int k = 0; k < n; ++k) {
    if (p[k] == 0.0 || (p[k] > 0) == (p[n] > 0)) continue;
    const int m = n - k;
    const int e = exponentOf(p[k]) + 1 - top;                           // |c_k / c_n| < 2^e
    largest = std::max(largest, e >= 0 ? (e + m - 1) / m : -(-e / m));  // ceil(e / m)
  }
  if (largest == std::numeric_limits<int>::min()) return 0.0;
  const int e = largest + 1;
  if (e > 1023) return kInf;
  if (e < -1022) return std::ldexp(1.0, e);  // subnormal or 0
  return std::bit_cast<double>(static_cast<std::uint64_t>(e + 1023) << 52);
}

// b^2 - 4ac with the rounding of both products recovered by fma (Kahan) when they nearly cancel,
// as they do near a double root: the sign is then right and the value nearly so.
double discriminant(double a, double b, double c) {
  const double bb = b * b;
  const double ac = 4 * a * c;
  const double d = bb - ac;
  if (3 * std::abs(d) >= bb + std::abs(ac)) return d;
  return d + (std::fma(b, b, -bb) - std::fma(4 * a, c, -ac));
}

// The points where a t^2 + b t + c changes sign, ascending; returns how many. The root formula
// avoids cancellation: q = -(b + sign(b) sqrt(d)) / 2, roots q / a and c / q.
int signChanges(double a, double b, double c, double roots[2]) {
  if (a == 0.0) {
    if (b == 0.0) return 0;
    roots[0] = -c / b;
    return 1;
  }
  const double d = discriminant(a, b, c);
  if (!(d > 0)) return 0;
  const double q = -0.5 * (b + std::copysign(std::sqrt(d), b));
  roots[0] = std::min(q / a, c / q);
  roots[1] = std::max(q / a, c / q);
  return 2;
}

// The points in (0, horizon) where q changes sign, ascending, into `out`; returns how many (at
// most q's degree). Between the sign changes of q' q is monotone, so each such piece holds at most
// one, narrowed by refine to adjacent doubles. A point where q' changes sign and q is zero within
// round-off is taken too (a triple root changes sign there): a spare cut costs nothing.
int signChangesBefore(const Poly& q, double horizon, double* out) {
  int count = 0;
  if (q.degree() <= 2) {
    double roots[2];
    const Coefficients n = forFormula({q[0], q[1], q[2]});
    const int found = signChanges(n[2], n[1], n[0], roots);
    for (int i = 0; i < found; ++i) {
      if (roots[i] > (count > 0 ? out[count - 1] : 0.0) && roots[i] < horizon)
        out[count++] = roots[i];
    }
    return count;
  }
  double turns[kMaxPolynomialDegree];
  const int turnCount = signChangesBefore(q.derivative(), horizon, turns);
  double a = 0.0;
  Sample sa = q.sample(a);
  for (int i = 0; i <= turnCount; ++i) {
    const double b = i < turnCount ? turns[i] : horizon;
    const Sample sb = q.sample(b);
    if (sa.sign * sb.sign < 0) {
      const double root = refine(q, sa.sign, a, b, sa.value, sb.value);
      if (root > (count > 0 ? out[count - 1] : 0.0)) out[count++] = root;
    }
    if (i < turnCount && sb.sign == 0 && b > (count > 0 ? out[count - 1] : 0.0)) out[count++] = b;
    a = b;
    if (sb.sign != 0 || sa.sign == 0) sa = sb;
  }
  return count;
}

// Lowers the computed crossing `root` of p (falling there, p > 0 at `floor`) to where p is
// positive beyond doubt, and checks it against the horizon.
double settle(const Poly& p, double root, double floor, double tMax) {
  if (!(root >= 0) || !(root < kInf)) return kInf;
  double t = root + 0.0;  // never -0
  if (t > tMax) {
    // The formula may be a few ulps late; p has then already turned at tMax.
    if (tMax < floor || p.sample(tMax).sign > 0) return kInf;
    t = tMax;
  }
  Sample s = p.sample(t);
  if (s.sign > 0) return t;
  // Step down in doubling steps until p is positive, then narrow the last step.
  double hi = t;
  double gap = t - std::nextafter(t, 0.0);
  for (int step = 0; step < kMaxSteps; ++step) {
    const double lo = std::max(floor, hi - gap);
    const Sample slo = p.sample(lo);
    if (slo.sign > 0) return refine(p, 1, lo, hi, slo.value, s.value);
    if (lo == floor) return lo;
    hi = lo;
    s = slo;
    gap *= 2;
  }
  return floor;
}

// The sign of the first non-zero derivative of p at t: which way p leaves a zero there.
int departure(const Poly& p, double t) {
  Poly d = p;
  for (int k = 1; k <= p.degree(); ++k) {
    d = d.derivative();
    const int sign = d.sample(t).sign;
    if (sign != 0) return sign;
  }
  return 0;
}

// On a piece where f is convex (concave), f lies above (below) both end tangents, so where they
// meet bounds the extremum in between.
double tangentsMeet(double a, double fa, double sa, double b, double fb, double sb) {
  return fa + sa * ((fb - fa - sb * (b - a)) / (sa - sb));
}

double tangentMargin(double a, double fa, double sa, double b, double fb, double sb) {
  return kTangentMargin * (std::abs(fa) + std::abs(fb) + (std::abs(sa) + std::abs(sb)) * (b - a));
}

}  // namespace

double firstEntryQuadratic(double a, double b, double c, double tMax) {
  if (!(tMax >= 0) || !std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c)) return kInf;
  if (c <= 0) {
    const double slope = b != 0.0 ? b : a;  // the first non-zero derivative at 0
    if (slope < 0) return 0.0;
    if (a >= 0) return kInf;  // opening up (or constant), never turning back
  }
  // The common case, cheaply: apart at 0 and unable to fall to 0 by tMax.
  if (c > 0 && c > (std::max(-b, 0.0) * tMax + std::max(-a, 0.0) * tMax * tMax) * (1 + 1e-12)) {
    return kInf;
  }
  const Poly p(forEvaluation({c, b, a, 0.0, 0.0}), a != 0.0 ? 2 : 1);
  if (a == 0.0) return b < 0 ? settle(p, -c / b, 0.0, tMax) : kInf;
  const Coefficients n = forFormula({c, b, a, 0.0, 0.0});
  // No real root, or a double root: a tangential touch is not an entry.
  const double d = discriminant(n[2], n[1], n[0]);
  if (!(d > 0)) return kInf;
  const double q = -0.5 * (n[1] + std::copysign(std::sqrt(d), n[1]));
  const double r0 = q / n[2];
  const double r1 = n[0] / q;
  // Opening upwards f falls through the smaller root; downwards through the larger one, after
  // the vertex.
  if (a > 0) return settle(p, std::min(r0, r1), 0.0, tMax);
  return settle(p, std::max(r0, r1), std::max(0.0, -n[1] / (2 * n[2])), tMax);
}

double firstEntry(const Polynomial& f, double tMax) {
  if (!(tMax >= 0)) return kInf;
  for (const double x : f.c) {
    if (!std::isfinite(x)) return kInf;
  }
  if (f.degree() <= 2) return firstEntryQuadratic(f.c[2], f.c[1], f.c[0], tMax);

  // `positive`: f has been > 0 since it was last < 0, so a fall below 0 is an entry.
  bool positive = f.c[0] > 0;
  if (!positive) {
    int k = 1;
    while (f.c[k] == 0.0) ++k;  // stops at the degree
    if (f.c[k] < 0) return 0.0;
    positive = f.c[0] == 0.0;  // touching and opening: apart right after 0
  }
  const Poly p(forEvaluation(f.c), f.degree());
  const double horizon = std::min({tMax, positiveRootBound(p), std::numeric_limits<double>::max()});
  if (!(horizon > 0)) return kInf;
  // The common case, cheaply: apart at 0 and unable to fall to 0 by the horizon even if every
  // negative term took its largest value there.
  if (p[0] > 0) {
    double fall = 0.0;
    double power = 1.0;
    for (int k = 1; k <= p.degree(); ++k) {
      power *= horizon;
      if (p[k] < 0) fall -= p[k] * power;
    }
    if (p[0] > fall * (1 + 1e-12)) return kInf;
  }

  // Cut [0, horizon] at the inflection points (where f'' changes sign): f' is monotone on each
  // piece, so f has at most one extremum there and is monotone on either side of it.
  const Poly slope = p.derivative();
  double cuts[kMaxPolynomialDegree];
  int pieces = 0;
  if (f.degree() <= 4) {
    // f'' is a quadratic: its roots in closed form.
    double roots[2];
    const Coefficients curvature = forFormula({f.c[2], f.c[3], f.c[4]});
    const int count = signChanges(12 * curvature[2], 6 * curvature[1], 2 * curvature[0], roots);
    for (int i = 0; i < count; ++i) {
      if (roots[i] > (pieces > 0 ? cuts[pieces - 1] : 0.0) && roots[i] < horizon) {
        cuts[pieces++] = roots[i];
      }
    }
  } else {
    pieces = signChangesBefore(slope.derivative(), horizon, cuts);
  }
  cuts[pieces++] = horizon;

  double a = 0.0;
  double fa = p[0];
  double sa = p[1];
  for (int i = 0; i < pieces; ++i) {
    const double b = cuts[i];
    Sample sb = p.sample(b);
    // Where only the sign of f is known, that of f' tells minimum from maximum.
    if (std::isnan(sb.slope)) sb.slope = slope.sample(b).sign;
    // Inside, only a sign beyond round-off counts. At the horizon any negative value does (the
    // crossing is then at most round-off later), as does a zero that f leaves downwards.
    int signB = sb.sign;
    if (i == pieces - 1 && signB == 0) {
      signB = sb.value < 0 ? -1 : (sb.value > 0 ? 0 : departure(p, b));
    }
    const bool minimum = sa < 0 && sb.slope > 0;
    const bool maximum = sa > 0 && sb.slope < 0;
    const auto extremum = [&] {
      const int dir = maximum ? 1 : -1;
      return refine(slope, dir, a, b, dir * sa, dir * sb.slope);  // scale cancels
    };

    if (positive) {
      if (minimum) {
        // Entering here means dipping below 0 at the minimum; skip finding it when the tangents
        // already keep f clear of 0.
        if (signB < 0 || !(tangentsMeet(a, fa, sa, b, sb.value, sb.slope) >
                           tangentMargin(a, fa, sa, b, sb.value, sb.slope))) {
          const double m = extremum();
          const Sample sm = p.sample(m);
          if (sm.sign < 0 || (signB < 0 && sm.value <= 0)) {
            return refine(p, 1, a, m, fa, sm.value);
          }
          if (signB < 0) return refine(p, 1, a, b, fa, sb.value);
        }
      } else if (maximum) {
        if (signB < 0) {
          const double m = extremum();
          return refine(p, 1, m, b, p.sample(m).value, sb.value);
        }
      } else if (signB < 0) {
        return refine(p, 1, a, b, fa, sb.value);
      }
    } else if (maximum && signB <= 0 &&
               !(tangentsMeet(a, fa, sa, b, sb.value, sb.slope) <
                 -tangentMargin(a, fa, sa, b, sb.value, sb.slope))) {
      // Overlapping and opening: an entry needs f to rise above 0 at the maximum first.
      const double m = extremum();
      const Sample sm = p.sample(m);
      if (sm.sign > 0) {
        if (signB < 0) return refine(p, 1, m, b, sm.value, sb.value);
        positive = true;
      }
    }
    if (signB != 0) positive = signB > 0;
    a = b;
    fa = sb.value;
    sa = sb.slope;
  }
  return kInf;
}

}  // namespace carom
