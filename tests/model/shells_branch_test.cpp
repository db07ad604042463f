// The refined model's tabulated two-level branch (ShellsBranch, docs/model.md section 11.3)
// against what it stands in for: Newton roots of TwoLevelShells reached by continuation
// from touchdown (the engine's path before the table, independent of the table), the
// independent Python study's states, and the merge margin where the branch ends. Also
// Brent's method, which the refined single-level phase now inverts with.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "model/problem/localization.hpp"
#include "model/point/point_evaluation.hpp"
#include "model/laws/standard_linear_solid.hpp"
#include "model/localization/localization_model.hpp"
#include "model/contact/regime.hpp"
#include "model/numerics/root_finding.hpp"
#include "model/shells/shells_branch.hpp"
#include "model/shells/two_level_shells.hpp"

using namespace punchsweep::model;

namespace {

ContactProblem refined(double l, double dh, int s) {
  ContactProblem p{l, dh, 0.01, Shape{s, 0.5}};
  p.localization = parse_localization("refined");
  return p;
}

/// The spots' least distance to merging at the 0.98 margin, in l.
double gap(const TwoLevelState& st, double l) {
  const double m = Localization::kMergeMargin;
  return std::min({m - 2.0 * st.a1 / l, m - 2.0 * st.a2 / l, m / std::numbers::sqrt2 - (st.a1 + st.a2) / l});
}

}  // namespace

TEST(ShellsBranch, equals_newton_roots_reached_from_touchdown) {
  std::mt19937 rng(12);
  int cases = 0;
  for (const int s : {1, 2}) {
    for (const double l : {0.5, 1.0, 1.5}) {
      for (const double dh : {0.005, 0.05}) {
        const ContactProblem p = refined(l, dh, s);
        const Touchdown touch = touchdown(p);
        // Level 2 touches only as level 1's spots reach their limit (0.49 l): no branch.
        if (!(touch.a1_star < 0.999 * 0.5 * Localization::kMergeMargin * l)) continue;
        ++cases;
        const ShellsBranch branch(p, touch);
        ASSERT_FALSE(branch.at(1e3 * touch.X_star + 10.0).converged);  // beyond every end: builds it all
        const double X_end = branch.X_end();
        ASSERT_GT(X_end, touch.X_star) << "l " << l << " dh " << dh << " s " << s;
        const TwoLevelShells system(p, p.localization);
        const TwoLevelState start{touch.a1_star, 0.0, l * l * touch.X_star, 0.0};
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        for (int k = 0; k < 8; ++k) {
          // Uniform in v = sqrt(X - X*), which crowds samples toward touchdown.
          const double v = std::sqrt(X_end - touch.X_star) * unit(rng);
          const double X = touch.X_star + v * v;
          const TwoLevelSolve table = branch.at(X);
          const TwoLevelSolve newton = system.continue_to(start, touch.X_star, X);
          ASSERT_TRUE(table.converged && newton.converged) << "X " << X;
          const double z_scale = s >= 2 ? l * l : l;
          const auto z = [s](double a2) { return s >= 2 ? a2 * a2 : a2; };
          EXPECT_NEAR(table.state.a1, newton.state.a1, 2 * ShellsBranch::kTolerance * l) << "X " << X;
          EXPECT_NEAR(z(table.state.a2), z(newton.state.a2), 2 * ShellsBranch::kTolerance * z_scale) << "X " << X;
          EXPECT_NEAR(table.state.Q1, newton.state.Q1, 2 * ShellsBranch::kTolerance * X * l * l) << "X " << X;
          // The loads sum to the nominal load exactly (to rounding).
          EXPECT_NEAR(table.state.Q1 + table.state.Q2, X * l * l, 1e-15 * X * l * l);
        }
        // The branch ends where the spots reach the merge margin: Newton roots exist up to
        // there and not past it.
        const TwoLevelSolve end = branch.at(X_end);
        ASSERT_TRUE(end.converged);
        EXPECT_NEAR(gap(end.state, l), 0.0, 1e-9) << "l " << l << " dh " << dh << " s " << s;
        EXPECT_FALSE(branch.at(X_end * (1.0 + 1e-9)).converged);
        EXPECT_FALSE(system.continue_to(end.state, X_end, X_end * (1.0 + 1e-6)).converged);
      }
    }
  }
  EXPECT_GE(cases, 9);
}

