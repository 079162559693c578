// The cells: a grid for each size class of balls over where they are, built again when they
// spread beyond it, and for each cell the static shapes a ball in it can meet.

#include "sim/exact/cell_levels.h"

#include "sim/core/prefault.h"
#include "sim/geometry/contact_time.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace carom {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

// Size classes: a ball's is how many times its radius doubles the smallest one's, so that a
// class's cells, sized by its largest ball, are at most about twice its smallest balls'
// diameter. Radii may span 80 doublings (tol::kMinRadius to tol::kMaxMagnitude): beyond
// kMaxSizeClasses a class spans several doublings, so that every ball's coordinates in every
// class's grid (levelCoords) stay within memory.
constexpr int kMaxSizeClasses = 12;

int sizeClass(double radius, double smallest, int doublingsPerClass) {
  return static_cast<int>(std::floor(std::log2(radius / smallest))) / doublingsPerClass;
}

}  // namespace

void CellLevels::build(const Bodies& bodies, const std::vector<Vec3>& positions) {
  buildGrid(bodies, positions);
  buildStaticLists(bodies, positions.size());
  for (int i = 0; i < static_cast<int>(positions.size()); ++i) noteStatics(i);
}

void CellLevels::buildGrid(const Bodies& bodies, const std::vector<Vec3>& positions) {
  const int n = static_cast<int>(positions.size());
  levels_.clear();
  levelCoords_.clear();
  crowded_ = false;
  if (places_.size() != positions.size()) resizePrefaulted(places_, positions.size());
  if (n == 0) {
    // A scene without balls (being built in the editor) gets one unit cell.
    levels_.push_back({CellGrid(Vec3::Zero(), Vec3::Zero(), 1.0, 64)});
    members_.reset(levels_[0].grid.cellCount(), 0);
    return;
  }
  double smallest = kNever, largest = 0.0;
  for (int i = 0; i < n; ++i) {
    smallest = std::min(smallest, bodies.radius[i]);
    largest = std::max(largest, bodies.radius[i]);
  }
  smallest = std::max(smallest, std::numeric_limits<double>::min());
  const int doublings = static_cast<int>(std::floor(std::log2(largest / smallest)));
  const int doublingsPerClass = std::max(1, doublings / kMaxSizeClasses + 1);
  std::vector<int> classes;
  for (int i = 0; i < n; ++i)
    classes.push_back(sizeClass(bodies.radius[i], smallest, doublingsPerClass));
  std::vector<int> used = classes;
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  levels_.resize(used.size());
  std::vector<Vec3> lower(used.size(), Vec3::Constant(kNever));
  std::vector<Vec3> upper(used.size(), Vec3::Constant(-kNever));
  for (int i = 0; i < n; ++i) {
    const int l =
        static_cast<int>(std::lower_bound(used.begin(), used.end(), classes[i]) - used.begin());
    places_[i].level = static_cast<std::int8_t>(l);
    const Vec3& at = positions[i];
    lower[l] = lower[l].cwiseMin(at);
    upper[l] = upper[l].cwiseMax(at);
    levels_[l].maxRadius = std::max(levels_[l].maxRadius, bodies.radius[i]);
    levels_[l].minRadius = std::min(levels_[l].minRadius, bodies.radius[i]);
    ++levels_[l].balls;
  }
  // Each grid covers its balls where they are now, and the finite shapes, where balls go (a
  // board's pegs below the balls poured onto it); balls that spread beyond it make the grids be
  // built again (rebuildCellsIfCrowded). The planes are left out: a room may be far larger than
  // where its balls are. Cells a little wider than the largest diameter, so contacts never skip
  // a cell.
  Vec3 shapesLower = Vec3::Constant(kNever), shapesUpper = Vec3::Constant(-kNever);
  const auto cover = [&](const Vec3& centre, const Vec3& reach) {
    shapesLower = shapesLower.cwiseMin(centre - reach);
    shapesUpper = shapesUpper.cwiseMax(centre + reach);
  };
  for (const CylinderShape& cylinder : bodies.cylinders)
    if (cylinder.capped()) cover(cylinder.point, cylinder.reach());
  for (const BoxShape& box : bodies.boxes) cover(box.center, box.reach());
  int cells = 0;
  for (std::size_t l = 0; l < levels_.size(); ++l) {
    Level& level = levels_[l];
    lower[l] = lower[l].cwiseMin(shapesLower);
    upper[l] = upper[l].cwiseMax(shapesUpper);
    const double margin = 2.0 * level.maxRadius;
    const double cellSize = std::max(2.0 * level.maxRadius * (1.0 + 1e-9), 1e-300);
    level.grid = CellGrid(lower[l] - Vec3::Constant(margin), upper[l] + Vec3::Constant(margin),
                          cellSize, 32 * std::size_t(level.balls) + 64);
    level.firstCell = cells;
    cells += level.grid.cellCount();
  }
  members_.reset(cells, n);
  // A ball follows a finer level when its box there holds no more than its block of cells in its
  // own level would hand over to a ball of that level: the grain finds it in the block around
  // it (forEachNeighbourAcrossLevels). Touching, a ball of radius R and one of radius r are at
  // most R + r apart along each axis, within the box's reach of cells and one more for where in
  // its cell each centre is; the grain's block covers one cell of the larger level, at least 2R,
  // around it, so the box reach of R + r and two of the grains' cells (2r each) more must be
  // within 2R: R at least 7 r. 8 r keeps a margin for rounding.
  //
  // Following costs a crossing event each finer cell the ball moves across: past a reach of
  // kMaxBoxReach cells (radius ratios of some thousands, or a finer grid made coarse by its cell
  // budget) the ball finds the finer balls under its block instead, where they are few.
  constexpr double kFollowRatio = 8.0;
  constexpr double kMaxBoxReach = 4096.0;
  const int levelCount = static_cast<int>(levels_.size());
  boxReach_.assign(std::size_t(levelCount) * levelCount, CellGrid::Coords{0, 0, 0});
  for (int l = 0; l < levelCount; ++l)
    for (int finer = 0; finer < l; ++finer) {
      if (levels_[l].minRadius < kFollowRatio * levels_[finer].maxRadius) continue;
      CellGrid::Coords reach{};
      bool near = true;
      for (int a = 0; a < 3; ++a) {
        const double cells = std::ceil((levels_[l].maxRadius + levels_[finer].maxRadius) /
                                       levels_[finer].grid.cellSize(a)) +
                             1.0;
        near = near && cells <= kMaxBoxReach;
        reach[a] = near ? static_cast<int>(cells) : 0;
      }
      if (near) boxReach_[std::size_t(l) * levelCount + finer] = reach;
    }
  if (levelCount > 1) levelCoords_.resize(std::size_t(n) * levelCount);
  for (int i = 0; i < n; ++i) fileBall(i, positions[i]);
  for (Level& level : levels_) level.builtBorderBalls = level.borderBalls;
}

