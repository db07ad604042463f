#include "fit/nnls.hpp"

#include <algorithm>
#include <limits>
#include <vector>

namespace punchsweep::fit {
namespace {

/// The least-squares solution over the columns in `passive` (others zero), from the
/// normal equations' submatrix (Bro and de Jong, J. Chemometrics 11:393, 1997).
Eigen::VectorXd solve_on(const Eigen::MatrixXd& AtA, const Eigen::VectorXd& Atb, const std::vector<bool>& passive) {
  std::vector<Eigen::Index> cols;
  for (Eigen::Index j = 0; j < AtA.cols(); ++j) {
    if (passive[static_cast<std::size_t>(j)]) cols.push_back(j);
  }
  const auto m = static_cast<Eigen::Index>(cols.size());
  Eigen::MatrixXd P(m, m);
  Eigen::VectorXd q(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    q(i) = Atb(cols[static_cast<std::size_t>(i)]);
    for (Eigen::Index j = 0; j < m; ++j) P(i, j) = AtA(cols[static_cast<std::size_t>(i)], cols[static_cast<std::size_t>(j)]);
  }
  const Eigen::VectorXd zp = P.ldlt().solve(q);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(AtA.cols());
  for (std::size_t k = 0; k < cols.size(); ++k) z(cols[k]) = zp(static_cast<Eigen::Index>(k));
  return z;
}

}  // namespace

Eigen::VectorXd nnls(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  const Eigen::Index n = A.cols();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  std::vector<bool> passive(static_cast<std::size_t>(n), false);
  // Lawson and Hanson's tolerance on the dual vector w = A^T (b - A x).
  const double tol = 10.0 * std::numeric_limits<double>::epsilon() * A.cwiseAbs().colwise().sum().maxCoeff() *
                     static_cast<double>(std::max(A.rows(), n));
  const Eigen::MatrixXd AtA = A.transpose() * A;
  const Eigen::VectorXd Atb = A.transpose() * b;
  for (Eigen::Index outer = 0; outer < 3 * n; ++outer) {
    const Eigen::VectorXd w = Atb - AtA * x;
    Eigen::Index best = -1;
    double w_max = tol;
    for (Eigen::Index j = 0; j < n; ++j) {
      if (!passive[static_cast<std::size_t>(j)] && w(j) > w_max) {
        w_max = w(j);
        best = j;
      }
    }
    if (best < 0) break;  // Kuhn-Tucker conditions hold
    passive[static_cast<std::size_t>(best)] = true;
    for (Eigen::Index inner = 0; inner < 3 * n; ++inner) {
      const Eigen::VectorXd z = solve_on(AtA, Atb, passive);
      bool feasible = true;
      for (Eigen::Index j = 0; j < n; ++j) {
        if (passive[static_cast<std::size_t>(j)] && z(j) <= 0.0) feasible = false;
      }
      if (feasible) {
        x = z;
        break;
      }
      // Step from x toward z as far as feasibility allows; the variables reaching 0 leave.
      double alpha = 1.0;
      for (Eigen::Index j = 0; j < n; ++j) {
        if (passive[static_cast<std::size_t>(j)] && z(j) <= 0.0) alpha = std::min(alpha, x(j) / (x(j) - z(j)));
      }
      x += alpha * (z - x);
      for (Eigen::Index j = 0; j < n; ++j) {
        if (passive[static_cast<std::size_t>(j)] && x(j) <= 0.0) {
          passive[static_cast<std::size_t>(j)] = false;
          x(j) = 0.0;
        }
      }
    }
  }
  return x;
}

}  // namespace punchsweep::fit
