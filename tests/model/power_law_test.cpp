// Power-law creep J(t) = 1 + (t/t_1)^n and its relaxation function, the Mittag-Leffler
// function E(t) = E_n(-Gamma(1 + n) (t/t_1)^n) (docs/model.md, section 10), held to
// references independent of the code under test:
//  - the closed form E_(1/2)(-x) = exp(x^2) erfc(x), from the C library's erfc (and its
//    asymptotic series where exp(x^2) would overflow), for x from 0 to 1e3;
//  - E_a(-s^a) and s d/ds E_a(-s^a) computed with mpmath at 40 to 500 digits (the power
//    series sum_k (-s^a)^k / Gamma(a k + 1) for s <= 150, the asymptotic series beyond,
//    where its error at the smallest term, about exp(-s), is below 1e-60), for six orders
//    a from 0.05 to 0.999 over s from 1e-8 to 1e6;
//  - the interconversion int_0-^t E(t - tau) dJ(tau) = 1 by a tanh-sinh quadrature written
//    here (not the law's own).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/laws/power_law.hpp"

using namespace punchsweep::model;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInverseSqrtPi = std::numbers::inv_sqrtpi;

// erfcx(x) = exp(x^2) erfc(x), and x erfcx'(x) / 2 = x^2 erfcx(x) - x / sqrt(pi) (which is
// s f'(s) for f(s) = E_(1/2)(-s^(1/2)) = erfcx(sqrt(s))). Below x = 8 from erfc, with
// x^2 = hi + lo split exactly so that exp(x^2) = exp(hi) (1 + lo) carries no rounding of
// x^2; from x = 8 by the asymptotic series
//   erfcx(x) = (1/sqrt(pi)) sum_k (-1)^k (2k-1)!! / 2^k x^-(2k+1),
// whose terms decrease until k ~ x^2 to below exp(-64).
double erfcx(double x) {
  if (x < 8.0) {
    const double hi = x * x;
    const double lo = std::fma(x, x, -hi);
    return std::exp(hi) * (1.0 + lo) * std::erfc(x);
  }
  const double y = 1.0 / (2.0 * x * x);
  double term = 1.0 / x;
  double sum = 0.0;
  for (int k = 0; std::abs(term) > 1e-20 * std::abs(sum) || k == 0; ++k) {
    sum += term;
    term *= -(2 * k + 1) * y;
  }
  return kInverseSqrtPi * sum;
}

double erfcx_rate(double x) {  // x erfcx'(x) / 2
  if (x < 8.0) return x * x * erfcx(x) - x * kInverseSqrtPi;
  // -(1/(2 sqrt(pi))) sum_k (-1)^k (2k+1)!! / 2^k x^-(2k+1)
  const double y = 1.0 / (2.0 * x * x);
  double term = 1.0 / x;  // (-1)^k (2k-1)!! / 2^k x^-(2k+1)
  double sum = 0.0;
  for (int k = 0; std::abs(term) > 1e-20 * std::abs(sum) || k == 0; ++k) {
    sum += (2 * k + 1) * term;
    term *= -(2 * k + 1) * y;
  }
  return -0.5 * kInverseSqrtPi * sum;
}

