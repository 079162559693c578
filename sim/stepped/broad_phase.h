#pragma once
// Finding pairs of balls that may touch, when all of them are looked at at once (discrete steps,
// measurements): grids rebuilt from scratch by counting sort, O(N).
//
// Balls of very different sizes get a grid per size class (radii within a factor of two share
// one), each with cells fitted to its largest ball: one grid sized by the largest ball would put
// thousands of small balls in a cell. A pair of one class is found in its grid's neighbouring
// cells; a pair of two classes from the smaller ball, in the larger class's cells around it.
// Scenes of one size class have one grid, and visit their pairs in the same order as ever.

#include "sim/core/memory_bytes.h"
#include "sim/model/scene.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace carom {

class BallBins {
 public:
  // Bins the centres by size class; two balls i, j that may touch are those closer than
  // radii[i] + radii[j] + margin (and maybe some farther: callers test the distance themselves).
  void build(const std::vector<Vec3>& centres, const std::vector<double>& radii, double margin);

  // Calls f(i, j), i < j, once for every candidate pair.
  template <typename F>
  void forEachCandidatePair(F&& f) const {
    for (std::size_t l = 0; l < levels_.size(); ++l) {
      const Level& level = levels_[l];
      for (int i : level.balls) {
        level.forEachAround(level.cellAt(cellOfBall_[i]), [&](int j) {
          if (j > i) f(i, j);
        });
        // With every larger class, from this (the smaller) ball's side.
        for (std::size_t k = l + 1; k < levels_.size(); ++k)
          levels_[k].forEachAround(levels_[k].cellOf(centres_[i]),
                                   [&](int j) { f(std::min(i, j), std::max(i, j)); });
      }
    }
  }

  // Calls f(j) for every other ball j that may touch ball i.
  template <typename F>
  void forEachCandidateOf(int i, F&& f) const {
    const std::size_t own = levelOf_[i];
    for (std::size_t k = 0; k < levels_.size(); ++k) {
      const Level& level = levels_[k];
      if (k >= own) {
        level.forEachAround(k == own ? level.cellAt(cellOfBall_[i]) : level.cellOf(centres_[i]),
                            [&](int j) {
                              if (j != i) f(j);
                            });
      } else {
        // A smaller class: its cells within reach of ball i, clipped to its grid.
        const double reach = radii_[i] + level.cellSize;
        const Cell low = level.cellOf(centres_[i] - Vec3::Constant(reach));
        const Cell high = level.cellOf(centres_[i] + Vec3::Constant(reach));
        level.forEachIn(low, high, f);
      }
    }
  }

  std::size_t memoryBytes() const {
    std::size_t bytes = carom::memoryBytes(centres_) + carom::memoryBytes(radii_) +
                        carom::memoryBytes(levelOf_) + carom::memoryBytes(cellOfBall_);
    for (const Level& level : levels_)
      bytes += carom::memoryBytes(level.balls) + carom::memoryBytes(level.start) +
               carom::memoryBytes(level.order);
    return bytes;
  }

 private:
  struct Cell {
    long long x, y, z;  // may lie outside the grid, by any amount
  };
  struct Level {
    std::vector<int> balls;  // of this class, in index order
    Vec3 lower = Vec3::Zero();
    double cellSize = 1.0;
    int counts[3] = {1, 1, 1};
    std::vector<int> start;  // first slot of each cell in order
    std::vector<int> order;  // the class's balls sorted by cell

    Cell cellOf(const Vec3& p) const {
      long long c[3];
      for (int a = 0; a < 3; ++a) {
        // Clamped first, so that far-off points (or huge coordinates) cannot overflow.
        const double x = std::clamp(std::floor((p[a] - lower[a]) / cellSize), -2.0,
                                    static_cast<double>(counts[a]) + 1.0);
        c[a] = static_cast<long long>(x);
      }
      return {c[0], c[1], c[2]};
    }
    Cell cellAt(int index) const {
      return {index % counts[0], (index / counts[0]) % counts[1], index / (counts[0] * counts[1])};
    }
    template <typename F>
    void forEachIn(const Cell& low, const Cell& high, F&& f) const {
      for (long long z = std::max(low.z, 0LL); z <= std::min(high.z, counts[2] - 1LL); ++z)
        for (long long y = std::max(low.y, 0LL); y <= std::min(high.y, counts[1] - 1LL); ++y)
          for (long long x = std::max(low.x, 0LL); x <= std::min(high.x, counts[0] - 1LL); ++x) {
            const long long cell = (z * counts[1] + y) * counts[0] + x;
            for (int s = start[cell]; s < start[cell + 1]; ++s) f(order[s]);
          }
    }
    template <typename F>
    void forEachAround(const Cell& c, F&& f) const {
      forEachIn({c.x - 1, c.y - 1, c.z - 1}, {c.x + 1, c.y + 1, c.z + 1}, f);
    }
  };

  // Kept only with more than one class, for the queries across classes.
  std::vector<Vec3> centres_;
  std::vector<double> radii_;
  std::vector<std::size_t> levelOf_;  // each ball's level, an index into levels_
  std::vector<int> cellOfBall_;       // each ball's cell in its level's grid
  std::vector<Level> levels_;         // smallest class first
};

// Calls f(i, j) once for each pair of balls whose centres are closer than the sum of their radii
// plus `margin` (and maybe some farther ones: callers test the distance themselves).
template <typename F>
void forEachCloseBallPair(const std::vector<Vec3>& centres, const std::vector<double>& radii,
                          double margin, F&& f) {
  BallBins bins;
  bins.build(centres, radii, margin);
  bins.forEachCandidatePair(f);
}

}  // namespace carom
