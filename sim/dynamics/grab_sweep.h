#pragma once
// Moving the held ball with no time passing (a paused run): it goes straight as far as it can
// without entering anything, then slides along what stopped it.

#include "sim/dynamics/bodies.h"

#include <vector>

namespace carom {

struct FreeTravel {
  double fraction = 1.0;       // of the move, in [0, 1]
  Vec3 normal = Vec3::Zero();  // of what stops it, towards the ball; zero when nothing does
};

// How far ball `ball` (at state[ball]) travels along `move` in a straight line before it
// touches a static shape or another ball where `state` has it.
FreeTravel freeTravel(const Bodies& bodies, const std::vector<BallState>& state, int ball,
                      const Vec3& move);

// Where ball `ball` gets by `move`: straight until it touches something, then along it with
// the part of the move into it taken away, as a hand sliding it along a wall would, a few
// times over.
Vec3 slideTo(const Bodies& bodies, std::vector<BallState> state, int ball, Vec3 move);

}  // namespace carom