void CellLevels::fileBall(int i, const Vec3& at) {
  Place& p = places_[i];
  Level& level = levels_[p.level];
  p.coords = level.grid.coordsOf(at);
  p.cell = level.firstCell + level.grid.index(p.coords);
  members_.insert(i, p.cell);
  if (level.grid.isBorder(p.coords)) ++level.borderBalls;
  noteLevelCoords(i, at);
}

void CellLevels::noteLevelCoords(int i, const Vec3& at) {
  const int own = places_[i].level;
  for (int l = 0; l < static_cast<int>(levels_.size()); ++l) {
    const CellGrid& grid = levels_[l].grid;
    if (l > own) {
      levelCoords(i, l) = grid.coordsOf(at);
    } else if (l < own && followsFiner(own, l)) {
      for (int a = 0; a < 3; ++a)
        levelCoords(i, l)[a] = grid.latticeCoordOf(a, at[a], latticeMargin(own, l, a));
    }
  }
}

void CellLevels::moveToCell(int i, const CellGrid::Coords& coords) {
  Place& p = places_[i];
  Level& level = levels_[p.level];
  if (level.grid.isBorder(p.coords)) --level.borderBalls;
  p.coords = coords;
  members_.remove(i);
  p.cell = level.firstCell + level.grid.index(coords);
  members_.insert(i, p.cell);
  if (level.grid.isBorder(coords) &&
      ++level.borderBalls > level.builtBorderBalls + std::max(64, level.balls / 8))
    crowded_ = true;
  noteStatics(i);
}

