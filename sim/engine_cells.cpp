// EventEngine's cells: the grid over the balls' region and, for each cell, the static shapes a
// ball in it can meet.

#include "sim/event_engine.h"

#include "sim/prefault.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace carom {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

// The grid covers the balls and stretches to axis-aligned planes, which usually bound the room.
void gridBounds(const Bodies& bodies, const std::vector<BallState>& state, Vec3& lower,
                Vec3& upper) {
  lower = Vec3::Constant(kNever);
  upper = Vec3::Constant(-kNever);
  for (const BallState& s : state) {
    lower = lower.cwiseMin(s.position);
    upper = upper.cwiseMax(s.position);
  }
  if (state.empty()) lower = upper = Vec3::Zero();
  for (const PlaneShape& plane : bodies.planes) {
    for (int a = 0; a < 3; ++a) {
      if (std::abs(plane.normal[a]) < 1.0 - 1e-12) continue;
      const double at = plane.offset / plane.normal[a];
      lower[a] = std::min(lower[a], at);
      upper[a] = std::max(upper[a], at);
    }
  }
  const double margin = 2.0 * bodies.maxRadius;
  lower -= Vec3::Constant(margin);
  upper += Vec3::Constant(margin);
}

}  // namespace

void EventEngine::buildGrid(const std::vector<BallState>& state) {
  Vec3 lower = Vec3::Zero(), upper = Vec3::Zero();
  if (!particles_.empty()) gridBounds(bodies_, state, lower, upper);
  // Cells a little wider than the largest diameter, so contacts never skip a cell. A scene
  // without balls (being built in the editor) gets one unit cell.
  const double cellSize =
      particles_.empty() ? 1.0 : std::max(2.0 * bodies_.maxRadius * (1.0 + 1e-9), 1e-300);
  const std::size_t maxCells = 32 * particles_.size() + 64;
  grid_ = CellGrid(lower, upper, cellSize, maxCells);
  members_.reset(grid_.cellCount(), static_cast<int>(particles_.size()));
  for (int i = 0; i < static_cast<int>(particles_.size()); ++i) {
    particles_[i].coords = grid_.coordsOf(tracks_[i].motion.position);
    particles_[i].cell = grid_.index(particles_[i].coords);
    members_.insert(i, particles_[i].cell);
  }
}

