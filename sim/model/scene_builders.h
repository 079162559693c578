#pragma once
// Scenes made in code: the benchmark gases and the random scenes of the tests.

#include "sim/model/scene.h"

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

// A Galton board for `ballCount` balls of radius `radius` under gravity -y, restitution 0.5:
// a block of balls above a funnel of two boxes sloping at 35 degrees, a triangle of capped pegs
// along z (at least ten rows, about a third of the square root of the ball count), bins of thin
// boxes tall enough for the fullest, and glass planes 3 radii either side of the middle. The
// seed jitters the balls' starting places.
Scene makeGaltonBoard(int ballCount, std::uint64_t seed, double radius = 0.01);

// Issue 36's poured pile: `ballCount` balls of radius 0.05 and mass 1, restitution 0.5, on a
// jittered lattice of 7 by 7 sites a layer, 0.11 m apart across and 0.12 m up from 0.06 m, with
// random velocities of up to 0.5 m/s per component, above the floor of a 0.8 m square box open
// at the top; `friction` is the world's μ. The seed picks the sites and the velocities.
Scene makePouredPile(int ballCount, double friction, std::uint64_t seed);

}  // namespace carom
