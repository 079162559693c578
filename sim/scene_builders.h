#pragma once
// Scenes made in code: the benchmark gases and the random scenes of the tests.

#include "sim/scene.h"

#include <cstdint>
#include <initializer_list>

namespace carom {

// Planes at -halfSide and +halfSide on each of the given axes (0, 1, 2 for x, y, z), facing in.
void addBoxWalls(Scene& scene, double halfSide, std::initializer_list<int> axes = {0, 1, 2});

// `ballCount` balls of radius `radius` on a cubic lattice inside a closed box of six planes,
// sized so that the balls fill `packingFraction` of it. Velocities are normal with unit variance
// per component, shifted to zero total momentum; the same seed gives the same scene.
Scene makeGasInBox(int ballCount, double packingFraction, const Vec3& gravity, std::uint64_t seed,
                   double radius = 0.5);

}  // namespace carom
