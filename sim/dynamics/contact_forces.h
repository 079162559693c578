#pragma once
// Contact forces on a cluster of touching balls at rest: whether pushes (no pull) along the
// contact normals, with friction forces within their Coulomb cones where a contact has friction,
// can balance gravity on every ball of the cluster, and with friction the torques as well. This
// is how the rest policy tells a ball in a corner or a stack in a box, which rest, from a
// frictionless pyramid, which must spread, and a rough pyramid, which stands (docs/physics.md,
// "Resting contact").

#include "sim/model/scene.h"

#include <Eigen/Core>

#include <vector>

namespace carom {

// One contact of cluster ball `body` with `other` (another cluster ball, or -1 for something
// that does not move: a plane, a cylinder, a ball outside the cluster). `normal` is the unit
// vector from the other towards `body`: the direction in which the contact pushes `body`.
struct ClusterContact {
  int body;
  int other;
  Vec3 normal;
  double friction = 0.0;  // the contact's μ
};

// True when forces f_c >= 0 along the contacts hold every ball of the cluster (masses and radii
// given) against `gravity`, to within `tolerance` of each ball's weight. A contact with friction
// may push anywhere within its cone |f_t| ≤ μ·f_n (taken as the pyramid of kConeEdges edges
// inside it, a little less than the cone); when one has, the torques about each ball's centre
// must balance too, so that a ball held by friction does not roll. `carries`, when given, is
// filled with whether each contact takes part (a force above round-off) in that balance.
bool contactForcesBalance(const Vec3& gravity, const std::vector<double>& masses,
                          const std::vector<double>& radii,
                          const std::vector<ClusterContact>& contacts, double tolerance,
                          std::vector<bool>* carries = nullptr);
inline constexpr int kConeEdges = 8;

// Minimises |A x - b| over x >= 0 (Lawson and Hanson's active-set method, 1974), for the small
// systems of a cluster. Returns x.
Eigen::VectorXd nonNegativeLeastSquares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b);

}  // namespace carom
