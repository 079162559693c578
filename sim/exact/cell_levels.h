#pragma once
// The event engine's broad phase: where every ball is in the cell grids, which balls are near
// it, and which static shapes a ball in its cell can meet. The engine asks it for a ball's
// neighbours, its static shapes and its next cell crossing, and tells it when a ball crosses or
// is placed; it knows nothing of contacts.
//
// Balls of very different sizes live in grids of their own (levels, by size class): cells sized
// by the largest ball of all would put thousands of small balls in one cell. A ball finds the
// larger balls it may touch in the cells of their levels around it, and the smaller ones in
// their levels' cells under its own level's block of 3x3x3 cells (Ogarko and Luding, "A fast
// multilevel algorithm for contact detection of arbitrarily polydisperse objects", 2012). It
// follows its position in every larger level's grid by crossing events, as in its own.
//
// A ball at least eight times larger than another level's balls follows its cell in that
// level's grid too, and finds them in the box of cells its own size around it rather than under
// its block, which is 27 times the volume: every collision of a boulder ploughing through sand
// predicts it again against every grain so found. A grain then looks for boulders in their
// level's block around it at each of its own crossings.

#include "sim/dynamics/bodies.h"
#include "sim/exact/cell_grid.h"
#include "sim/exact/static_ref.h"
#include "sim/geometry/contact_time.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace carom {

class CellLevels {
 public:
  // A ball's next move to a neighbouring cell, in its own level or one it is followed in.
  struct Crossing {
    double time = std::numeric_limits<double>::infinity();  // absolute
    std::int8_t axis = 0;
    std::int8_t direction = 0;
    std::int8_t level = 0;  // the ball's own, or a larger one it is followed in
  };

  // The levels and their grids around the balls at `positions` (each ball's position now), and
  // each cell's static shapes.
  void build(const Bodies& bodies, const std::vector<Vec3>& positions);
  // A level's border cells hold many more balls than when it was built (balls spread beyond the
  // region it covers): they would all be one another's neighbours there, so the engine builds
  // the levels again.
  bool crowded() const { return crowded_; }

  // The static shapes a ball in ball i's cell can meet.
  std::span<const StaticRef> staticsNear(int i) const {
    const Place& p = places_[i];
    return {statics_.data() + p.staticBegin, statics_.data() + p.staticEnd};
  }
  // Calls f(ball) for every ball, other than i, whose cell in any level is near enough to touch i.
  template <typename F>
  void forEachNeighbour(int i, F&& f) const;

  // Ball i's next crossing on `path` from `now`, none later than `horizon`; `straight` when the
  // path has no acceleration.
  Crossing nextCrossing(int i, const BallPath& path, double now, double horizon,
                        bool straight) const;
  // Ball i makes `crossing`; true when it moved to another cell of its own level (and so has
  // other static shapes near).
  bool cross(int i, const Crossing& crossing);
  // Calls f(ball) for the balls that just came into ball i's reach by `crossing`: those in the
  // layer of cells ahead of its block in the crossed level, or, in a finer level it follows, in
  // the face of its box ahead.
  template <typename F>
  void forEachBallComingIntoReach(int i, const Crossing& crossing, F&& f) const;
  // Ball i was put at `position` (the held ball, placed by the user).
  void place(int i, const Vec3& position);

  // The grid in use, for run reports ("cell grid 20x20x20, 8000 cells").
  std::string summary() const;
  std::size_t memoryBytes() const;

 private:
  // Where a ball is filed.
  struct Place {
    CellGrid::Coords coords{};  // in its level's grid
    int cell = 0;               // its cell, numbered across all levels
    std::int8_t level = 0;
    int staticBegin = 0;  // the cell's static shapes in statics_, kept here to save a lookup
    int staticEnd = 0;
  };
  // The balls of one size class and their grid.
  struct Level {
    CellGrid grid;
    int firstCell = 0;  // its cells' first number across all levels
    double maxRadius = 0.0;
    double minRadius = std::numeric_limits<double>::infinity();
    int balls = 0;
    // Balls in the grid's border cells, now and just after it was built: when many more have
    // wandered out there, the grid is built again around where the balls are.
    int borderBalls = 0;
    int builtBorderBalls = 0;
  };