// {a, s, E_a(-s^a), s d/ds E_a(-s^a)} from mpmath (a and s are the doubles written).
struct Reference {
  double a, s, f, rate;
};
const std::vector<Reference> kReferences{
    {0.05, 1e-08, 0.7095184451094879, -0.010313575952486198},
    {0.05, 0.001, 0.57856200611267962, -0.01220349030580766},
    {0.05, 0.3, 0.50784814237536448, -0.012509755562599892},
    {0.05, 1.0, 0.49278415120025198, -0.012510261113665816},
    {0.05, 3.0, 0.47904912991029459, -0.012490903614171752},
    {0.05, 10.0, 0.46403392920855178, -0.012448112890693482},
    {0.05, 30.0, 0.45038872027846652, -0.012389632386666782},
    {0.05, 100.0, 0.43552092081781851, -0.012304672680082321},
    {0.05, 1000.0, 0.40742839092068612, -0.012083678700709024},
    {0.05, 1000000.0, 0.32732031547336819, -0.011019314678377884},
    {0.3, 1e-08, 0.99558179302695591, -0.001320179931763431},
    {0.3, 0.001, 0.87559468194309694, -0.03306519893808123},
    {0.3, 0.3, 0.54998101524216083, -0.076883425694996325},
    {0.3, 1.0, 0.45659440832969067, -0.077316799030089673},
    {0.3, 3.0, 0.37364894580679399, -0.072982391058051814},
    {0.3, 10.0, 0.2907394319085957, -0.064192223736727209},
    {0.3, 30.0, 0.22561759661461027, -0.054194619427306093},
    {0.3, 100.0, 0.16717994263449272, -0.042965322652048282},
    {0.3, 1000.0, 0.090085099179551313, -0.025037065004264645},
    {0.3, 1000000.0, 0.012096937742994336, -0.0035953692471569733},
    {0.75, 1e-08, 0.99999891193550012, -8.1604781071997851e-7},
    {0.75, 0.001, 0.99390507817333408, -0.0045534543900131303},
    {0.75, 0.3, 0.66033746664230044, -0.19280911330838802},
    {0.75, 1.0, 0.39310830281575406, -0.23223772010096143},
    {0.75, 3.0, 0.17420627032196826, -0.15080043226145269},
    {0.75, 10.0, 0.059097362075268172, -0.052191611006113655},
    {0.75, 30.0, 0.023350827561617869, -0.018970028727962988},
    {0.75, 100.0, 0.0090121807419400138, -0.0069826936558838425},
    {0.75, 1000.0, 0.0015599914171505455, -0.0011767520343252272},
    {0.75, 1000000.0, 8.722339191781115e-6, -6.541965977026104e-6},
    {0.9, 1e-08, 0.99999993439595162, -5.9043641402463619e-8},
    {0.9, 0.001, 0.99792779050125963, -0.0018628547927246793},
    {0.9, 0.3, 0.70807456094404936, -0.21561934342531128},
    {0.9, 1.0, 0.37606602142464188, -0.30814879777662195},
    {0.9, 3.0, 0.10148660560547141, -0.15608924034486953},
    {0.9, 10.0, 0.017259379513631199, -0.02090367816734634},
    {0.9, 30.0, 0.0053528032644826116, -0.0052535791293045315},
    {0.9, 100.0, 0.0017113705332184068, -0.0015826849393758977},
    {0.9, 1000.0, 2.1042632447030482e-4, -1.9001379515610773e-4},
    {0.9, 1000000.0, 4.1846794122574166e-7, -3.7662363279841376e-7},
    {0.99, 1e-08, 0.99999998792680841, -1.1952459600096989e-8},
    {0.99, 0.001, 0.99892456017147934, -0.0010641069749688831},
    {0.99, 0.3, 0.73755109544427688, -0.22190357001876248},
    {0.99, 1.0, 0.36854831806033962, -0.36159131535572008},
    {0.99, 3.0, 0.05510409576723306, -0.15047676144291716},
    {0.99, 10.0, 0.0013998716984241149, -0.002319155403887732},
    {0.99, 30.0, 3.7318856384455482e-4, -3.9877515130739116e-4},
    {0.99, 100.0, 1.0755355158741989e-4, -1.0877085805826985e-4},
    {0.99, 1000.0, 1.0799169307010493e-5, -1.0713850606163433e-5},
    {0.99, 1000000.0, 1.1547082058021502e-8, -1.1431637105648226e-8},
    {0.999, 1e-08, 0.9999999898097821, -1.0180027627359488e-8},
    {0.999, 0.001, 0.99899315057213535, -0.0010053355356783699},
    {0.999, 0.3, 0.74049174418154333, -0.22221444688207139},
    {0.999, 1.0, 0.36794468034194147, -0.36724764916903786},
    {0.999, 3.0, 0.050320401525521082, -0.14947749530702764},
    {0.999, 10.0, 1.7730712504008013e-4, -6.37975698888284e-4},
    {0.999, 30.0, 3.5961739788430213e-5, -3.8722886145928515e-5},
    {0.999, 100.0, 1.02599517947793e-5, -1.0464071739005726e-5},
    {0.999, 1000.0, 1.0095444565291045e-6, -1.0105712631861363e-6},
    {0.999, 1000000.0, 1.0144980205168721e-9, -1.0134855747384804e-9},
};

