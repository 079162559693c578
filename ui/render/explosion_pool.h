#pragma once
// The explosions shown where balls collide: a fixed-size pool of short-lived sparks that fade
// and grow with time. No Qt, no GL, so the bookkeeping can be tested with made-up times.

#include "sim/model/scene.h"

#include <cstdint>
#include <vector>

namespace carom::render {

class ExplosionPool {
 public:
  // How long one lasts, and how much its scale grows over that time: the classic tutorial's
  // -0.01 alpha and +0.03 scale a frame at 60 frames a second, in seconds instead of frames.
  static constexpr double kLifetime = 1.6;
  static constexpr double kGrowth = 1.8;
  static constexpr int kDefaultLimit = 20;

  struct Live {
    Vec3 centre;
    double scale;  // the size given to add(), times 1 at birth up to 1 + kGrowth at the end
    double alpha;  // 1 at birth down to 0 at the end
  };

  explicit ExplosionPool(int limit = kDefaultLimit);

  // At most `limit` (at least 0) at once; lowering it removes the oldest beyond it.
  void setLimit(int limit);
  int limit() const { return limit_; }

  // Starts one at `now` (seconds on any clock that only goes forward). Returns false, and
  // counts it as dropped, when the pool is full even after removing the finished ones.
  bool add(const Vec3& point, double size, double now);
  // Moves the pool's clock to `now` and removes the finished ones.
  void update(double now);
  // The ones alive at the last update or add, as they look then.
  std::vector<Live> live() const;
  int count() const { return static_cast<int>(explosions_.size()); }
  bool empty() const { return explosions_.empty(); }
  std::uint64_t dropped() const { return dropped_; }
  void clear() { explosions_.clear(); }

 private:
  struct Explosion {
    Vec3 centre;
    double size;
    double born;
  };
  void removeFinished();

  std::vector<Explosion> explosions_;  // oldest first
  int limit_;
  double now_ = 0.0;
  std::uint64_t dropped_ = 0;
};

}  // namespace carom::render
