#include <gtest/gtest.h>

#include <cmath>

#include "model/point/point_evaluation.hpp"
#include "model/localization/localization_model.hpp"
#include "model/contact/regime.hpp"
#include "model/paper/single_level.hpp"
#include "model/laws/standard_linear_solid.hpp"

using namespace punchsweep::model;

namespace {

Regime regime_of(double pbar0, double l, double dh, double T, int s = 2) {
  return classify(ContactProblem{l, dh, pbar0, Shape{s, 0.5}}, StandardLinearSolid(T)).regime;
}

// t* by bisection on h(t) = dh, composing the forward functions (a1 from X, then h):
// a different path from classify(), which inverts h(a1) directly.
double t_star_by_bisection(const ContactProblem& p, const StandardLinearSolid& sls) {
  const SingleLevel single(p.l, p.shape);
  auto h = [&](double t) {
    const double X = p.pbar0 * sls.creep(t);
    return single.displacement_difference(single.contact_radius(X), X);
  };
  double lo = 0.0;
  double hi = 200.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (h(mid) < p.dh ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST(Regime, fig_9_5b_claims) {
  // pbar0 = 0.06, l = 0.75, T = 2.5: dh = 0.05 immediate, 0.075 delayed, 0.1 never.
  EXPECT_EQ(regime_of(0.06, 0.75, 0.05, 2.5), Regime::immediate);
  EXPECT_EQ(regime_of(0.06, 0.75, 0.075, 2.5), Regime::delayed);
  EXPECT_EQ(regime_of(0.06, 0.75, 0.1, 2.5), Regime::never);
}

TEST(Regime, delayed_contact_at_t_1_03_as_in_section_9_4_3) {
  const auto c = classify(ContactProblem{0.75, 0.075, 0.06, Shape{2, 0.5}}, StandardLinearSolid(2.5));
  EXPECT_EQ(c.regime, Regime::delayed);
  EXPECT_NEAR(c.t_star, 1.03, 0.005);
}

TEST(Regime, fig_9_5a_claims) {
  // pbar0 = 0.025, dh = 0.05, T = 2.5: l = 0.75 delayed; l = 1.0 and 1.25 immediate.
  EXPECT_EQ(regime_of(0.025, 0.75, 0.05, 2.5), Regime::delayed);
  EXPECT_EQ(regime_of(0.025, 1.0, 0.05, 2.5), Regime::immediate);
  EXPECT_EQ(regime_of(0.025, 1.25, 0.05, 2.5), Regime::immediate);
}

TEST(Regime, fig_9_3_claims) {
  // pbar0 = 0.01, dh = 0.04: at l = 0.75, T = 2 never, T = 5 and 10 delayed;
  // at T = 10, l = 0.5 never, l = 0.75 and 1.0 delayed.
  EXPECT_EQ(regime_of(0.01, 0.75, 0.04, 2.0), Regime::never);
  EXPECT_EQ(regime_of(0.01, 0.75, 0.04, 5.0), Regime::delayed);
  EXPECT_EQ(regime_of(0.01, 0.75, 0.04, 10.0), Regime::delayed);
  EXPECT_EQ(regime_of(0.01, 0.5, 0.04, 10.0), Regime::never);
  EXPECT_EQ(regime_of(0.01, 0.75, 0.04, 10.0), Regime::delayed);
  EXPECT_EQ(regime_of(0.01, 1.0, 0.04, 10.0), Regime::delayed);
}

struct IndependentValue {
  double pbar0, l, dh, T;
  int s;
  Regime regime;
  double t_star, h_0, h_inf;
};

TEST(Regime, independent_values_of_the_model_notes) {
  const IndependentValue table[] = {
      {0.06, 0.75, 0.075, 2.5, 2, Regime::delayed, 1.027595, 0.0537767, 0.0842487},
      {0.025, 0.75, 0.05, 2.5, 2, Regime::delayed, 1.272585, 0.0339781, 0.0548962},
      {0.01, 0.75, 0.04, 5, 2, Regime::delayed, 0.908824, 0.0203224, 0.0490070},
      {0.02, 1.0, 0.03, 4, 1, Regime::immediate, 0.0, 0.1096993, 0.1910237},
      {0.03, 0.9, 0.06, 6, 3, Regime::delayed, 0.770779, 0.0277571, 0.0796717},
  };
  for (const IndependentValue& v : table) {
    const ContactProblem p{v.l, v.dh, v.pbar0, Shape{v.s, 0.5}};
    const PointResult r = evaluate_point(p, StandardLinearSolid(v.T), EvaluationOptions{{}, {}});
    SCOPED_TRACE("pbar0 = " + std::to_string(v.pbar0) + ", l = " + std::to_string(v.l));
    EXPECT_EQ(r.regime, v.regime);
    ASSERT_TRUE(r.t_star.has_value());
    // 1e-6 relative, but never tighter than half a unit in the last printed digit
    // (t* has 6 decimals; h has 7, which for h ~ 0.02 is only 2.5e-6 relative).
    EXPECT_NEAR(*r.t_star, v.t_star, std::max(1e-6 * v.t_star, 5e-7));
    EXPECT_NEAR(r.h_0, v.h_0, std::max(1e-6 * v.h_0, 5e-8));
    EXPECT_NEAR(r.h_inf, v.h_inf, std::max(1e-6 * v.h_inf, 5e-8));
  }
}

TEST(Regime, t_star_agrees_with_bisection_on_h_to_1e_10) {
  for (const auto& [p, T] : {std::pair{ContactProblem{0.75, 0.075, 0.06, Shape{2, 0.5}}, 2.5},
                             std::pair{ContactProblem{0.75, 0.05, 0.025, Shape{2, 0.5}}, 2.5},
                             std::pair{ContactProblem{0.9, 0.06, 0.03, Shape{3, 0.5}}, 6.0},
                             std::pair{ContactProblem{0.6, 0.035, 0.004, Shape{1, 0.2}}, 10.0},
                             std::pair{ContactProblem{1.2, 0.07, 0.05, Shape{5, 1.0}}, 3.0}}) {
    const StandardLinearSolid sls(T);
    const Classification c = classify(p, sls);
    ASSERT_EQ(c.regime, Regime::delayed);
    EXPECT_NEAR(c.t_star / t_star_by_bisection(p, sls), 1.0, 1e-10);
  }
}

TEST(Regime, elastic_material_is_never_delayed) {
  // T = 1: J(t) = 1, nothing evolves, so level 2 touches at once or never.
  int immediate = 0;
  int never = 0;
  for (int s = 1; s <= 4; ++s) {
    for (double l = 0.3; l < 1.5; l += 0.1) {
      for (double dh = 0.0; dh < 0.2; dh += 0.005) {
        for (double pbar0 = 0.002; pbar0 < 0.1; pbar0 *= 1.5) {
          const Regime r = regime_of(pbar0, l, dh, 1.0, s);
          EXPECT_NE(r, Regime::delayed);
          (r == Regime::immediate ? immediate : never) += 1;
        }
      }
    }
  }
  EXPECT_GT(immediate, 100);  // both outcomes do occur on this grid
  EXPECT_GT(never, 100);
}

TEST(Regime, zero_height_difference_touches_at_once) {
  EXPECT_EQ(regime_of(0.01, 0.75, 0.0, 2.5), Regime::immediate);
}

TEST(Regime, regime_follows_h_0_and_h_inf) {
  // docs/model.md section 4: immediate iff h(0) >= dh; never iff h(inf) < dh.
  for (double dh = 0.001; dh < 0.15; dh += 0.0037) {
    const ContactProblem p{0.8, dh, 0.03, Shape{2, 0.5}};
    const PointResult r = evaluate_point(p, StandardLinearSolid(3.0), EvaluationOptions{{}, {}});
    const Regime expected = r.h_0 >= dh ? Regime::immediate : (r.h_inf < dh ? Regime::never : Regime::delayed);
    EXPECT_EQ(r.regime, expected) << "dh = " << dh;
  }
}
