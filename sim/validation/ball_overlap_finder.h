#pragma once
// The balls of a scene that overlap one another, for validation (validation.cpp).

#include "sim/core/tolerances.h"
#include "sim/model/scene.h"

#include <cmath>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <queue>
#include <vector>

namespace carom::validation {

// Whether two objects overlap by `depth`: deeper than touching, measured against `scale` (a
// pair's radii summed, a ball's radius against a shape).
inline bool overlaps(double depth, double scale) {
  return depth > tolerance::kTouchFraction * scale;
}

// Finds the balls that overlap earlier balls with a grid per power-of-two size class: each ball
// sits in one cell of the class that fits its diameter and looks only at the 27 cells around it
// in its own and larger classes. Every pair is thus met once, from its smaller member, in time
// that grows linearly with the number of balls for any scene whose balls do not overlap.
class BallOverlapFinder {
 public:
  struct Overlap {
    std::size_t later;
    std::size_t earlier;
    double depth;
    bool operator>(const Overlap& other) const { return other < *this; }
    bool operator<(const Overlap& other) const {
      return later != other.later ? later < other.later : earlier < other.earlier;
    }
  };

  // Only the `maxReported` first overlaps (by later, then earlier ball) can be reported.
  BallOverlapFinder(const std::vector<Ball>& balls, const std::vector<bool>& usable,
                    std::size_t maxReported);

  // All overlaps whose later ball is `index`, by earlier ball; call for every usable ball in
  // increasing order.
  std::vector<Overlap> overlapsOf(std::size_t index);

 private:
  struct CellKey {
    int level;
    std::int64_t x, y, z;
    auto operator<=>(const CellKey&) const = default;
  };

  struct CellHash {
    std::size_t operator()(const CellKey& key) const {
      // Multiply and fold each part in, so that neighbouring cells land far apart.
      std::uint64_t hash = static_cast<std::uint32_t>(key.level);
      for (std::int64_t part : {key.x, key.y, key.z}) {
        hash = (hash ^ static_cast<std::uint64_t>(part)) * 0x100000001b3ULL;
        hash ^= hash >> 29;
      }
      return static_cast<std::size_t>(hash);
    }
  };

  struct Range {
    std::size_t begin, end;
  };

  static CellKey cellOf(const Vec3& position, int level) {
    const auto index = [level](double coordinate) {
      return static_cast<std::int64_t>(std::floor(std::ldexp(coordinate, -level)));
    };
    return {level, index(position.x()), index(position.y()), index(position.z())};
  }

  // The pairs within each class, found once for all balls: the cells are visited in their
  // sorted order, and the cells of each of the nine rows of neighbours, (x + dx, y + dy,
  // z - 1 .. z + 1), come in that order too, so nine cursors that only move forward find them
  // without a look-up (and its cache miss) per cell. Only the first `maxReported` overlaps are
  // kept.
  void sweepOwnClasses(std::size_t maxReported);
  // The pairs with balls of larger classes, which the sweep leaves out.
  void find(std::size_t index);
  const Range* findCell(const CellKey& key) const;
  std::optional<double> overlapDepth(std::size_t a, std::size_t b) const;

  const std::vector<Ball>& balls_;
  std::vector<int> levels_;
  std::vector<std::size_t> order_;  // ball indices grouped by cell
  // The occupied cells in a flat hash table of open addressing (slots_ holds a cell's index
  // plus one, 0 when empty, at least half of them empty): a million cells as nodes of a map
  // would take as many allocations, and a cache miss for each look-up.
  std::vector<CellKey> cellKeys_;
  std::vector<Range> cellRanges_;
  std::vector<std::uint32_t> slots_;
  std::vector<int> usedLevels_;  // ascending
  std::priority_queue<Overlap, std::vector<Overlap>, std::greater<Overlap>> pending_;
};

}  // namespace carom::validation
