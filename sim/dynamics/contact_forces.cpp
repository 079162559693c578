#include "sim/dynamics/contact_forces.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <Eigen/Jacobi>

#include <algorithm>
#include <cmath>

namespace carom {

namespace {

// The QR factorisation Qᵀ·A_P = R of a set of columns that grows and shrinks one at a time, kept
// up to date by Givens rotations (Golub and Van Loan, "Matrix Computations", 6.5 and 12.5):
// adding or removing a column costs O(m²) instead of a new factorisation's O(m·k²). A rough
// cluster's active set changes some tens of times on a system of up to 48 rows and 200 columns.
class ColumnQr {
 public:
  explicit ColumnQr(const Eigen::VectorXd& b)
      : qt_(Eigen::MatrixXd::Identity(b.size(), b.size())), r_(b.size(), b.size()), qtb_(b) {}

  Eigen::Index size() const { return size_; }

  // Appends `column` (of unit length) as the last. Returns false, and the factorisation still
  // holds the columns it held, when the column lies within round-off of their span.
  bool append(const Eigen::VectorXd& column) {
    const Eigen::Index k = size_;
    if (k == qt_.rows()) return false;
    Eigen::VectorXd w = qt_ * column;
    // Rows k and below of the held columns are zero, so these rotations leave them as they are.
    for (Eigen::Index i = w.size() - 1; i > k; --i)
      w.applyOnTheLeft(i - 1, i, rotate(i - 1, w[i - 1], w[i], k));
    if (std::abs(w[k]) <= kDependent) return false;
    r_.col(k) = w;
    ++size_;
    return true;
  }

  // Removes the column at `position`; the ones after it move up one place.
  void remove(Eigen::Index position) {
    const Eigen::Index last = size_ - 1;
    for (Eigen::Index c = position; c < last; ++c) r_.col(c) = r_.col(c + 1);
    --size_;
    // Column c now has one entry below its diagonal, at row c + 1.
    for (Eigen::Index c = position; c < size_; ++c) {
      rotate(c, r_(c, c), r_(c + 1, c), c);
      r_(c + 1, c) = 0.0;
    }
  }

  // The least-squares coefficients of the held columns for b.
  Eigen::VectorXd solve() const {
    return r_.topLeftCorner(size_, size_).triangularView<Eigen::Upper>().solve(qtb_.head(size_));
  }

  // The coefficient of the last column alone: back substitution's first step.
  double lastCoefficient() const { return qtb_[size_ - 1] / r_(size_ - 1, size_ - 1); }

 private:
  // A column within this of the span of the others (they and it of unit length) counts as in it.
  static constexpr double kDependent = 1e-13;

  // Rotates rows `row` and row + 1 of Qᵀ, Qᵀb and R's columns from `fromColumn` on so that
  // (x, y) there becomes (|(x, y)|, 0); returns the rotation.
  Eigen::JacobiRotation<double> rotate(Eigen::Index row, double x, double y,
                                       Eigen::Index fromColumn) {
    Eigen::JacobiRotation<double> g;
    g.makeGivens(x, y);
    const Eigen::JacobiRotation<double> apply = g.adjoint();
    qt_.applyOnTheLeft(row, row + 1, apply);
    qtb_.applyOnTheLeft(row, row + 1, apply);
    if (size_ > fromColumn)
      r_.middleCols(fromColumn, size_ - fromColumn).applyOnTheLeft(row, row + 1, apply);
    return apply;
  }

  Eigen::MatrixXd qt_;
  Eigen::MatrixXd r_;
  Eigen::VectorXd qtb_;
  Eigen::Index size_ = 0;
};

}  // namespace

Eigen::VectorXd nonNegativeLeastSquares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b) {
  const Eigen::Index n = a.cols();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  std::vector<Eigen::Index> set;  // the positive (passive) columns, in the factorisation's order
  std::vector<bool> passive(n, false), dependent(n, false);
  ColumnQr qr(b);
  const Eigen::RowVectorXd norms = a.colwise().norm();
  // Gradients below this are round-off of the products that make them.
  const double threshold = 1e-14 * std::max(1.0, a.norm() * b.norm());
  // Each pass frees one variable; a cycle through round-off is cut off after generous passes.
  for (Eigen::Index pass = 0; pass < 3 * n + 10; ++pass) {
    const Eigen::VectorXd gradient = a.transpose() * (b - a * x);
    Eigen::Index best = -1;
    for (Eigen::Index j = 0; j < n; ++j)
      if (!passive[j] && !dependent[j] && gradient[j] > threshold &&
          (best < 0 || gradient[j] > gradient[best]))
        best = j;
    if (best < 0) break;
    // A column in the span of the set cannot lower the residual (the residual is orthogonal to
    // the span); nor can one whose coefficient would not be positive (Lawson and Hanson's test).
    if (!qr.append(a.col(best) / norms[best])) {
      dependent[best] = true;
      continue;
    }
    if (qr.lastCoefficient() <= 0.0) {
      qr.remove(qr.size() - 1);
      dependent[best] = true;
      continue;
    }
    std::fill(dependent.begin(), dependent.end(), false);
    passive[best] = true;
    set.push_back(best);
    for (Eigen::Index inner = 0; inner < n + 1; ++inner) {
      // The columns were normalised for the factorisation: scale back.
      Eigen::VectorXd z = qr.solve();
      for (std::size_t k = 0; k < set.size(); ++k) z[k] /= norms[set[k]];
      bool feasible = true;
      double step = 1.0;
      for (std::size_t k = 0; k < set.size(); ++k) {
        if (z[k] > 0.0) continue;
        feasible = false;
        const double xk = x[set[k]];
        step = std::min(step, xk / (xk - z[k]));
      }
      if (feasible) {
        for (std::size_t k = 0; k < set.size(); ++k) x[set[k]] = z[k];
        break;
      }
      // Move towards z as far as x stays non-negative, and drop the variables that reach zero.
      for (std::size_t k = 0; k < set.size(); ++k) x[set[k]] += step * (z[k] - x[set[k]]);
      for (auto k = static_cast<Eigen::Index>(set.size()) - 1; k >= 0; --k) {
        const Eigen::Index j = set[k];
        if (x[j] > 0.0) continue;
        x[j] = 0.0;
        passive[j] = false;
        qr.remove(k);
        set.erase(set.begin() + k);
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