  void buildGrid(const Bodies& bodies, const std::vector<Vec3>& positions);
  void buildStaticLists(const Bodies& bodies, std::size_t ballCount);
  void noteStatics(int i);
  // Files ball i (at `at`, its position now) in its level's cell and follows it in the larger
  // levels.
  void fileBall(int i, const Vec3& at);
  void moveToCell(int i, const CellGrid::Coords& coords);
  // Ball i's coordinates in the other levels' grids, at `at` (levelCoords).
  void noteLevelCoords(int i, const Vec3& at);
  // Ball i's cell coordinates in another level `level`: each larger one, and the smaller ones it
  // follows (boxReach), there in the grid's lattice continued beyond it, since a large ball
  // outside a grid of small ones would otherwise have its box reach from the border cell deep
  // into it.
  CellGrid::Coords& levelCoords(int i, int level) {
    return levelCoords_[std::size_t(i) * levels_.size() + level];
  }
  const CellGrid::Coords& levelCoords(int i, int level) const {
    return levelCoords_[std::size_t(i) * levels_.size() + level];
  }
  // Calls f(cell) for the cells of the level `finer` (numbered across levels) that meet the box
  // of level `level`'s cells from `from` to `to` (clamped to its grid), with a cell more on
  // every side against rounding.
  template <typename F>
  void forEachFinerCell(int finer, int level, CellGrid::Coords from, CellGrid::Coords to,
                        F&& f) const;
  // How far, in cells of finer level `finer`, a ball of level `level` finds that level's balls
  // around its cell there; zero when it finds them under its block instead (too close in size).
  const CellGrid::Coords& boxReach(int level, int finer) const {
    return boxReach_[std::size_t(level) * levels_.size() + finer];
  }
  bool followsFiner(int level, int finer) const { return boxReach(level, finer)[0] > 0; }
  // How far beyond the finer grid the lattice a ball of `level` follows there goes along an
  // axis: past its box's reach, the box holds no cell of the grid but its border.
  int latticeMargin(int level, int finer, int axis) const {
    return boxReach(level, finer)[axis] + 1;
  }
  // The box of cells in finer level `finer` that ball k, which follows it, finds its balls in:
  // `boxReach` around `around` (its lattice cell there, or a face of it) clamped into the grid,
  // so that a box beyond the grid still holds the border cells, which reach to infinity.
  std::pair<CellGrid::Coords, CellGrid::Coords> followerBox(int k, int finer,
                                                            const CellGrid::Coords& around) const {
    const CellGrid::Coords& reach = boxReach(places_[k].level, finer);
    const CellGrid::Coords& counts = levels_[finer].grid.counts();
    CellGrid::Coords from, to;
    for (int a = 0; a < 3; ++a) {
      from[a] = std::clamp(around[a] - reach[a], 0, counts[a] - 1);
      to[a] = std::clamp(around[a] + reach[a], 0, counts[a] - 1);
    }
    return {from, to};
  }
  // Whether ball i's cell is in the box of larger ball k, which follows i's level.
  bool inFollowersBox(int i, int k) const {
    const Place& p = places_[i];
    const auto [from, to] = followerBox(k, p.level, levelCoords(k, p.level));
    for (int a = 0; a < 3; ++a)
      if (p.coords[a] < from[a] || p.coords[a] > to[a]) return false;
    return true;
  }
  // Calls f(cell) for the cells of level `level` from `from` to `to`, clamped to its grid.
  template <typename F>
  void forEachCellIn(int level, CellGrid::Coords from, CellGrid::Coords to, F&& f) const;
  template <typename F>
  void forEachNeighbourAcrossLevels(int i, F&& f) const;

  std::vector<Place> places_;
  std::vector<Level> levels_;
  std::vector<CellGrid::Coords> levelCoords_;  // per ball and level (only larger levels used)
  std::vector<CellGrid::Coords> boxReach_;     // per level and finer level (boxReach)
  bool crowded_ = false;                       // a level's border cells are crowded
  CellMembership members_;
  std::vector<int> staticStart_;  // CSR: static shapes near each cell
  bool sharedStatics_ = false;    // every cell uses all of statics_
  std::vector<StaticRef> statics_;
};

template <typename F>
void CellLevels::forEachNeighbour(int i, F&& f) const {
  if (levels_.size() > 1) {
    forEachNeighbourAcrossLevels(i, f);
    return;
  }
  levels_[0].grid.forEachNeighbourCell(places_[i].coords, [&](int cell) {
    members_.forEachIn(cell, [&](int k) {
      if (k != i) f(k);
    });
  });
}