void EventEngine::buildStaticLists() {
  const int cells = grid_.cellCount();
  reservePrefaulted(staticStart_, std::size_t(cells) + 1);
  staticStart_.assign(cells + 1, 0);
  statics_.clear();
  sharedStatics_ = false;
  const double reach = bodies_.maxRadius * (1.0 + 1e-9);
  // The cells' faces along each axis, computed once: a million balls make some ten million
  // cells, each tested against every unbounded shape.
  std::array<std::vector<double>, 3> lowerFaces, upperFaces;
  for (int a = 0; a < 3; ++a)
    for (int i = 0; i < grid_.counts()[a]; ++i) {
      lowerFaces[a].push_back(grid_.lowerFace(a, i));
      upperFaces[a].push_back(grid_.upperFace(a, i));
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
    box.border = grid_.isBorder(c);
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
  const auto finiteNear = [&](const Vec3& shapeCentre, const Vec3& shapeReach, const CellBox& box,
                              auto gapToCentre) {
    const Vec3 low = shapeCentre - shapeReach - Vec3::Constant(reach);
    const Vec3 high = shapeCentre + shapeReach + Vec3::Constant(reach);
    if ((high.array() < box.lo.array()).any() || (low.array() > box.hi.array()).any()) return false;
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
    CellGrid::Coords from{0, 0, 0}, to = grid_.counts();
    for (int a = 0; a < 3; ++a) --to[a];
    if (centre) {
      const Vec3 grown = shapeReach + Vec3::Constant(reach);
      from = grid_.coordsOf(*centre - grown);
      to = grid_.coordsOf(*centre + grown);
      for (int a = 0; a < 3; ++a) {
        from[a] = std::max(from[a] - 1, 0);
        to[a] = std::min(to[a] + 1, grid_.counts()[a] - 1);
      }
    }
    for (int z = from[2]; z <= to[2]; ++z)
      for (int y = from[1]; y <= to[1]; ++y)
        for (int x = from[0]; x <= to[0]; ++x) f(grid_.index({x, y, z}), cellBox({x, y, z}));
  };
  // The cells planeNear accepts, row by row along x. Inside a row the test's value moves one
  // way with x (each rounded step of its sum keeps order), so the near cells inside the grid
  // are a run from one end, found without testing the far ones: a million balls make some ten
  // million cells, of which a plane is near a few layers.
  const auto forEachCellNearPlane = [&](const PlaneShape& plane, auto&& f) {
    const CellGrid::Coords& counts = grid_.counts();
    const double nx = plane.normal.x();
    for (int z = 0; z < counts[2]; ++z)
      for (int y = 0; y < counts[1]; ++y) {
        const int first = grid_.index({0, y, z});
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
  // Visits every (cell, shape) pair that is near, shape by shape in the lists' order (planes,
  // cylinders, boxes), so each cell's list comes out in that order.
  const auto forEachNearPair = [&](auto&& f) {
    for (int k = 0; k < static_cast<int>(bodies_.planes.size()); ++k)
      forEachCellNearPlane(bodies_.planes[k], [&](int cell) {
        f(cell, StaticRef{StaticKind::Plane, k});
      });
    for (int k = 0; k < static_cast<int>(bodies_.cylinders.size()); ++k) {
      const CylinderShape& cylinder = bodies_.cylinders[k];
      const Vec3* centre = cylinder.capped() ? &cylinder.point : nullptr;
      forEachCandidate(centre, cylinder.capped() ? cylinder.reach() : Vec3::Zero(),
                       [&](int cell, const CellBox& box) {
                         if (cylinderNear(cylinder, box))
                           f(cell, StaticRef{StaticKind::Cylinder, k});
                       });
    }
    for (int k = 0; k < static_cast<int>(bodies_.boxes.size()); ++k) {
      const BoxShape& shape = bodies_.boxes[k];
      forEachCandidate(&shape.center, shape.reach(), [&](int cell, const CellBox& box) {
        if (boxNear(shape, box)) f(cell, StaticRef{StaticKind::Box, k});
      });
    }
  };
  std::size_t total = 0;
  forEachNearPair([&](int cell, StaticRef) {
    ++staticStart_[cell + 1];
    ++total;
  });
  // Many shapes in many cells would take more memory than the lists save time: then every cell
  // shares one list of all shapes.
  const std::size_t budget = 16 * (particles_.size() + 1024) + 4 * std::size_t(cells);
  if (total > budget) {
    staticStart_.assign(cells + 1, 0);
    for (int k = 0; k < static_cast<int>(bodies_.planes.size()); ++k)
      statics_.push_back({StaticKind::Plane, k});
    for (int k = 0; k < static_cast<int>(bodies_.cylinders.size()); ++k)
      statics_.push_back({StaticKind::Cylinder, k});
    for (int k = 0; k < static_cast<int>(bodies_.boxes.size()); ++k)
      statics_.push_back({StaticKind::Box, k});
    sharedStatics_ = true;
    return;
  }
  for (int cell = 0; cell < cells; ++cell) staticStart_[cell + 1] += staticStart_[cell];
  statics_.resize(total);
  std::vector<int> cursor(staticStart_.begin(), staticStart_.end() - 1);
  forEachNearPair([&](int cell, StaticRef ref) { statics_[cursor[cell]++] = ref; });
}

void EventEngine::noteStatics(int i) {
  Particle& p = particles_[i];
  p.staticBegin = sharedStatics_ ? 0 : staticStart_[p.cell];
  p.staticEnd = sharedStatics_ ? static_cast<int>(statics_.size()) : staticStart_[p.cell + 1];
}

}  // namespace carom
