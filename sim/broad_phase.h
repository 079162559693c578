#pragma once
// Finding pairs of balls that may touch, when all of them are looked at at once (discrete steps,
// measurements, validation): a grid rebuilt from scratch by counting sort, O(N).

#include "sim/memory_bytes.h"
#include "sim/scene.h"

#include <algorithm>
#include <vector>

namespace carom {

class BallBins {
 public:
  // Bins the centres into cells of at least `cellSize`, at most about 2 N cells.
  void build(const std::vector<Vec3>& centres, double cellSize);

  // Calls f(i, j), i < j, for every pair in the same or adjacent cells.
  template <typename F>
  void forEachCandidatePair(F&& f) const {
    const int n = static_cast<int>(cellOfBall_.size());
    for (int i = 0; i < n; ++i) {
      const int c = cellOfBall_[i];
      const int cx = c % counts_[0], cy = (c / counts_[0]) % counts_[1],
                cz = c / (counts_[0] * counts_[1]);
      for (int z = std::max(cz - 1, 0); z <= std::min(cz + 1, counts_[2] - 1); ++z)
        for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, counts_[1] - 1); ++y)
          for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, counts_[0] - 1); ++x) {
            const int cell = (z * counts_[1] + y) * counts_[0] + x;
            for (int s = start_[cell]; s < start_[cell + 1]; ++s)
              if (order_[s] > i) f(i, order_[s]);
          }
    }
  }

  // Calls f(j) for every other ball j in ball i's cell or the adjacent ones.
  template <typename F>
  void forEachCandidateOf(int i, F&& f) const {
    const int c = cellOfBall_[i];
    const int cx = c % counts_[0], cy = (c / counts_[0]) % counts_[1],
              cz = c / (counts_[0] * counts_[1]);
    for (int z = std::max(cz - 1, 0); z <= std::min(cz + 1, counts_[2] - 1); ++z)
      for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, counts_[1] - 1); ++y)
        for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, counts_[0] - 1); ++x) {
          const int cell = (z * counts_[1] + y) * counts_[0] + x;
          for (int s = start_[cell]; s < start_[cell + 1]; ++s)
            if (order_[s] != i) f(order_[s]);
        }
  }

  std::size_t memoryBytes() const {
    return carom::memoryBytes(cellOfBall_) + carom::memoryBytes(start_) +
           carom::memoryBytes(order_);
  }

 private:
  int counts_[3] = {1, 1, 1};
  std::vector<int> cellOfBall_;
  std::vector<int> start_;  // first slot of each cell in order_
  std::vector<int> order_;  // ball indices sorted by cell
};

// Calls f(i, j) once for each pair of balls whose centres are closer than the sum of their radii
// plus `margin` (and maybe some farther ones: callers test the distance themselves).
template <typename F>
void forEachCloseBallPair(const std::vector<Vec3>& centres, const std::vector<double>& radii,
                          double margin, F&& f) {
  double maxRadius = 0.0;
  for (double r : radii) maxRadius = std::max(maxRadius, r);
  BallBins bins;
  bins.build(centres, 2.0 * maxRadius + margin);
  bins.forEachCandidatePair(f);
}

}  // namespace carom
