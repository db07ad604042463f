// Lawson and Hanson's NNLS checked by its optimality (Kuhn-Tucker) conditions, which any
// minimizer of ||A x - b|| over x >= 0 must meet and only a minimizer meets (the problem is
// convex): x >= 0; the gradient w = A^T (b - A x) is <= 0 where x = 0 and 0 where x > 0.
#include <gtest/gtest.h>

#include <random>

#include "fit/nnls.hpp"

namespace punchsweep::fit {
namespace {

Eigen::MatrixXd random_matrix(int rows, int cols, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd A(rows, cols);
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < cols; ++j) A(i, j) = u(rng);
  }
  return A;
}

TEST(Nnls, RecoversANonNegativeExactSolution) {
  const Eigen::MatrixXd A = random_matrix(30, 6, 1);
  Eigen::VectorXd x_true(6);
  x_true << 0.5, 0.0, 2.0, 0.0, 1e-3, 3.0;
  const Eigen::VectorXd x = nnls(A, A * x_true);
  for (int j = 0; j < 6; ++j) EXPECT_NEAR(x(j), x_true(j), 1e-12) << j;
}

TEST(Nnls, MeetsTheKuhnTuckerConditionsWhereConstraintsBind) {
  for (unsigned seed = 2; seed < 22; ++seed) {
    const Eigen::MatrixXd A = random_matrix(25, 10, seed);
    const Eigen::VectorXd b = random_matrix(25, 1, seed + 100);
    const Eigen::VectorXd x = nnls(A, b);
    const Eigen::VectorXd w = A.transpose() * (b - A * x);
    int bound = 0;
    for (int j = 0; j < 10; ++j) {
      ASSERT_GE(x(j), 0.0) << "seed " << seed;
      if (x(j) > 0.0) {
        EXPECT_NEAR(w(j), 0.0, 1e-10) << "seed " << seed << ", free variable " << j;
      } else {
        ++bound;
        EXPECT_LE(w(j), 1e-10) << "seed " << seed << ", bound variable " << j;
      }
    }
    // A random right-hand side makes some constraints bind, or the test checks nothing new.
    if (seed == 2) {
      EXPECT_GT(bound, 0);
    }
  }
}

TEST(Nnls, AllNegativeCorrelationGivesZero) {
  Eigen::MatrixXd A(3, 2);
  A << 1, 0, 0, 1, 1, 1;
  const Eigen::VectorXd b = -Eigen::VectorXd::Ones(3);
  const Eigen::VectorXd x = nnls(A, b);
  EXPECT_EQ(x(0), 0.0);
  EXPECT_EQ(x(1), 0.0);
}

}  // namespace
}  // namespace punchsweep::fit