void CellLevels::buildStaticLists(const Bodies& bodies, std::size_t ballCount) {
  int cells = 0;
  for (const Level& level : levels_) cells += level.grid.cellCount();
  reservePrefaulted(staticStart_, std::size_t(cells) + 1);
  staticStart_.assign(cells + 1, 0);
  statics_.clear();
  sharedStatics_ = false;
  // Visits every (cell, shape) pair that is near, level by level and in each shape by shape in
  // the lists' order (planes, cylinders, boxes), so each cell's list comes out in that order. A
  // level's cells hold shapes within reach of its largest ball.
  const auto forEachNearPair = [&](auto&& f) {
    for (const Level& level : levels_) {
      const CellGrid& grid = level.grid;
      const double reach = level.maxRadius * (1.0 + 1e-9);
      // The cells' faces along each axis, computed once: a million balls make some ten million
      // cells, each tested against every unbounded shape.
      std::array<std::vector<double>, 3> lowerFaces, upperFaces;
      for (int a = 0; a < 3; ++a)
        for (int i = 0; i < grid.counts()[a]; ++i) {
          lowerFaces[a].push_back(grid.lowerFace(a, i));
          upperFaces[a].push_back(grid.upperFace(a, i));
        }
      // What a cell's test needs of it.
      struct CellBox {
        Vec3 lo, hi;
        bool border;
        Vec3 centre() const { return 0.5 * (lo + hi); }
        // Its bounding sphere's radius, grown by the reach.
        double sphere(double reach) const { return 0.5 * (hi - lo).norm() + reach; }
      };
      const auto cellBox = [&](const CellGrid::Coords& c) {
        CellBox box;
        box.border = grid.isBorder(c);
        for (int a = 0; a < 3; ++a) {
          box.lo[a] = lowerFaces[a][c[a]];
          box.hi[a] = upperFaces[a][c[a]];
        }
        return box;
      };
      const auto planeNear = [&](const PlaneShape& plane, const CellBox& box) {
        // Nearest corner of the cell to the surface (or behind it) decides.
        if (box.border) return true;
        double nearest = -plane.offset;
        for (int a = 0; a < 3; ++a)
          nearest += plane.normal[a] * (plane.normal[a] > 0 ? box.lo[a] : box.hi[a]);
        return nearest <= reach;
      };
      // A finite shape only where it is: its bounding box grown by the reach meets the cell (a
      // border cell's infinite side included), and for a cell inside the grid its bounding sphere.
      const auto finiteNear = [&](const Vec3& shapeCentre, const Vec3& shapeReach,
                                  const CellBox& box, auto gapToCentre) {
        const Vec3 low = shapeCentre - shapeReach - Vec3::Constant(reach);
        const Vec3 high = shapeCentre + shapeReach + Vec3::Constant(reach);
        if ((high.array() < box.lo.array()).any() || (low.array() > box.hi.array()).any())
          return false;
        return box.border || gapToCentre(box.centre()) <= box.sphere(reach);
      };
      // Round shapes are near when they come within the cell's bounding sphere; border cells reach
      // out to infinity and see every infinite cylinder.
      const auto cylinderNear = [&](const CylinderShape& cylinder, const CellBox& box) {
        const auto gap = [&](const Vec3& at) { return cylinder.contact(at, 0.0).gap; };
        return cylinder.capped() ? finiteNear(cylinder.point, cylinder.reach(), box, gap)
                                 : box.border || gap(box.centre()) <= box.sphere(reach);
      };
      const auto boxNear = [&](const BoxShape& shape, const CellBox& box) {
        return finiteNear(shape.center, shape.reach(), box,
                          [&](const Vec3& at) { return shape.contact(at, 0.0).gap; });
      };
      // Every cell whose test could pass, as f(cell, its box): all of them for unbounded shapes;
      // for a finite one only those its grown bounding box covers, give or take a cell for
      // rounding, so that a board of millions of cells and hundreds of pegs is not every cell
      // against every peg.
      const auto forEachCandidate = [&](const Vec3* centre, const Vec3& shapeReach, auto&& f) {
        CellGrid::Coords from{0, 0, 0}, to = grid.counts();
        for (int a = 0; a < 3; ++a) --to[a];
        if (centre) {
          const Vec3 grown = shapeReach + Vec3::Constant(reach);
          from = grid.coordsOf(*centre - grown);
          to = grid.coordsOf(*centre + grown);
          for (int a = 0; a < 3; ++a) {
            from[a] = std::max(from[a] - 1, 0);
            to[a] = std::min(to[a] + 1, grid.counts()[a] - 1);
          }
        }
        for (int z = from[2]; z <= to[2]; ++z)
          for (int y = from[1]; y <= to[1]; ++y)
            for (int x = from[0]; x <= to[0]; ++x) f(grid.index({x, y, z}), cellBox({x, y, z}));
      };
      // The cells planeNear accepts, row by row along x. Inside a row the test's value moves one
      // way with x (each rounded step of its sum keeps order), so the near cells inside the grid
      // are a run from one end, found without testing the far ones: a million balls make some ten
      // million cells, of which a plane is near a few layers.
      const auto forEachCellNearPlane = [&](const PlaneShape& plane, auto&& f) {
        const CellGrid::Coords& counts = grid.counts();
        const double nx = plane.normal.x();
        for (int z = 0; z < counts[2]; ++z)
          for (int y = 0; y < counts[1]; ++y) {
            const int first = grid.index({0, y, z});
            const bool borderRow = y == 0 || z == 0 || y + 1 == counts[1] || z + 1 == counts[2];
            if (borderRow || counts[0] <= 2) {
              for (int x = 0; x < counts[0]; ++x) f(first + x);
              continue;
            }
            const auto near = [&](int x) { return planeNear(plane, cellBox({x, y, z})); };
            f(first);  // the border cells at both ends of the row
            if (nx > 0.0) {
              for (int x = 1; x + 1 < counts[0] && near(x); ++x) f(first + x);
            } else if (nx < 0.0) {
              for (int x = counts[0] - 2; x > 0 && near(x); --x) f(first + x);
            } else if (near(1)) {
              for (int x = 1; x + 1 < counts[0]; ++x) f(first + x);
            }
            f(first + counts[0] - 1);
          }
      };
      const auto forEachNearPairInLevel = [&](auto&& f) {
        for (int k = 0; k < static_cast<int>(bodies.planes.size()); ++k)
          forEachCellNearPlane(bodies.planes[k], [&](int cell) {
            f(level.firstCell + cell, StaticRef{StaticKind::Plane, k});
          });
        for (int k = 0; k < static_cast<int>(bodies.cylinders.size()); ++k) {
          const CylinderShape& cylinder = bodies.cylinders[k];
          const Vec3* centre = cylinder.capped() ? &cylinder.point : nullptr;
          forEachCandidate(centre, cylinder.capped() ? cylinder.reach() : Vec3::Zero(),
                           [&](int cell, const CellBox& box) {
                             if (cylinderNear(cylinder, box))
                               f(level.firstCell + cell, StaticRef{StaticKind::Cylinder, k});
                           });
        }
        for (int k = 0; k < static_cast<int>(bodies.boxes.size()); ++k) {
          const BoxShape& shape = bodies.boxes[k];
          forEachCandidate(&shape.center, shape.reach(), [&](int cell, const CellBox& box) {
            if (boxNear(shape, box)) f(level.firstCell + cell, StaticRef{StaticKind::Box, k});
          });
        }
      };
      forEachNearPairInLevel(f);
    }
  };
  std::size_t total = 0;
  forEachNearPair([&](int cell, StaticRef) {
    ++staticStart_[cell + 1];
    ++total;
  });
  // Many shapes in many cells would take more memory than the lists save time: then every cell
  // shares one list of all shapes.
  const std::size_t budget = 16 * (ballCount + 1024) + 4 * std::size_t(cells);
  if (total > budget) {
    staticStart_.assign(cells + 1, 0);
    for (int k = 0; k < static_cast<int>(bodies.planes.size()); ++k)
      statics_.push_back({StaticKind::Plane, k});
    for (int k = 0; k < static_cast<int>(bodies.cylinders.size()); ++k)
      statics_.push_back({StaticKind::Cylinder, k});
    for (int k = 0; k < static_cast<int>(bodies.boxes.size()); ++k)
      statics_.push_back({StaticKind::Box, k});
    sharedStatics_ = true;
    return;
  }
  for (int cell = 0; cell < cells; ++cell) staticStart_[cell + 1] += staticStart_[cell];
  statics_.resize(total);
  std::vector<int> cursor(staticStart_.begin(), staticStart_.end() - 1);
  forEachNearPair([&](int cell, StaticRef ref) { statics_[cursor[cell]++] = ref; });
}

