#pragma once
// The balls' energy: kinetic, and potential in uniform gravity.

#include "sim/dynamics/bodies.h"

#include <vector>

namespace carom {

double kineticEnergy(const Bodies& bodies, const std::vector<Vec3>& velocities);
// Relative to the origin: the sum of -m g . p.
double potentialEnergy(const Bodies& bodies, const Vec3& gravity,
                       const std::vector<Vec3>& positions);
// One ball's share of the two sums above.
double ballKineticEnergy(double mass, const Vec3& velocity);
double ballPotentialEnergy(double mass, const Vec3& gravity, const Vec3& position);

}  // namespace carom