// int_0^1 g(u, 1 - u) du by tanh-sinh: u = 1 / (1 + e^-q), q = pi sinh(tau), tau = k h for
// |tau| <= 3.6 (the end weights are below 1e-30 there), with u and 1 - u both formed
// without cancellation so that g may be singular at either end.
template <class G>
double tanh_sinh(G&& g, double h) {
  double sum = 0.0;
  const int n = static_cast<int>(3.6 / h);
  for (int k = -n; k <= n; ++k) {
    const double tau = k * h;
    const double q = kPi * std::sinh(tau);
    const double e = std::exp(-std::abs(q));
    const double near = e / (1.0 + e);  // the distance to the nearer end
    const double far = 1.0 / (1.0 + e);
    const double weight = kPi * std::cosh(tau) * e / ((1.0 + e) * (1.0 + e));
    sum += weight * (q >= 0.0 ? g(far, near) : g(near, far));
  }
  return h * sum;
}

// int_0-^t E(t - tau) dJ(tau) = J(0) E(t) + int_0^t E(t - tau) J'(tau) dtau. With
// tau = t u^(1/n), J'(tau) dtau = (t/t_1)^n du: the tau^(n-1) singularity is gone, and
// E(t (1 - u^(1/n))), singular like (1 - u)^n at u = 1, is left to tanh-sinh.
double interconversion(const PowerLaw& law, double t, double h) {
  const double n = law.exponent();
  const double integral = tanh_sinh(
      [&](double u, double one_minus_u) {
        const double log_u = u < 0.5 ? std::log(u) : std::log1p(-one_minus_u);
        return law.relaxation(t * -std::expm1(log_u / n));
      },
      h);
  return law.creep(0.0) * law.relaxation(t) + std::pow(t / law.doubling_time(), n) * integral;
}

}  // namespace

TEST(MittagLeffler, one_half_is_the_scaled_complementary_error_function) {
  // E_(1/2)(-x) = exp(x^2) erfc(x), over the series (x <= 0.5), the quadrature and the
  // asymptotic series (x >= 6.6), x from 0 to 1e3.
  const MittagLeffler ml(0.5);
  std::vector<double> xs;
  for (int m = 0; m <= 512; ++m) xs.push_back(m / 64.0);
  for (double x = 8.0; x <= 1e3; x *= 1.03) xs.push_back(x);
  xs.push_back(1e3);
  double worst = 0.0;
  double worst_rate = 0.0;
  for (const double x : xs) {
    const double expected = erfcx(x);
    const double error = std::abs(ml.negative(x) - expected) / expected;
    EXPECT_LT(error, 5e-15) << "x = " << x;
    worst = std::max(worst, error);
    // s f'(s) at s = x^2; below x = 8 the reference loses digits to the cancellation
    // x^2 erfcx(x) - x/sqrt(pi) (a factor 1 + 2 x^2).
    const double s = x * x;
    if (s == 0.0) continue;
    const double expected_rate = erfcx_rate(x);
    const double rate_error = std::abs(s * ml.relaxation_rate(s) - expected_rate) / std::abs(expected_rate);
    EXPECT_LT(rate_error, (x < 8.0 ? 1.0 + 2.0 * s : 1.0) * 5e-15) << "x = " << x;
    if (x >= 8.0 || x <= 1.0) worst_rate = std::max(worst_rate, rate_error);
  }
  std::cout << "E_(1/2)(-x), x in [0, 1e3]: max relative error " << worst << "; s f'(s): " << worst_rate
            << " (x <= 1 or x >= 8)\n";
}