void CellLevels::noteStatics(int i) {
  Place& p = places_[i];
  p.staticBegin = sharedStatics_ ? 0 : staticStart_[p.cell];
  p.staticEnd = sharedStatics_ ? static_cast<int>(statics_.size()) : staticStart_[p.cell + 1];
}

CellLevels::Crossing CellLevels::nextCrossing(int i, const BallPath& path, double now,
                                              double horizon, bool straight) const {
  Crossing next;
  // A crossing closer than the time's resolution comes an ulp later rather than now: the ball
  // has not reached the face yet, and one taken now found the ball back beyond the face it had
  // crossed and crossed again, to and fro for ever at one instant (at 5e53 s, gravity switched
  // on brought a ball back to a face 1e49 m below it in 1e23 s).
  const auto timeOf = [&](double t) {
    const double time = now + t;
    return t > 0.0 && time <= now ? std::nextafter(now, kNever) : time;
  };
  // In a finer level it follows, a ball crosses the faces of the lattice beyond the grid too.
  const Place& p = places_[i];
  const auto findIn = [&](int l, const CellGrid::Coords& c, bool lattice) {
    const CellGrid& grid = levels_[l].grid;
    const auto lowerFace = [&](int a) {
      return lattice ? grid.latticeLowerFace(a, c[a], latticeMargin(p.level, l, a))
                     : grid.lowerFace(a, c[a]);
    };
    const auto upperFace = [&](int a) {
      return lattice ? grid.latticeUpperFace(a, c[a], latticeMargin(p.level, l, a))
                     : grid.upperFace(a, c[a]);
    };
    const auto level = static_cast<std::int8_t>(l);
    if (straight) {
      for (int a = 0; a < 3; ++a) {
        const double t =
            straightExitTime(path.position[a], path.velocity[a], lowerFace(a), upperFace(a));
        const double time = timeOf(t);
        if (time < std::min(next.time, horizon))
          next = {time, static_cast<std::int8_t>(a),
                  static_cast<std::int8_t>(path.velocity[a] > 0.0 ? 1 : -1), level};
      }
      return;
    }
    for (int a = 0; a < 3; ++a) {
      for (int direction : {1, -1}) {
        const double face = direction > 0 ? upperFace(a) : lowerFace(a);
        const double until = std::min(next.time, horizon) - now;
        const double t = boundaryCrossingTime(path.position[a], path.velocity[a],
                                              path.acceleration[a], face, direction > 0, until);
        if (t < until)
          next = {timeOf(t), static_cast<std::int8_t>(a), static_cast<std::int8_t>(direction),
                  level};
      }
    }
  };
  findIn(p.level, p.coords, false);
  for (int l = 0; l < static_cast<int>(levels_.size()); ++l) {
    if (l > p.level) findIn(l, levelCoords(i, l), false);
    if (l < p.level && followsFiner(p.level, l)) findIn(l, levelCoords(i, l), true);
  }
  return next;
}

