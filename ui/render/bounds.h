#pragma once
// An axis-aligned box: the region the camera frames and picking keeps to; infinite planes and
// cylinders are drawn beyond it, fading (kHorizonRadii).

#include "sim/model/scene.h"

namespace carom::render {

struct Bounds {
  Vec3 min = Vec3::Constant(-1.0);
  Vec3 max = Vec3::Constant(1.0);

  Vec3 center() const { return 0.5 * (min + max); }
  Vec3 size() const { return max - min; }
  double radius() const { return 0.5 * size().norm(); }  // of the enclosing sphere
  Bounds grown(double margin) const {
    return {min - Vec3::Constant(margin), max + Vec3::Constant(margin)};
  }
};

// Infinite planes and cylinders are drawn out this many radii of the bounds beyond them, fading
// to the background by kFadeRadii (e^-6 at the end), so that they reach towards the horizon
// instead of stopping at the edge of the scene.
constexpr double kHorizonRadii = 12.0;
constexpr double kFadeRadii = 2.0;

}  // namespace carom::render
