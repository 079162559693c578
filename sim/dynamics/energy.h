#pragma once
// The balls' energy: kinetic (translation, and rotation of uniform solid spheres), and potential
// in uniform gravity.

#include "sim/dynamics/bodies.h"

#include <vector>

namespace carom {

// Of translation only.
double kineticEnergy(const Bodies& bodies, const std::vector<Vec3>& velocities);
// Of rotation: the sum of 1/2·(2/5·m·r²)·|ω|².
double rotationalEnergy(const Bodies& bodies, const std::vector<Vec3>& angularVelocities);
// Relative to the origin: the sum of -m g . p.
double potentialEnergy(const Bodies& bodies, const Vec3& gravity,
                       const std::vector<Vec3>& positions);
// One ball's share of the two sums above.
double ballKineticEnergy(double mass, const Vec3& velocity);
double ballRotationalEnergy(double mass, double radius, const Vec3& angularVelocity);
double ballPotentialEnergy(double mass, const Vec3& gravity, const Vec3& position);

}  // namespace carom
