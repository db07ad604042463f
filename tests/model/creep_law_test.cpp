#include <gtest/gtest.h>

#include <cmath>

#include "model/point/parameters.hpp"
#include "model/laws/standard_linear_solid.hpp"

using namespace punchsweep::model;

TEST(StandardLinearSolid, limits_are_instantaneous_and_long_term_moduli) {
  const StandardLinearSolid sls(2.5);
  EXPECT_DOUBLE_EQ(sls.creep(0.0), 1.0);
  EXPECT_DOUBLE_EQ(sls.creep_initial(), 1.0);
  EXPECT_DOUBLE_EQ(sls.creep_final(), 2.5);
  EXPECT_NEAR(sls.creep(60.0), 2.5, 1e-15);
  EXPECT_DOUBLE_EQ(sls.relaxation(0.0), 1.0);
  EXPECT_NEAR(sls.relaxation(60.0), 1.0 / 2.5, 1e-15);  // E_inf = E0 T_sigma / T_eps
}

TEST(StandardLinearSolid, relaxation_and_creep_are_interconverted) {
  // int_0-^t E(t - tau) dJ(tau) = E(t) J(0) + int_0^t E(t - tau) J'(tau) dtau = 1, by
  // composite Simpson with 20000 intervals (independent of the model's Gauss rules).
  for (const double T : {1.0, 2.5, 10.0}) {
    const StandardLinearSolid sls(T);
    for (const double t : {0.3, 1.0, 4.0}) {
      const int n = 20000;
      const double h = t / n;
      double sum = 0.0;
      for (int i = 0; i <= n; ++i) {
        const double tau = i * h;
        const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        sum += weight * sls.relaxation(t - tau) * (T - 1.0) * std::exp(-tau);
      }
      EXPECT_NEAR(sls.relaxation(t) * sls.creep(0.0) + sum * h / 3.0, 1.0, 1e-12)
          << "T = " << T << ", t = " << t;
    }
  }
}

TEST(StandardLinearSolid, relaxation_rate_is_the_derivative_of_relaxation) {
  const StandardLinearSolid sls(4.0);
  for (const double t : {0.0, 0.2, 1.5}) {
    const double h = 1e-6;
    const double central = (sls.relaxation(t + h) - sls.relaxation(std::max(t - h, 0.0))) /
                           (t > 0 ? 2 * h : h);
    EXPECT_NEAR(sls.relaxation_rate(t), central, t > 0 ? 1e-8 : 1e-5);
  }
}

TEST(StandardLinearSolid, time_at_creep_inverts_creep) {
  // Round trip, to within the conditioning of J: a rounding of J by eps J moves t by
  // eps J / J'(t) = eps J e^t / (T - 1).
  const double T = 6.0;
  const StandardLinearSolid sls(T);
  for (const double t : {1e-9, 0.01, 0.77, 3.0, 20.0}) {
    const double J = sls.creep(t);
    const double conditioning = 4.0 * 2.2e-16 * J * std::exp(t) / (T - 1.0);
    EXPECT_NEAR(sls.time_at_creep(J), t, conditioning) << "t = " << t;
  }
  EXPECT_EQ(sls.time_at_creep(1.0), 0.0);
  EXPECT_TRUE(std::isinf(sls.time_at_creep(6.0)));
}

TEST(StandardLinearSolid, creep_ratio_below_one_is_refused_with_its_range) {
  const Parameter& T = creep_ratio_parameter();
  EXPECT_EQ(T.error(1.0), "");
  EXPECT_NE(T.error(0.5).find("T >= 1"), std::string::npos);
  EXPECT_NE(T.error(std::nan("")).find("T = nan"), std::string::npos);
}

TEST(StandardLinearSolid, is_the_one_term_retardation_series_of_its_creep_function) {
  const StandardLinearSolid sls(3.5);
  const RetardationSeries series = *sls.retardation_series();
  ASSERT_EQ(series.terms.size(), 1U);
  EXPECT_EQ(series.J_final, 3.5);
  EXPECT_EQ(series.terms[0].J, 2.5);
  EXPECT_EQ(series.terms[0].lambda, 1.0);
}
