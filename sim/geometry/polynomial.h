#pragma once
// Contact times as polynomial roots. The gap between two shapes along their paths (ball on a
// parabola against a plane, a cylinder, a box's edge or another ball) is a polynomial of degree
// at most 4 in time, and 8 against a capped cylinder's rim; the simulator needs the first time
// that gap turns negative, never late and never missed.

#include <array>

namespace carom {

inline constexpr int kMaxPolynomialDegree = 8;

// f(t) = c[0] + c[1] t + ... + c[8] t^8 (higher coefficients may be zero).
struct Polynomial {
  std::array<double, kMaxPolynomialDegree + 1> c{};

  double operator()(double t) const;  // Horner
  Polynomial derivative() const;
  // Highest index with a non-zero coefficient, -1 for the zero polynomial.
  int degree() const;
};

// The earliest time t in [0, tMax] at which the gap f (> 0 apart, < 0 overlapping) starts to
// become negative, or +infinity when there is none (tMax may be +infinity):
// * f(0) <= 0 and approaching at 0 (the first non-zero derivative f'(0), f''(0), ... is negative)
//   gives 0: a contact that touches or overlaps and closes in fires at once. An overlap that is
//   opening up is not an entry; the next one comes after f has been positive again.
// * Otherwise the smallest t in (0, tMax] where f crosses from > 0 to < 0. A tangential touch (f
//   reaches 0 and turns back up) is not an entry.
// Signs are decided in about twice the working precision (compensated Horner), so only a dip or
// touch shallower than ~1e-30 of the terms' size is ambiguous; an ambiguous sign counts as
// overlap. The result is the lower end of a bracket narrowed to adjacent doubles, where f > 0
// beyond doubt: a few ulps before the crossing at most, never after it. Only where the terms of f
// near the crossing leave the double range (below ~1e-290 or above ~1e300) may it be further early.
// Non-finite coefficients, a NaN or a negative tMax give +infinity. No allocation, no iteration
// without a hard cap.
double firstEntry(const Polynomial& f, double tMax);

// The same for f(t) = a t^2 + b t + c, in closed form.
double firstEntryQuadratic(double a, double b, double c, double tMax);

}  // namespace carom
