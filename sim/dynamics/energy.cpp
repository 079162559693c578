#include "sim/dynamics/energy.h"

namespace carom {

double ballKineticEnergy(double mass, const Vec3& velocity) {
  return 0.5 * mass * velocity.squaredNorm();
}

double ballRotationalEnergy(double mass, double radius, const Vec3& angularVelocity) {
  return 0.2 * mass * radius * radius * angularVelocity.squaredNorm();
}

double ballPotentialEnergy(double mass, const Vec3& gravity, const Vec3& position) {
  return -mass * gravity.dot(position);
}

double kineticEnergy(const Bodies& bodies, const std::vector<Vec3>& velocities) {
  double sum = 0.0;
  for (int i = 0; i < static_cast<int>(velocities.size()); ++i)
    sum += ballKineticEnergy(bodies.mass[i], velocities[i]);
  return sum;
}

double rotationalEnergy(const Bodies& bodies, const std::vector<Vec3>& angularVelocities) {
  double sum = 0.0;
  for (int i = 0; i < static_cast<int>(angularVelocities.size()); ++i)
    sum += ballRotationalEnergy(bodies.mass[i], bodies.radius[i], angularVelocities[i]);
  return sum;
}

double potentialEnergy(const Bodies& bodies, const Vec3& gravity,
                       const std::vector<Vec3>& positions) {
  double sum = 0.0;
  for (int i = 0; i < static_cast<int>(positions.size()); ++i)
    sum += ballPotentialEnergy(bodies.mass[i], gravity, positions[i]);
  return sum;
}

}  // namespace carom