TEST(MittagLeffler, matches_high_precision_values) {
  double worst = 0.0;
  for (const Reference& r : kReferences) {
    const MittagLeffler ml(r.a);
    const double f = ml.relaxation(r.s);
    const double rate = r.s * ml.relaxation_rate(r.s);
    EXPECT_NEAR(f, r.f, 5e-15 * r.f) << "a = " << r.a << ", s = " << r.s;
    EXPECT_NEAR(rate, r.rate, 5e-15 * std::abs(r.rate)) << "a = " << r.a << ", s = " << r.s;
    worst = std::max({worst, std::abs(f / r.f - 1.0), std::abs(rate / r.rate - 1.0)});
  }
  std::cout << "E_a(-s^a) and s f'(s) against mpmath: max relative error " << worst << "\n";
}

TEST(MittagLeffler, regions_join_continuously) {
  // The series, the quadrature and the asymptotic series agree where they meet.
  for (const double a : {0.01, 0.1, 0.3, 0.5, 0.7, 0.8, 0.9, 0.95, 0.97, 0.99, 0.999}) {
    const MittagLeffler ml(a);
    for (const double x : {ml.x_series(), ml.x_asymptotic()}) {
      const double below = std::nextafter(x, 0.0);
      const double above = std::nextafter(x, 2.0 * x);
      EXPECT_NEAR(ml.negative(below) / ml.negative(above), 1.0, 4e-15) << "a = " << a << ", x = " << x;
      const double s_below = std::pow(below, 1.0 / a);
      const double s_above = std::pow(above, 1.0 / a);
      EXPECT_NEAR(s_below * ml.relaxation_rate(s_below) / (s_above * ml.relaxation_rate(s_above)), 1.0, 4e-15)
          << "a = " << a << ", x = " << x;
    }
  }
}

TEST(MittagLeffler, is_completely_monotone_in_shape) {
  // f decreasing, f' negative and increasing (f convex), on a grid over every region, for
  // orders down to 1e-4 and up to 1 - 1e-6 (where each quadrature is at its limits).
  for (const double a : {1e-4, 0.05, 0.5, 0.85, 0.98, 0.999, 1.0 - 1e-6}) {
    const MittagLeffler ml(a);
    double f_prev = 1.0;
    double rate_prev = -std::numeric_limits<double>::infinity();
    EXPECT_EQ(ml.relaxation(0.0), 1.0);
    EXPECT_EQ(ml.relaxation_rate(0.0), -std::numeric_limits<double>::infinity());
    for (double s = 1e-12; s < 1e12; s *= 1.02) {
      const double f = ml.relaxation(s);
      const double rate = ml.relaxation_rate(s);
      ASSERT_TRUE(f < f_prev && f > 0.0) << "a = " << a << ", s = " << s;
      ASSERT_TRUE(rate < 0.0 && rate > rate_prev) << "a = " << a << ", s = " << s;
      f_prev = f;
      rate_prev = rate;
    }
  }
}

TEST(MittagLeffler, order_near_one_approaches_the_exponential) {
  // E_1(-x) = exp(-x); |E_a(-s^a) - exp(-s)| is about 0.54 (1 - a) at most.
  for (const double a : {0.999, 1.0 - 1e-6}) {
    const MittagLeffler ml(a);
    for (double s = 0.0; s <= 50.0; s += 0.125) EXPECT_NEAR(ml.relaxation(s), std::exp(-s), 1.0 - a) << s;
  }
}

TEST(MittagLeffler, refuses_orders_outside_zero_one) {
  for (const double a : {0.0, 1.0, -0.5, 1.5, std::nan("")}) EXPECT_THROW(MittagLeffler{a}, std::invalid_argument);
}

TEST(PowerLaw, limits_and_description) {
  const PowerLaw law(0.3, 2.5);
  EXPECT_EQ(law.creep(0.0), 1.0);
  EXPECT_EQ(law.creep_initial(), 1.0);
  EXPECT_EQ(law.relaxation(0.0), 1.0);
  EXPECT_TRUE(std::isinf(law.creep_final()));
  EXPECT_TRUE(std::isinf(law.relaxation_memory()));
  EXPECT_FALSE(law.retardation_series().has_value());
  EXPECT_EQ(law.relaxation_rate(0.0), -std::numeric_limits<double>::infinity());
  EXPECT_EQ(law.creep_rate(0.0), std::numeric_limits<double>::infinity());
  EXPECT_DOUBLE_EQ(law.creep(2.5), 2.0);  // J(t_1) = 2 J(0)
  EXPECT_EQ(law.creep_time_scale(), 2.5);
  EXPECT_NEAR(law.relaxation_time_scale(), 2.5 * std::pow(std::tgamma(1.3), -1.0 / 0.3), 1e-14);
  EXPECT_EQ(law.describe(), "power law, n = 0.3, t_1 = 2.5");
}

