#pragma once
// Uniform grid of cells over the balls' region, for finding a ball's neighbours. Cells are at
// least as wide as the largest ball's diameter, so balls that can touch are in adjacent cells.
// The outermost layer of cells reaches to infinity, so balls that leave the region are still
// filed (in border cells) and nothing is ever lost.

#include "sim/core/memory_bytes.h"
#include "sim/model/scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace carom {

class CellGrid {
 public:
  CellGrid() = default;
  // Covers the box [lower, upper] with cells of size at least `minCellSize`, at most `maxCells`
  // in all: coarser cells where smaller ones would be too many, whatever the box's size.
  CellGrid(const Vec3& lower, const Vec3& upper, double minCellSize, std::size_t maxCells);

  using Coords = std::array<int, 3>;

  int cellCount() const { return counts_[0] * counts_[1] * counts_[2]; }
  const Coords& counts() const { return counts_; }
  double cellSize(int axis) const { return size_[axis]; }

  Coords coordsOf(const Vec3& p) const;
  // The cell's coordinate along one axis at x (clamped: the border cells reach to infinity).
  int coordOf(int axis, double x) const {
    const double f = std::floor((x - origin_[axis]) / size_[axis]);
    return f < 0.0 ? 0 : (f >= counts_[axis] - 1 ? counts_[axis] - 1 : static_cast<int>(f));
  }
  int index(const Coords& c) const { return (c[2] * counts_[1] + c[1]) * counts_[0] + c[0]; }
  Coords coords(int cell) const;

  // The grid's lattice continued `margin` cells beyond it on every side: the cell coordinate at x
  // and the faces of any cell of it. Its outermost cells reach to infinity, as the grid's border
  // cells do, so that a position however far away is in a cell of it. Inside the grid, these are
  // the grid's own coordinates and faces.
  int latticeCoordOf(int axis, double x, int margin) const {
    const double f = std::floor((x - origin_[axis]) / size_[axis]);
    return static_cast<int>(std::clamp(f, -double(margin), double(counts_[axis] - 1 + margin)));
  }
  double latticeLowerFace(int axis, int k, int margin) const {
    return k <= -margin ? -std::numeric_limits<double>::infinity()
                        : origin_[axis] + k * size_[axis];
  }
  double latticeUpperFace(int axis, int k, int margin) const {
    return k >= counts_[axis] - 1 + margin ? std::numeric_limits<double>::infinity()
                                           : origin_[axis] + (k + 1) * size_[axis];
  }

  // Coordinates of the cell's faces along an axis; +-infinity for the outer faces of border cells.
  double lowerFace(int axis, int i) const {
    return i == 0 ? -std::numeric_limits<double>::infinity() : origin_[axis] + i * size_[axis];
  }
  double upperFace(int axis, int i) const {
    return i + 1 == counts_[axis] ? std::numeric_limits<double>::infinity()
                                  : origin_[axis] + (i + 1) * size_[axis];
  }
  // Box of a cell's interior region, ignoring infinite border extents (for static-shape lists).
  bool isBorder(const Coords& c) const;

  // Calls f(cell) for the up to 27 cells around `centre` (itself included).
  template <typename F>
  void forEachNeighbourCell(const Coords& centre, F&& f) const {
    if (centre[0] > 0 && centre[1] > 0 && centre[2] > 0 && centre[0] + 1 < counts_[0] &&
        centre[1] + 1 < counts_[1] && centre[2] + 1 < counts_[2]) {
      const int base = index(centre);  // inside: fixed offsets, no bounds to check
      for (int offset : neighbourOffsets_) f(base + offset);
      return;
    }
    const int x0 = centre[0] > 0 ? centre[0] - 1 : 0;
    const int x1 = centre[0] + 1 < counts_[0] ? centre[0] + 1 : centre[0];
    const int y0 = centre[1] > 0 ? centre[1] - 1 : 0;
    const int y1 = centre[1] + 1 < counts_[1] ? centre[1] + 1 : centre[1];
    const int z0 = centre[2] > 0 ? centre[2] - 1 : 0;
    const int z1 = centre[2] + 1 < counts_[2] ? centre[2] + 1 : centre[2];
    for (int z = z0; z <= z1; ++z)
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) f(index({x, y, z}));
  }

 private:
  Vec3 origin_ = Vec3::Zero();
  Vec3 size_ = Vec3::Ones();
  Coords counts_{1, 1, 1};
  std::array<int, 27> neighbourOffsets_{};
};

// Which balls are in which cell: an intrusive doubly linked list per cell, O(1) moves.
class CellMembership {
 public:
  void reset(int cellCount, int ballCount);
  void insert(int ball, int cell);
  void remove(int ball);
  int cellOf(int ball) const { return cell_[ball]; }
  std::size_t memoryBytes() const {
    return carom::memoryBytes(head_) + carom::memoryBytes(next_) + carom::memoryBytes(prev_) +
           carom::memoryBytes(cell_);
  }
  template <typename F>
  void forEachIn(int cell, F&& f) const {
    for (int b = head_[cell]; b >= 0; b = next_[b]) f(b);
  }

 private:
  std::vector<int> head_, next_, prev_, cell_;
};

}  // namespace carom
