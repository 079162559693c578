#include "sim/dynamics/contact_forces.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace carom {

Eigen::VectorXd nonNegativeLeastSquares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b) {
  const int n = static_cast<int>(a.cols());
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  std::vector<bool> passive(n, false);
  // Gradients below this are round-off of the products that make them.
  const double threshold = 1e-14 * std::max(1.0, a.norm() * b.norm());
  // Each pass frees one variable; a cycle through round-off is cut off after generous passes.
  for (int pass = 0; pass < 3 * n + 10; ++pass) {
    const Eigen::VectorXd gradient = a.transpose() * (b - a * x);
    int best = -1;
    for (int j = 0; j < n; ++j)
      if (!passive[j] && gradient[j] > threshold && (best < 0 || gradient[j] > gradient[best]))
        best = j;
    if (best < 0) break;
    passive[best] = true;
    for (int inner = 0; inner < n + 1; ++inner) {
      std::vector<int> columns;
      for (int j = 0; j < n; ++j)
        if (passive[j]) columns.push_back(j);
      Eigen::MatrixXd sub(a.rows(), static_cast<Eigen::Index>(columns.size()));
      for (std::size_t k = 0; k < columns.size(); ++k) sub.col(k) = a.col(columns[k]);
      const Eigen::VectorXd z = sub.colPivHouseholderQr().solve(b);
      bool feasible = true;
      double step = 1.0;
      for (std::size_t k = 0; k < columns.size(); ++k) {
        if (z[k] > 0.0) continue;
        feasible = false;
        const double xk = x[columns[k]];
        step = std::min(step, xk / (xk - z[k]));
      }
      if (feasible) {
        x.setZero();
        for (std::size_t k = 0; k < columns.size(); ++k) x[columns[k]] = z[k];
        break;
      }
      // Move towards z as far as x stays non-negative, and drop the variables that reach zero.
      for (std::size_t k = 0; k < columns.size(); ++k) {
        const int j = columns[k];
        x[j] += step * (z[k] - x[j]);
        if (x[j] <= 0.0) {
          x[j] = 0.0;
          passive[j] = false;
        }
      }
    }
  }
  return x;
}

bool contactForcesBalance(const Vec3& gravity, const std::vector<double>& masses,
                          const std::vector<double>& radii,
                          const std::vector<ClusterContact>& contacts, double tolerance,
                          std::vector<bool>* carries) {
  const double g = gravity.norm();
  if (g == 0.0 || contacts.empty() || masses.empty()) return false;
  const int bodies = static_cast<int>(masses.size());
  const bool rough = std::any_of(contacts.begin(), contacts.end(),
                                 [](const ClusterContact& c) { return c.friction > 0.0; });
  // Each ball's rows are its force balance divided by its weight, so that every ball counts
  // alike whatever the mass ratios (with friction, its torque balance divided by weight times
  // radius follows); each column is a force the contact may push with, scaled to unit length,
  // which changes no answer of the non-negative problem: the normal alone, or the edges of the
  // friction pyramid.
  // Normal forces alone exert no torque, and each lies inside its pyramid (the mean of its
  // edges): when they hold the cluster, friction holds it too, and the frictionless system is
  // far smaller (a rough pile's clusters came to 47 rows and 193 columns).
  if (rough) {
    std::vector<ClusterContact> smooth = contacts;
    for (ClusterContact& contact : smooth) contact.friction = 0.0;
    if (contactForcesBalance(gravity, masses, radii, smooth, tolerance, carries)) return true;
  }
  const int rowsPerBody = rough ? 6 : 3;
  std::vector<Eigen::Index> firstColumn(contacts.size() + 1, 0);
  for (std::size_t c = 0; c < contacts.size(); ++c)
    firstColumn[c + 1] = firstColumn[c] + (contacts[c].friction > 0.0 ? kConeEdges : 1);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(rowsPerBody * bodies, firstColumn.back());
  Eigen::VectorXd b = Eigen::VectorXd::Zero(rowsPerBody * bodies);
  const Vec3 up = -gravity / g;
  for (int k = 0; k < bodies; ++k) b.segment<3>(rowsPerBody * k) = up;
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const ClusterContact& contact = contacts[c];
    const Vec3& n = contact.normal;
    // Unit tangents of the contact (any pair across n).
    const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
    for (Eigen::Index column = firstColumn[c]; column < firstColumn[c + 1]; ++column) {
      const double angle = 2.0 * M_PI * double(column - firstColumn[c]) / kConeEdges;
      const Vec3 force =
          contact.friction > 0.0
              ? Vec3(n + contact.friction * (std::cos(angle) * t1 + std::sin(angle) * t2))
              : n;
      const auto put = [&](int body, const Vec3& f, const Vec3& arm) {
        a.block<3, 1>(rowsPerBody * body, column) = f / masses[body];
        if (rough)
          a.block<3, 1>(rowsPerBody * body + 3, column) =
              arm.cross(f) / (masses[body] * radii[body]);
      };
      // The contact point is at -r·n from the body's centre, and at +r·n from the other's.
      put(contact.body, force, -radii[contact.body] * n);
      if (contact.other >= 0) put(contact.other, -force, radii[contact.other] * n);
      a.col(column).normalize();
    }
  }
  // Each ball's own rows, with every contact it has free to push, are a necessary condition
  // (a solution of the whole satisfies each ball's rows): a cluster whose falling member no
  // contact can hold fails at the cost of a small system.
  if (bodies > 1)
    for (int k = 0; k < bodies; ++k) {
      std::vector<Eigen::Index> own;
      for (Eigen::Index column = 0; column < a.cols(); ++column)
        if (a.col(column).segment(rowsPerBody * k, rowsPerBody).squaredNorm() > 0.0)
          own.push_back(column);
      Eigen::MatrixXd rows(rowsPerBody, static_cast<Eigen::Index>(own.size()));
      for (std::size_t c = 0; c < own.size(); ++c)
        rows.col(static_cast<Eigen::Index>(c)) =
            a.col(own[c]).segment(rowsPerBody * k, rowsPerBody);
      const Eigen::VectorXd ownB = b.segment(rowsPerBody * k, rowsPerBody);
      if ((rows * nonNegativeLeastSquares(rows, ownB) - ownB).norm() > tolerance) return false;
    }
  const Eigen::VectorXd forces = nonNegativeLeastSquares(a, b);
  for (int k = 0; k < bodies; ++k)
    if ((a.middleRows(rowsPerBody * k, rowsPerBody) * forces -
         b.segment(rowsPerBody * k, rowsPerBody))
            .norm() > tolerance)
      return false;
  if (carries) {
    carries->resize(contacts.size());
    for (std::size_t c = 0; c < contacts.size(); ++c)
      (*carries)[c] =
          forces.segment(firstColumn[c], firstColumn[c + 1] - firstColumn[c]).sum() > tolerance;
  }
  return true;
}

}  // namespace carom
