#include "sim/broad_phase.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace carom {

void BallBins::build(const std::vector<Vec3>& centres, double cellSize) {
  const int n = static_cast<int>(centres.size());
  Vec3 lower = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 upper = -lower;
  for (const Vec3& p : centres) {
    lower = lower.cwiseMin(p);
    upper = upper.cwiseMax(p);
  }
  if (n == 0) lower = upper = Vec3::Zero();
  const Vec3 extent = upper - lower;
  double size = std::max(cellSize, 1e-300);
  const double maxCells = 2.0 * n + 8.0;
  while ((std::floor(extent[0] / size) + 1) * (std::floor(extent[1] / size) + 1) *
             (std::floor(extent[2] / size) + 1) >
         maxCells)
    size *= 1.25;
  for (int a = 0; a < 3; ++a) counts_[a] = static_cast<int>(std::floor(extent[a] / size)) + 1;
  const int cells = counts_[0] * counts_[1] * counts_[2];
  cellOfBall_.resize(n);
  start_.assign(cells + 1, 0);
  for (int i = 0; i < n; ++i) {
    int c[3];
    for (int a = 0; a < 3; ++a)
      c[a] = std::min(static_cast<int>((centres[i][a] - lower[a]) / size), counts_[a] - 1);
    cellOfBall_[i] = (c[2] * counts_[1] + c[1]) * counts_[0] + c[0];
    ++start_[cellOfBall_[i] + 1];
  }
  for (int c = 0; c < cells; ++c) start_[c + 1] += start_[c];
  order_.resize(n);
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (int i = 0; i < n; ++i) order_[fill[cellOfBall_[i]]++] = i;
}

}  // namespace carom