template <typename F>
void CellLevels::forEachBallComingIntoReach(int i, const Crossing& crossing, F&& f) const {
  const Place& p = places_[i];
  const int crossed = crossing.level;
  const bool own = crossed == p.level;
  const int axis = crossing.axis;
  const CellGrid::Coords& coords = own ? p.coords : levelCoords(i, crossed);
  CellGrid::Coords from = coords, to = coords;
  if (crossed < p.level) {
    // The box's face ahead: the lattice cell it is now, moved by its reach.
    CellGrid::Coords ahead = coords;
    ahead[axis] += crossing.direction * boxReach(p.level, crossed)[axis];
    std::tie(from, to) = followerBox(i, crossed, ahead);
    from[axis] = to[axis] = std::clamp(ahead[axis], 0, levels_[crossed].grid.counts()[axis] - 1);
  } else {
    for (int a = 0; a < 3; ++a) {
      --from[a];
      ++to[a];
    }
    (crossing.direction > 0 ? from : to)[axis] = (crossing.direction > 0 ? to : from)[axis];
  }
  const auto visitCell = [&](int cell) { members_.forEachIn(cell, f); };
  forEachCellIn(crossed, from, to, visitCell);
  if (!own) return;
  for (int l = 0; l < static_cast<int>(levels_.size()); ++l) {
    if (l < p.level && !followsFiner(p.level, l)) {
      // The smaller balls under the new layer of its own cells.
      forEachFinerCell(l, p.level, from, to, visitCell);
    } else if (l > p.level && followsFiner(l, p.level)) {
      // Larger balls that follow this level: it may have come into their boxes.
      levels_[l].grid.forEachNeighbourCell(levelCoords(i, l), [&](int cell) {
        members_.forEachIn(levels_[l].firstCell + cell, [&](int k) {
          if (inFollowersBox(i, k)) f(k);
        });
      });
    }
  }
}

template <typename F>
void CellLevels::forEachCellIn(int level, CellGrid::Coords from, CellGrid::Coords to, F&& f) const {
  const Level& cells = levels_[level];
  for (int a = 0; a < 3; ++a) {
    from[a] = std::max(from[a], 0);
    to[a] = std::min(to[a], cells.grid.counts()[a] - 1);
    if (from[a] > to[a]) return;
  }
  for (int z = from[2]; z <= to[2]; ++z)
    for (int y = from[1]; y <= to[1]; ++y)
      for (int x = from[0]; x <= to[0]; ++x) f(cells.firstCell + cells.grid.index({x, y, z}));
}

template <typename F>
void CellLevels::forEachFinerCell(int finer, int level, CellGrid::Coords from, CellGrid::Coords to,
                                  F&& f) const {
  const CellGrid& coarse = levels_[level].grid;
  const Level& fine = levels_[finer];
  CellGrid::Coords low, high;
  for (int a = 0; a < 3; ++a) {
    from[a] = std::max(from[a], 0);
    to[a] = std::min(to[a], coarse.counts()[a] - 1);
    if (from[a] > to[a]) return;
    low[a] = std::max(fine.grid.coordOf(a, coarse.lowerFace(a, from[a])) - 1, 0);
    high[a] =
        std::min(fine.grid.coordOf(a, coarse.upperFace(a, to[a])) + 1, fine.grid.counts()[a] - 1);
  }
  for (int z = low[2]; z <= high[2]; ++z)
    for (int y = low[1]; y <= high[1]; ++y)
      for (int x = low[0]; x <= high[0]; ++x) f(fine.firstCell + fine.grid.index({x, y, z}));
}

template <typename F>
void CellLevels::forEachNeighbourAcrossLevels(int i, F&& f) const {
  const Place& p = places_[i];
  const auto visitCell = [&](int cell) {
    members_.forEachIn(cell, [&](int k) {
      if (k != i) f(k);
    });
  };
  for (int l = 0; l < static_cast<int>(levels_.size()); ++l) {
    const Level& level = levels_[l];
    if (l < p.level && followsFiner(p.level, l)) {
      const auto [from, to] = followerBox(i, l, levelCoords(i, l));
      forEachCellIn(l, from, to, visitCell);
      continue;
    }
    if (l < p.level) {
      CellGrid::Coords from = p.coords, to = p.coords;
      for (int a = 0; a < 3; ++a) {
        --from[a];
        ++to[a];
      }
      forEachFinerCell(l, p.level, from, to, visitCell);
      continue;
    }
    const CellGrid::Coords& around = l == p.level ? p.coords : levelCoords(i, l);
    if (l > p.level && followsFiner(l, p.level)) {
      // Those whose boxes hold it: it meets no other.
      level.grid.forEachNeighbourCell(around, [&](int cell) {
        members_.forEachIn(level.firstCell + cell, [&](int k) {
          if (inFollowersBox(i, k)) f(k);
        });
      });
      continue;
    }
    level.grid.forEachNeighbourCell(around, [&](int cell) { visitCell(level.firstCell + cell); });
  }
}

}  // namespace carom
