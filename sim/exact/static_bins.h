#pragma once
// Finding the static shapes a ball may touch without testing every shape: the finite ones
// (boxes, capped cylinders) binned in a hashed grid by their bounding boxes, so that a look-up
// costs the shapes near the point, not all of them. Planes and infinite cylinders reach
// everywhere and are always candidates.

#include "sim/dynamics/bodies.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace carom {

class StaticBins {
 public:
  enum class Kind { Plane, Cylinder, Box };
  struct Entry {
    Kind kind;
    int index;  // into bodies.planes, .cylinders or .boxes
  };

  // Bins `bodies`' shapes for balls of radius up to bodies.maxRadius.
  explicit StaticBins(const Bodies& bodies);

  // Calls f(entry) for every shape that a ball centred at `centre` (of radius up to maxRadius)
  // may touch or have its centre inside; each at most once.
  template <typename F>
  void forEachNear(const Vec3& centre, F&& f) const {
    for (const Entry& entry : everywhere_) f(entry);
    const auto cell = cells_.find(keyOf(centre));
    if (cell == cells_.end()) return;
    for (int i = cell->second.first; i < cell->second.second; ++i) f(binned_[i]);
  }

 private:
  struct Key {
    std::int64_t x, y, z;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& key) const;
  };
  Key keyOf(const Vec3& p) const;

  double cellSize_ = 1.0;
  std::vector<Entry> everywhere_;
  std::vector<Entry> binned_;                                    // grouped by cell
  std::unordered_map<Key, std::pair<int, int>, KeyHash> cells_;  // range in binned_
};

}  // namespace carom
