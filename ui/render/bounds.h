#pragma once
// An axis-aligned box: the region the renderer clips infinite planes and cylinders to, and the
// region the camera frames.

#include "sim/scene.h"

namespace carom::render {

struct Bounds {
  Vec3 min = Vec3::Constant(-1.0);
  Vec3 max = Vec3::Constant(1.0);

  Vec3 center() const { return 0.5 * (min + max); }
  Vec3 size() const { return max - min; }
  double radius() const { return 0.5 * size().norm(); }  // of the enclosing sphere
};

}  // namespace carom::render