TEST(ShellsBranch, twenty_distances_equal_the_python_study) {
  // studies/localization/localization_shells.py (numpy/scipy), as in TwoLevelShells' test.
  struct Case {
    double l, dh, X, a1, a2, Q1;
  };
  for (const Case& c : {Case{0.75, 0.05, 0.06, 0.2795406117475716, 0.06914789241474505, 0.03319329985717882},
                        Case{1.25, 0.05, 0.025, 0.29411650707050113, 0.14175976069728735, 0.03505533767637511}}) {
    ContactProblem p{c.l, c.dh, c.X, Shape{2, 0.5}};
    p.localization = Localization{20, true};
    const TwoLevelSolve r = ShellsBranch(p, touchdown(p)).at(c.X);
    ASSERT_TRUE(r.converged);
    EXPECT_NEAR(r.state.a1 / c.a1, 1.0, 1e-9);
    EXPECT_NEAR(r.state.a2 / c.a2, 1.0, 1e-8);
    EXPECT_NEAR(r.state.Q1 / c.Q1, 1.0, 1e-9);
  }
}

TEST(ShellsBranch, is_the_same_curve_whatever_order_it_is_read_in) {
  // Built on first use, segment by segment: a sweep and `punchsweep point` read the same bits.
  const ContactProblem p = refined(1.0, 0.02, 2);
  const Touchdown touch = touchdown(p);
  const ShellsBranch forward(p, touch);
  const ShellsBranch backward(p, touch);
  const double Xs[] = {1.001 * touch.X_star, 3.0 * touch.X_star, 0.1, 0.15, 0.5};
  for (const double X : Xs) (void)forward.at(X);
  for (int k = 4; k >= 0; --k) (void)backward.at(Xs[k]);
  for (const double X : Xs) {
    const TwoLevelSolve a = forward.at(X);
    const TwoLevelSolve b = backward.at(X);
    EXPECT_EQ(a.converged, b.converged);
    EXPECT_EQ(a.state.a1, b.state.a1);
    EXPECT_EQ(a.state.a2, b.state.a2);
    EXPECT_EQ(a.state.Q1, b.state.Q1);
  }
  EXPECT_EQ(forward.X_end(), backward.X_end());
}

TEST(Brent, finds_roots_to_rounding_in_few_evaluations) {
  struct Case {
    double (*f)(double);
    double lo, hi, root;
    int max_calls;
  };
  const Case cases[] = {
      {[](double x) { return x - std::cos(x); }, 0.0, 1.0, 0.7390851332151607, 12},  // the Dottie number
      {[](double x) { return x * x * x - 2.0; }, 0.0, 2.0, std::cbrt(2.0), 12},
      {[](double x) { return std::expm1(20.0 * (x - 0.3)); }, 0.0, 1.0, 0.3, 20},  // steep on one side
      {[](double x) { return x < 0.25 ? -1.0 : 1.0; }, 0.0, 1.0, 0.25, 60},       // a jump: bisection
  };
  for (const Case& c : cases) {
    int calls = 0;
    const auto f = [&](double x) {
      ++calls;
      return c.f(x);
    };
    const RootResult r = brent(f, c.lo, c.hi, c.f(c.lo), c.f(c.hi), 1e-15);
    ASSERT_TRUE(r.converged);
    EXPECT_NEAR(r.x, c.root, 2e-15);
    EXPECT_LE(calls, c.max_calls);
  }
}

// The probe's hang (issue 22): s = 3 with dh < 0.004 R, where TwoLevelShells' roots can
// only be followed in ever shorter steps, once crawled for minutes inside
// build_pieces -> root -> continue_to. Every curve is now built within its budget of Newton
// solves, and a point beyond where it ends has no solution instead of no answer.
TEST(ShellsBranch, every_curve_is_built_within_its_solve_budget) {
  for (const double l : {0.5, 0.75, 1.0, 1.5}) {
    for (const double dh : {0.0003, 0.001, 0.003}) {
      const ContactProblem p = refined(l, dh, 3);
      const Touchdown touch = touchdown(p);
      const ShellsBranch branch(p, touch);
      EXPECT_FALSE(branch.at(1e3 * touch.X_star + 10.0).converged);  // builds the whole curve
      EXPECT_LE(branch.solves(), ShellsBranch::kMaxSolves) << "l " << l << " dh " << dh;
      EXPECT_GE(branch.X_end(), touch.X_star) << "l " << l << " dh " << dh;
    }
  }
}

TEST(ShellsBranch, the_probes_hanging_point_ends_flagged_no_solution) {
  ContactProblem p{0.75, 0.0003, 0.005, Shape{3, 0.5}};
  p.localization = parse_localization("refined");
  const PointResult r = evaluate_point(p, StandardLinearSolid(2.0), EvaluationOptions{{0.0}, {}});
  EXPECT_EQ(r.validity, Validity::no_solution) << r.reason();
  for (const Snapshot& sample : r.series) EXPECT_TRUE(std::isnan(sample.a2));
}
