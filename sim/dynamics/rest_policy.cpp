#include "sim/dynamics/rest_policy.h"

#include "sim/core/tolerances.h"

#include <cmath>

namespace carom {

double restSpeed(const Vec3& gravity, double radius) {
  return std::sqrt(2.0 * gravity.norm() * tolerance::kRestHeightFraction * radius);
}

double slideSpeed(const Vec3& gravity, double radius) {
  return std::sqrt(2.0 * gravity.norm() * tolerance::kTouchFraction * radius);
}

double collapseSpeed(double initialRmsSpeed) {
  return tolerance::kCollapseSpeedFraction * initialRmsSpeed;
}

}  // namespace carom
