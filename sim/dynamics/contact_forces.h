#pragma once
// Normal contact forces on a cluster of touching balls at rest: whether pushes alone (no pull,
// no friction) along the contact normals can balance gravity on every ball of the cluster. This
// is how the rest policy tells a ball in a corner or a stack in a box, which rest, from a
// frictionless pyramid, which must spread (docs/physics.md, "Resting contact").

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
};

// True when forces f_c >= 0 along the contacts hold every ball of the cluster (masses given)
// against `gravity`, to within `tolerance` of each ball's weight. `carries`, when given, is
// filled with whether each contact takes part (a force above round-off) in that balance.
bool contactForcesBalance(const Vec3& gravity, const std::vector<double>& masses,
                          const std::vector<ClusterContact>& contacts, double tolerance,
                          std::vector<bool>* carries = nullptr);

// Minimises |A x - b| over x >= 0 (Lawson and Hanson's active-set method, 1974), for the small
// systems of a cluster. Returns x.
Eigen::VectorXd nonNegativeLeastSquares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b);

}  // namespace carom
