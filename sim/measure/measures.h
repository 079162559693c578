#pragma once
// Checks of a state against the scene, independent of how the state was computed.

#include "sim/dynamics/bodies.h"

#include <vector>

namespace carom {

struct OverlapReport {
  double maxPenetration = 0.0;  // largest overlap of a ball with a ball, plane or cylinder
  int escaped = 0;              // balls whose centre is behind a plane or inside a cylinder or box
};

OverlapReport measureOverlaps(const Bodies& bodies, const std::vector<Vec3>& positions);

// How many balls of `state` are at rest (the rest policy's, docs/physics.md).
int restingCount(const std::vector<BallState>& state);

// The Kolmogorov-Smirnov distance of two samples: the largest gap between their empirical
// distribution functions, 0 (the same distribution) to 1 (no overlap). Takes copies to sort.
double distributionDistance(std::vector<double> a, std::vector<double> b);

}  // namespace carom
