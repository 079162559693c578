#include "sim/exact/cell_grid.h"
#include "sim/core/prefault.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace carom {

CellGrid::CellGrid(const Vec3& lower, const Vec3& upper, double minCellSize, std::size_t maxCells) {
  const Vec3 extent = (upper - lower).cwiseMax(minCellSize);
  // Grow the cells until their number fits the budget. Counted in doubles: cells of a 1e-12 m
  // ball over a region of 1e12 m number 1e72, beyond any integer type, and a count within the
  // budget is exact. The budget keeps every cell's number an int.
  const double budget =
      double(std::clamp<std::size_t>(maxCells, 1, std::numeric_limits<int>::max()));
  double size = minCellSize;
  const auto countAlong = [&](int a) { return std::max(1.0, std::floor(extent[a] / size)); };
  while (countAlong(0) * countAlong(1) * countAlong(2) > budget) size *= 1.25;
  for (int a = 0; a < 3; ++a) {
    counts_[a] = static_cast<int>(countAlong(a));
    size_[a] = extent[a] / counts_[a];  // >= size, so neighbours stay within one cell
    origin_[a] = lower[a];
  }
  int k = 0;
  for (int z = -1; z <= 1; ++z)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x) neighbourOffsets_[k++] = (z * counts_[1] + y) * counts_[0] + x;
}

CellGrid::Coords CellGrid::coordsOf(const Vec3& p) const {
  return {coordOf(0, p.x()), coordOf(1, p.y()), coordOf(2, p.z())};
}

CellGrid::Coords CellGrid::coords(int cell) const {
  const int x = cell % counts_[0];
  const int rest = cell / counts_[0];
  return {x, rest % counts_[1], rest / counts_[1]};
}

bool CellGrid::isBorder(const Coords& c) const {
  for (int a = 0; a < 3; ++a)
    if (c[a] == 0 || c[a] + 1 == counts_[a]) return true;
  return false;
}

void CellMembership::reset(int cellCount, int ballCount) {
  for (auto [values, count] : {std::pair{&head_, cellCount}, std::pair{&next_, ballCount},
                               std::pair{&prev_, ballCount}, std::pair{&cell_, ballCount}}) {
    reservePrefaulted(*values, std::size_t(count));
    values->assign(count, -1);
  }
}

void CellMembership::insert(int ball, int cell) {
  cell_[ball] = cell;
  prev_[ball] = -1;
  next_[ball] = head_[cell];
  if (head_[cell] >= 0) prev_[head_[cell]] = ball;
  head_[cell] = ball;
}

void CellMembership::remove(int ball) {
  const int cell = cell_[ball];
  if (prev_[ball] >= 0)
    next_[prev_[ball]] = next_[ball];
  else
    head_[cell] = next_[ball];
  if (next_[ball] >= 0) prev_[next_[ball]] = prev_[ball];
  cell_[ball] = -1;
}

}  // namespace carom
