#pragma once

#include <Eigen/Dense>

namespace punchsweep::fit {

/// The solution of min ||A x - b|| subject to x >= 0, by Lawson and Hanson's active-set
/// method (Solving Least Squares Problems, 1974, chapter 23, algorithm NNLS), each inner
/// least-squares problem solved on the normal equations A^T A (Bro and de Jong's fast NNLS). Stops after
/// 3 n outer iterations (Lawson and Hanson's bound), returning the best point so far.
Eigen::VectorXd nnls(const Eigen::MatrixXd& A, const Eigen::VectorXd& b);

}  // namespace punchsweep::fit
