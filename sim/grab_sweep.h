#pragma once
// Moving the held ball with no time passing (a paused run): it goes straight as far as it can
// without touching anything.

#include "sim/bodies.h"

#include <vector>

namespace carom {

// The fraction in [0, 1] of `move` that ball `ball` (at state[ball]) travels in a straight line
// before it touches a static shape or another ball where `state` has it: 1 when nothing is in
// the way, 0 when it already touches what the move heads into.
double freeTravel(const Bodies& bodies, const std::vector<BallState>& state, int ball,
                  const Vec3& move);

}  // namespace carom