TEST(PowerLaw, relaxation_for_one_half_is_the_scaled_error_function) {
  // E(t) = E_(1/2)(-Gamma(3/2) sqrt(t/t_1)) = erfcx(sqrt(pi t/t_1) / 2), and E(tau) = erfcx(1).
  const double t_1 = 0.7;
  const PowerLaw law(0.5, t_1);
  for (double t = 1e-9; t < 1e9; t *= 1.7) {
    const double x = 0.5 * std::sqrt(kPi * t / t_1);
    EXPECT_NEAR(law.relaxation(t), erfcx(x), 5e-15 * erfcx(x)) << "t = " << t;
    // dE/dt = d/dt erfcx(x) = erfcx'(x) x / (2 t).
    const double expected_rate = erfcx_rate(x) / t;
    if (x < 1.0 || x >= 8.0) {
      EXPECT_NEAR(law.relaxation_rate(t), expected_rate, 5e-15 * std::abs(expected_rate)) << "t = " << t;
    }
  }
  EXPECT_NEAR(law.relaxation(law.relaxation_time_scale()), erfcx(1.0), 5e-15);
}

TEST(PowerLaw, relaxation_and_creep_are_interconverted) {
  double worst = 0.0;
  for (const double n : {0.1, 0.3, 0.5, 0.8}) {
    const double t_1 = 2.5;
    const PowerLaw law(n, t_1);
    for (const double t : {1e-3, 1.0, 1e3}) {
      const double coarse = interconversion(law, t * t_1, 1.0 / 32);
      const double fine = interconversion(law, t * t_1, 1.0 / 64);
      EXPECT_NEAR(coarse, fine, 1e-14) << "tanh-sinh not converged; n = " << n << ", t/t_1 = " << t;
      EXPECT_NEAR(fine, 1.0, 1e-13) << "n = " << n << ", t/t_1 = " << t;
      worst = std::max(worst, std::abs(fine - 1.0));
    }
  }
  std::cout << "interconversion: max |int E dJ - 1| = " << worst << "\n";
}

TEST(PowerLaw, relaxation_rate_is_the_derivative_of_relaxation) {
  // Five-point central differences, error O(h^4) with h = 1e-3 t.
  for (const double n : {0.1, 0.5, 0.9, 0.99}) {
    const PowerLaw law(n, 3.0);
    for (const double t : {1e-6, 1e-3, 0.3, 1.0, 3.0, 10.0, 100.0, 1e4}) {
      const double h = 1e-3 * t;
      const double difference = (8.0 * (law.relaxation(t + h) - law.relaxation(t - h)) -
                                 (law.relaxation(t + 2 * h) - law.relaxation(t - 2 * h))) /
                                (12.0 * h);
      const double rate = law.relaxation_rate(t);
      EXPECT_LT(rate, 0.0);
      // Truncation (h/t)^4 = 1e-12 relative, and the rounding of E (<= 1), 1.5 eps / h.
      EXPECT_NEAR(rate, difference, 1e-10 * std::abs(rate) + 4e-16 / h) << "n = " << n << ", t = " << t;
    }
  }
}

