#include "sim/exact/static_bins.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace carom {
namespace {

// A shape covering more cells than this is tested everywhere instead: binning it would cost
// more than the tests it saves.
constexpr double kMaxCellsPerShape = 4096.0;
// Coordinates beyond this many cells from the origin all fall into the outermost cell, so that
// the keys stay integers; shapes that far out are tested everywhere.
constexpr double kMaxCellCoordinate = 1e15;

struct Bounds {
  Vec3 lower, upper;
};

}  // namespace

std::size_t StaticBins::KeyHash::operator()(const Key& key) const {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (std::int64_t part : {key.x, key.y, key.z}) {
    hash = (hash ^ static_cast<std::uint64_t>(part)) * 0x100000001b3ULL;
    hash ^= hash >> 29;
  }
  return static_cast<std::size_t>(hash);
}

StaticBins::Key StaticBins::keyOf(const Vec3& p) const {
  const auto index = [this](double x) {
    const double cell = std::floor(x / cellSize_);
    return static_cast<std::int64_t>(std::clamp(cell, -kMaxCellCoordinate, kMaxCellCoordinate));
  };
  return {index(p.x()), index(p.y()), index(p.z())};
}

StaticBins::StaticBins(const Bodies& bodies) {
  for (int i = 0; i < static_cast<int>(bodies.planes.size()); ++i)
    everywhere_.push_back({Kind::Plane, i});
  // Each finite shape's box, grown by the largest ball's radius: a ball touching the shape, or
  // with its centre inside, has its centre in there.
  std::vector<std::pair<Entry, Bounds>> finite;
  for (int i = 0; i < static_cast<int>(bodies.cylinders.size()); ++i) {
    const CylinderShape& c = bodies.cylinders[i];
    if (!c.capped()) {
      everywhere_.push_back({Kind::Cylinder, i});
      continue;
    }
    const Vec3 reach = c.reach() + Vec3::Constant(bodies.maxRadius);
    finite.push_back({{Kind::Cylinder, i}, {c.point - reach, c.point + reach}});
  }
  for (int i = 0; i < static_cast<int>(bodies.boxes.size()); ++i) {
    const BoxShape& b = bodies.boxes[i];
    const Vec3 reach = b.reach() + Vec3::Constant(bodies.maxRadius);
    finite.push_back({{Kind::Box, i}, {b.center - reach, b.center + reach}});
  }
  if (finite.empty()) return;

  // Cells about as wide as the median shape, so that a typical shape covers a few cells.
  std::vector<double> widths;
  for (const auto& [entry, bounds] : finite)
    widths.push_back((bounds.upper - bounds.lower).maxCoeff());
  std::nth_element(widths.begin(), widths.begin() + widths.size() / 2, widths.end());
  cellSize_ = std::max(widths[widths.size() / 2], 1e-300);

  std::vector<std::pair<Key, Entry>> placed;
  for (const auto& [entry, bounds] : finite) {
    const Key low = keyOf(bounds.lower), high = keyOf(bounds.upper);
    const double cells =
        double(high.x - low.x + 1) * double(high.y - low.y + 1) * double(high.z - low.z + 1);
    const bool edge = std::abs(double(low.x)) >= kMaxCellCoordinate ||
                      std::abs(double(high.x)) >= kMaxCellCoordinate ||
                      std::abs(double(low.y)) >= kMaxCellCoordinate ||
                      std::abs(double(high.y)) >= kMaxCellCoordinate ||
                      std::abs(double(low.z)) >= kMaxCellCoordinate ||
                      std::abs(double(high.z)) >= kMaxCellCoordinate;
    if (cells > kMaxCellsPerShape || edge) {
      everywhere_.push_back(entry);
      continue;
    }
    for (std::int64_t z = low.z; z <= high.z; ++z)
      for (std::int64_t y = low.y; y <= high.y; ++y)
        for (std::int64_t x = low.x; x <= high.x; ++x) placed.push_back({{x, y, z}, entry});
  }
  std::stable_sort(placed.begin(), placed.end(), [](const auto& a, const auto& b) {
    const Key& p = a.first;
    const Key& q = b.first;
    return p.x != q.x ? p.x < q.x : (p.y != q.y ? p.y < q.y : p.z < q.z);
  });
  binned_.reserve(placed.size());
  for (std::size_t begin = 0; begin < placed.size();) {
    std::size_t end = begin;
    while (end < placed.size() && placed[end].first == placed[begin].first)
      binned_.push_back(placed[end++].second);
    cells_.emplace(placed[begin].first, std::pair<int, int>(int(begin), int(end)));
    begin = end;
  }
}

}  // namespace carom
