#include "sim/dynamics/turning_drag.h"

#include <cmath>
#include <limits>

namespace carom {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The integral of e^(-p·x) over [0, lambda]: (1 - e^(-p·lambda))/p, lambda itself when p = 0,
// and without cancellation when p·lambda is small.
double decayIntegral(double p, double lambda) {
  if (lambda == kInfinity) return p > 0.0 ? 1.0 / p : kInfinity;
  if (p == 0.0) return lambda;
  return -std::expm1(-p * lambda) / p;
}

// e^(-p·lambda), zero at lambda = infinity when p > 0.
double decay(double p, double lambda) {
  if (lambda == kInfinity) return p > 0.0 ? 0.0 : (p == 0.0 ? 1.0 : kInfinity);
  return std::exp(-p * lambda);
}

}  // namespace

TurningDrag::TurningDrag(const Vec3& w0, const Vec3& pull, double drag) {
  a_ = pull.norm();
  e_ = pull / a_;
  q_ = drag / a_;
  const double along = w0.dot(e_);
  const Vec3 across = w0 - along * e_;
  across0_ = across.norm();
  across_ = across / across0_;
  const double length = std::hypot(along, across0_);
  // |w0| ± w0·e, the smaller one as the product over the larger (no cancellation near 0 or π).
  if (along >= 0.0) {
    plus_ = length + along;
    minus_ = across0_ * across0_ / plus_;
  } else {
    minus_ = length - along;
    plus_ = across0_ * across0_ / minus_;
  }
  s0_ = across0_ / plus_;
  stopTime_ = q_ > 1.0 ? (plus_ / (q_ - 1.0) + minus_ / (q_ + 1.0)) / (2.0 * a_) : kInfinity;
}

double TurningDrag::startAngle() const {
  return 2.0 * std::atan(s0_);
}

double TurningDrag::startTurnRate() const {
  const double length = 0.5 * (plus_ + minus_);  // |w0|
  return a_ * across0_ / (length * length);
}

// With lambda = ln(s0/s): t = [(|w0| + w0·e)·E(q-1) + (|w0| - w0·e)·E(q+1)]/(2a), E(p) the
// integral of e^(-p·x) over [0, lambda].
double TurningDrag::timeAt(double lambda) const {
  return (plus_ * decayIntegral(q_ - 1.0, lambda) + minus_ * decayIntegral(q_ + 1.0, lambda)) /
         (2.0 * a_);
}

double TurningDrag::rateAt(double lambda) const {
  return (plus_ * decay(q_ - 1.0, lambda) + minus_ * decay(q_ + 1.0, lambda)) / (2.0 * a_);
}

// t(lambda) rises monotonically from 0: a bracket that always holds the root, narrowed by
// Newton steps where they stay inside it and halved where they do not, until it cannot shrink.
double TurningDrag::lambdaAt(double t) const {
  if (!(t > 0.0)) return 0.0;
  if (t >= stopTime_) return kInfinity;
  double low = 0.0;
  double high = t / rateAt(0.0);
  while (timeAt(high) < t) {
    low = high;
    high *= 2.0;
  }
  double x = high;
  for (int iteration = 0; iteration < 400; ++iteration) {
    const double f = timeAt(x) - t;
    if (f == 0.0) return x;
    (f < 0.0 ? low : high) = x;
    double next = x - f / rateAt(x);
    if (!(next > low && next < high)) next = low + 0.5 * (high - low);
    if (next == x || next == low || next == high) break;
    x = next;
  }
  return x;
}

TurningDrag::State TurningDrag::stateAt(double lambda) const {
  const double q = q_;
  const double across = across0_ * decay(q, lambda);
  const double along = 0.5 * (plus_ * decay(q - 1.0, lambda) - minus_ * decay(q + 1.0, lambda));
  const double integralAcross = across0_ / (2.0 * a_) *
                                (plus_ * decayIntegral(2.0 * q - 1.0, lambda) +
                                 minus_ * decayIntegral(2.0 * q + 1.0, lambda));
  const double integralAlong = (plus_ * plus_ * decayIntegral(2.0 * q - 2.0, lambda) -
                                minus_ * minus_ * decayIntegral(2.0 * q + 2.0, lambda)) /
                               (4.0 * a_);
  const double angle = lambda == kInfinity ? 0.0 : 2.0 * std::atan(s0_ * std::exp(-lambda));
  return {along * e_ + across * across_, integralAlong * e_ + integralAcross * across_, angle};
}

TurningDrag::State TurningDrag::at(double t) const {
  return stateAt(lambdaAt(t));
}

}  // namespace carom