bool CellLevels::cross(int i, const Crossing& crossing) {
  Place& p = places_[i];
  const int crossed = crossing.level;
  const bool own = crossed == p.level;
  CellGrid::Coords coords = own ? p.coords : levelCoords(i, crossed);
  coords[crossing.axis] += crossing.direction;
  if (own)
    moveToCell(i, coords);
  else
    levelCoords(i, crossed) = coords;
  return own;
}

void CellLevels::place(int i, const Vec3& position) {
  const Place& p = places_[i];
  const CellGrid::Coords coords = levels_[p.level].grid.coordsOf(position);
  if (coords != p.coords) moveToCell(i, coords);
  noteLevelCoords(i, position);
}

std::string CellLevels::summary() const {
  std::string grid = levels_.size() > 1 ? "cell grids" : "cell grid";
  for (std::size_t l = 0; l < levels_.size(); ++l) {
    const CellGrid::Coords& c = levels_[l].grid.counts();
    grid += (l > 0 ? ", " : " ") + std::to_string(c[0]) + "x" + std::to_string(c[1]) + "x" +
            std::to_string(c[2]);
  }
  if (levels_.size() > 1) grid += " (" + std::to_string(levels_.size()) + " ball size classes)";
  if (sharedStatics_)
    return grid + ", all " + std::to_string(statics_.size()) + " static shapes in every cell";
  return grid + ", " + std::to_string(statics_.size()) + " static-shape entries in cells";
}

std::size_t CellLevels::memoryBytes() const {
  return carom::memoryBytes(places_) + members_.memoryBytes() + carom::memoryBytes(levelCoords_) +
         carom::memoryBytes(levels_) + carom::memoryBytes(staticStart_) +
         carom::memoryBytes(statics_);
}

}  // namespace carom
