#include "sim/rest_policy.h"

#include "sim/tolerances.h"

#include <Eigen/Dense>

#include <cmath>
#include <limits>

namespace carom {
namespace {

// Distance from `d` to the cone spanned by the first `count` columns of `normals` when the
// least-squares weights are all non-negative; +infinity otherwise.
double coneResidual(const Eigen::Matrix3d& normals, int count, const Vec3& d) {
  const Eigen::MatrixXd basis = normals.leftCols(count);
  const Eigen::VectorXd weights = basis.colPivHouseholderQr().solve(d);
  if ((weights.array() < 0.0).any()) return std::numeric_limits<double>::infinity();
  return (basis * weights - d).norm();
}

}  // namespace

double restSpeed(const Vec3& gravity, double radius) {
  return std::sqrt(2.0 * gravity.norm() * tolerance::kRestHeightFraction * radius);
}

double collapseSpeed(double initialRmsSpeed) {
  return tolerance::kCollapseSpeedFraction * initialRmsSpeed;
}

bool holdsAgainstGravity(const Vec3& gravity, const std::vector<Vec3>& supportNormals) {
  const double g = gravity.norm();
  if (g == 0.0 || supportNormals.empty()) return false;
  const Vec3 up = -gravity / g;
  const int n = static_cast<int>(supportNormals.size());
  // Gravity is balanced by at most three supports (a vertex of the cone), so trying every
  // single, pair and triple of the few contacts a ball has finds the answer exactly.
  Eigen::Matrix3d m;
  for (int i = 0; i < n; ++i) {
    m.col(0) = supportNormals[i];
    if (coneResidual(m, 1, up) <= tolerance::kSupportSlope) return true;
    for (int j = i + 1; j < n; ++j) {
      m.col(1) = supportNormals[j];
      if (coneResidual(m, 2, up) <= tolerance::kSupportSlope) return true;
      for (int k = j + 1; k < n; ++k) {
        m.col(2) = supportNormals[k];
        if (coneResidual(m, 3, up) <= tolerance::kSupportSlope) return true;
      }
    }
  }
  return false;
}

}  // namespace carom