TEST(PowerLaw, creep_rate_and_integral) {
  for (const double n : {0.1, 0.5, 0.9}) {
    const double t_1 = 1.5;
    const PowerLaw law(n, t_1);
    for (const double t : {1e-6, 0.3, 1.0, 30.0, 1e6}) {
      const double h = 1e-3 * t;
      const double difference =
          (8.0 * (law.creep(t + h) - law.creep(t - h)) - (law.creep(t + 2 * h) - law.creep(t - 2 * h))) / (12.0 * h);
      EXPECT_NEAR(law.creep_rate(t), difference, 1e-10 * law.creep_rate(t) + 4e-16 * law.creep(t) / h)
          << "n = " << n << ", t = " << t;
      // int_0^t J = t + t_1 (t/t_1)^(n+1) / (n+1).
      const double integral = t + t_1 * std::pow(t / t_1, n + 1.0) / (n + 1.0);
      EXPECT_NEAR(law.creep_integral(0.0, t), integral, 4e-15 * integral);
    }
    // A short interval far out: int_u^(u+d) J = d J(u + d/2) + J'' d^3 / 24 + ..., without
    // the cancellation of the difference of two large integrals (d is the interval's exact
    // length: u + 1e-3 is rounded).
    const double u = 1e6;
    const double d = (u + 1e-3) - u;
    const double mid = law.creep(u + 0.5 * d);
    const double curvature = 0.5 * n * (n - 1.0) * std::pow(u / t_1, n) / (u * u);  // J''/2
    EXPECT_NEAR(law.creep_integral(u, d), d * mid + curvature * d * d * d / 12.0, 1e-14 * d * mid);
    EXPECT_EQ(law.creep_integral(0.7, 0.0), 0.0);
    EXPECT_NEAR(law.creep_integral(2.0, 3.0), law.creep_integral(0.0, 5.0) - law.creep_integral(0.0, 2.0), 1e-14 * 10.0);
  }
}

TEST(PowerLaw, time_at_creep_inverts_creep) {
  for (const double n : {0.1, 0.5, 0.9}) {
    const PowerLaw law(n, 2.0);
    for (const double t : {1e-9, 1e-3, 0.77, 2.0, 3e4}) {
      const double J = law.creep(t);
      // A rounding of J by eps J moves t by eps J / J'(t) = eps J t / (n (J - 1)).
      const double conditioning = 4.0 * 2.2e-16 * J * t / (n * (J - 1.0));
      EXPECT_NEAR(law.time_at_creep(J), t, conditioning + 1e-15 * t) << "n = " << n << ", t = " << t;
    }
    EXPECT_EQ(law.time_at_creep(1.0), 0.0);
    EXPECT_EQ(law.time_at_creep(0.5), 0.0);
    EXPECT_EQ(law.time_at_creep(3.0), 2.0 * std::pow(2.0, 1.0 / n));
  }
}

TEST(PowerLaw, relaxation_decreases_creep_increases_and_their_product_tends_to_sin_n_pi_over_n_pi) {
  for (const double n : {0.05, 0.3, 0.7, 0.95}) {
    const PowerLaw law(n, 1.0);
    double E_prev = 1.0;
    double J_prev = 1.0;
    for (double t = 1e-12; t < 1e12; t *= 1.05) {
      const double E = law.relaxation(t);
      const double J = law.creep(t);
      ASSERT_LT(E, E_prev) << "n = " << n << ", t = " << t;
      ASSERT_GT(J, J_prev) << "n = " << n << ", t = " << t;
      ASSERT_LE(E * J, 1.0) << "n = " << n << ", t = " << t;
      E_prev = E;
      J_prev = J;
    }
    // E J -> 1/(Gamma(1+n) Gamma(1-n)) = sin(n pi)/(n pi), with relative corrections of
    // order (t/t_1)^-n.
    const double t = 1e300;
    EXPECT_NEAR(law.relaxation(t) * law.creep(t), std::sin(n * kPi) / (n * kPi), 1e-12) << "n = " << n;
  }
}

TEST(PowerLaw, refuses_bad_parameters_naming_value_and_range) {
  const double nan = std::nan("");
  const double inf = std::numeric_limits<double>::infinity();
  for (const double n : {0.0, 1.0, -0.2, 1.5, nan, inf}) {
    try {
      PowerLaw law(n, 1.0);
      ADD_FAILURE() << "accepted n = " << n;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("n = "), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("0 < n < 1"), std::string::npos) << e.what();
    }
  }
  for (const double t_1 : {0.0, -1.0, nan, inf}) {
    try {
      PowerLaw law(0.5, t_1);
      ADD_FAILURE() << "accepted t_1 = " << t_1;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("t_1 = "), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("t_1 > 0"), std::string::npos) << e.what();
    }
  }
}
