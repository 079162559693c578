#include "sim/cell_grid.h"
#include "sim/prefault.h"

#include <algorithm>
#include <cmath>

namespace carom {

CellGrid::CellGrid(const Vec3& lower, const Vec3& upper, double minCellSize, std::size_t maxCells) {
  const Vec3 extent = (upper - lower).cwiseMax(minCellSize);
  double size = minCellSize;
  // Grow the cells until their number fits the budget.
  for (;;) {
    std::size_t total = 1;
    for (int a = 0; a < 3; ++a)
      total *= static_cast<std::size_t>(std::max(1.0, std::floor(extent[a] / size)));
    if (total <= std::max<std::size_t>(maxCells, 1)) break;
    size *= 1.25;
  }
  for (int a = 0; a < 3; ++a) {
    counts_[a] = static_cast<int>(std::max(1.0, std::floor(extent[a] / size)));
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
