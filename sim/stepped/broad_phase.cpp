#include "sim/stepped/broad_phase.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace carom {

void BallBins::build(const std::vector<Vec3>& centres, const std::vector<double>& radii,
                     double margin) {
  const std::size_t n = centres.size();
  levelOf_.assign(n, 0);
  cellOfBall_.resize(n);
  levels_.clear();
  centres_.clear();
  radii_.clear();
  if (n == 0) return;
  // Size classes: radii within a factor of two of each other share one, counted up from the
  // smallest ball.
  const double smallest = *std::min_element(radii.begin(), radii.end());
  std::map<int, std::vector<int>> classes;
  for (std::size_t i = 0; i < n; ++i)
    classes[std::ilogb(radii[i] / smallest)].push_back(static_cast<int>(i));
  // Only queries across classes look at positions again: one class needs no copy (a discrete
  // step of a million balls would copy 24 MB for nothing).
  if (classes.size() > 1) {
    centres_ = centres;
    radii_ = radii;
  }
  for (auto& [sizeClass, balls] : classes) {
    const std::size_t index = levels_.size();
    Level& level = levels_.emplace_back();
    level.balls = std::move(balls);
    Vec3 lower = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 upper = -lower;
    double largest = 0.0;
    for (int i : level.balls) {
      levelOf_[i] = index;
      lower = lower.cwiseMin(centres[i]);
      upper = upper.cwiseMax(centres[i]);
      largest = std::max(largest, radii[i]);
    }
    // Cells at least as wide as the class's reach to any ball of its class or a smaller one, and
    // no more than about twice as many cells as balls.
    const Vec3 extent = upper - lower;
    double size = std::max(2.0 * largest + margin, 1e-300);
    const double maxCells = 2.0 * double(level.balls.size()) + 8.0;
    while ((std::floor(extent[0] / size) + 1) * (std::floor(extent[1] / size) + 1) *
               (std::floor(extent[2] / size) + 1) >
           maxCells)
      size *= 1.25;
    level.lower = lower;
    level.cellSize = size;
    for (int a = 0; a < 3; ++a)
      level.counts[a] = static_cast<int>(std::floor(extent[a] / size)) + 1;
    const int cells = level.counts[0] * level.counts[1] * level.counts[2];
    level.start.assign(cells + 1, 0);
    for (int i : level.balls) {
      const Cell c = level.cellOf(centres[i]);
      cellOfBall_[i] = static_cast<int>((c.z * level.counts[1] + c.y) * level.counts[0] + c.x);
      ++level.start[cellOfBall_[i] + 1];
    }
    for (int c = 0; c < cells; ++c) level.start[c + 1] += level.start[c];
    level.order.resize(level.balls.size());
    std::vector<int> fill(level.start.begin(), level.start.end() - 1);
    for (int i : level.balls) level.order[fill[cellOfBall_[i]]++] = i;
  }
}

}  // namespace carom
