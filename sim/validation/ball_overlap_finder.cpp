#include "sim/validation/ball_overlap_finder.h"

#include "sim/core/prefault.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace carom::validation {

BallOverlapFinder::BallOverlapFinder(const std::vector<Ball>& balls,
                                     const std::vector<bool>& usable, std::size_t maxReported)
    : balls_(balls), levels_(balls.size(), 0) {
  // Cells are at least 2^-40 of the largest coordinate so that cell indices fit in 64 bits.
  double largest = 0.0;
  for (std::size_t i = 0; i < balls.size(); ++i)
    if (usable[i]) largest = std::max(largest, balls[i].position.cwiseAbs().maxCoeff());
  const int minLevel =
      largest > 0.0 ? std::ilogb(largest) + 1 - 40 : std::numeric_limits<int>::min();

  std::vector<std::pair<CellKey, std::size_t>> entries;
  reservePrefaulted(entries, balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (!usable[i]) continue;
    // A cell is wider than the diameter, so overlapping balls of a class are in neighbouring
    // cells; ldexp in cellOf is exact, so no rounding can move a ball across a cell border.
    levels_[i] = std::max(std::ilogb(2.0 * balls[i].radius) + 1, minLevel);
    entries.push_back({cellOf(balls[i].position, levels_[i]), i});
  }
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first < b.first : a.second < b.second;
  });
  order_.reserve(entries.size());
  for (std::size_t begin = 0; begin < entries.size();) {
    std::size_t end = begin;
    while (end < entries.size() && entries[end].first == entries[begin].first) {
      order_.push_back(entries[end].second);
      ++end;
    }
    cellKeys_.push_back(entries[begin].first);
    cellRanges_.push_back({begin, end});
    if (usedLevels_.empty() || usedLevels_.back() != entries[begin].first.level)
      usedLevels_.push_back(entries[begin].first.level);
    begin = end;
  }
  std::size_t slots = 16;
  while (slots < 2 * cellKeys_.size()) slots *= 2;
  slots_.assign(slots, 0);
  for (std::size_t cell = 0; cell < cellKeys_.size(); ++cell) {
    std::size_t slot = CellHash{}(cellKeys_[cell]) & (slots - 1);
    while (slots_[slot] != 0) slot = (slot + 1) & (slots - 1);
    slots_[slot] = static_cast<std::uint32_t>(cell + 1);
  }
  sweepOwnClasses(maxReported);
}

std::vector<BallOverlapFinder::Overlap> BallOverlapFinder::overlapsOf(std::size_t index) {
  find(index);
  std::vector<Overlap> result;
  while (!pending_.empty() && pending_.top().later == index) {
    result.push_back(pending_.top());
    pending_.pop();
  }
  return result;
}

void BallOverlapFinder::sweepOwnClasses(std::size_t maxReported) {
  std::priority_queue<Overlap, std::vector<Overlap>, std::less<>> kept;  // largest on top
  const auto keep = [&](const Overlap& overlap) {
    if (kept.size() == maxReported && !(kept.top() > overlap)) return;
    kept.push(overlap);
    if (kept.size() > maxReported) kept.pop();
  };
  // Once as many are kept as can be reported, pairs whose later ball comes after the last
  // kept one's are not tested: a thousand balls in one spot stop at the first few.
  const auto latest = [&] {
    return kept.size() == maxReported ? kept.top().later : std::numeric_limits<std::size_t>::max();
  };
  const auto testCells = [&](std::size_t a, std::size_t b) {
    // Cells list their balls in increasing order.
    if (std::max(order_[cellRanges_[a].begin], order_[cellRanges_[b].begin]) > latest()) return;
    for (std::size_t i = cellRanges_[a].begin; i < cellRanges_[a].end; ++i) {
      const std::size_t x = order_[i];
      if (x > latest()) break;
      for (std::size_t j = cellRanges_[b].begin; j < cellRanges_[b].end; ++j) {
        if (a == b && j >= i) break;
        const std::size_t y = order_[j];
        if (y > x && y > latest()) break;
        if (const std::optional<double> depth = overlapDepth(x, y))
          keep({std::max(x, y), std::min(x, y), *depth});
      }
    }
  };
  std::size_t cursors[9] = {};
  for (std::size_t cell = 0; cell < cellKeys_.size() && maxReported > 0; ++cell) {
    const CellKey& key = cellKeys_[cell];
    int row = 0;
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy, ++row) {
        const CellKey first{key.level, key.x + dx, key.y + dy, key.z - 1};
        const CellKey last{key.level, key.x + dx, key.y + dy, key.z + 1};
        std::size_t& cursor = cursors[row];
        while (cursor < cellKeys_.size() && cellKeys_[cursor] < first) ++cursor;
        // Each pair of cells once: from the later of the two.
        for (std::size_t other = cursor;
             other <= cell && other < cellKeys_.size() && !(last < cellKeys_[other]); ++other)
          testCells(cell, other);
      }
    }
  }
  for (; !kept.empty(); kept.pop()) pending_.push(kept.top());
}

void BallOverlapFinder::find(std::size_t index) {
  const Ball& ball = balls_[index];
  const int ownLevel = levels_[index];
  for (auto level = std::upper_bound(usedLevels_.begin(), usedLevels_.end(), ownLevel);
       level != usedLevels_.end(); ++level) {
    const CellKey centre = cellOf(ball.position, *level);
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const Range* cell = findCell({*level, centre.x + dx, centre.y + dy, centre.z + dz});
          if (!cell) continue;
          for (std::size_t k = cell->begin; k < cell->end; ++k) {
            const std::size_t other = order_[k];
            if (const std::optional<double> depth = overlapDepth(index, other))
              pending_.push({std::max(index, other), std::min(index, other), *depth});
          }
        }
      }
    }
  }
}

const BallOverlapFinder::Range* BallOverlapFinder::findCell(const CellKey& key) const {
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t slot = CellHash{}(key)&mask;; slot = (slot + 1) & mask) {
    const std::uint32_t cell = slots_[slot];
    if (cell == 0) return nullptr;
    if (cellKeys_[cell - 1] == key) return &cellRanges_[cell - 1];
  }
}

std::optional<double> BallOverlapFinder::overlapDepth(std::size_t a, std::size_t b) const {
  const double radiusSum = balls_[a].radius + balls_[b].radius;
  const double depth = radiusSum - (balls_[a].position - balls_[b].position).norm();
  if (!overlaps(depth, radiusSum)) return std::nullopt;
  return depth;
}

}  // namespace carom::validation
