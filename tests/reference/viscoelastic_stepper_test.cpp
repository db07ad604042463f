// The viscoelastic time stepping: the correspondence principle for a single punch under
// constant load, the exactness of the creep-scaled pressure, both history forms, rewinding.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "model/laws/creep_law.hpp"
#include "model/laws/prony_series.hpp"
#include "model/laws/standard_linear_solid.hpp"
#include "model/test_series_hidden.hpp"
#include "reference/closed_forms.hpp"
#include "reference/contact_solver.hpp"
#include "reference/periodic_grid.hpp"
#include "reference/viscoelastic_stepper.hpp"

using namespace punchsweep;
using namespace punchsweep::reference;

namespace {

constexpr double pi = std::numbers::pi;

/// A Maxwell fluid, J(t) = 1 + t/eta, E(t) = exp(-t/eta): unlimited creep, no retardation
/// series, so the stepper takes the convolution form.
class MaxwellFluid final : public model::CreepLaw {
 public:
  explicit MaxwellFluid(double eta) : eta_(eta) {}
  double creep(double t) const override { return 1.0 + t / eta_; }
  double creep_rate(double /*t*/) const override { return 1.0 / eta_; }
  double creep_integral(double u, double d) const override { return d * (1.0 + (u + 0.5 * d) / eta_); }
  double relaxation(double t) const override { return std::exp(-t / eta_); }
  double relaxation_rate(double t) const override { return -std::exp(-t / eta_) / eta_; }
  double creep_initial() const override { return 1.0; }
  double creep_final() const override { return std::numeric_limits<double>::infinity(); }
  double time_at_creep(double J) const override { return J <= 1.0 ? 0.0 : eta_ * (J - 1.0); }
  double relaxation_time_scale() const override { return eta_; }
  double creep_time_scale() const override { return eta_; }
  double relaxation_memory() const override { return 40.0 * eta_; }
  std::string describe() const override { return "Maxwell fluid"; }

 private:
  double eta_;
};


int pressed_nodes(std::span<const double> p) {
  return static_cast<int>(std::count_if(p.begin(), p.end(), [](double v) { return v > 0.0; }));
}

/// Geometric steps 0.02 * 1.25^k up to 0.25, landing on every time of `times`.
std::vector<double> step_times(const std::vector<double>& times) {
  std::vector<double> out;
  double t = 0.0, dt = 0.02;
  for (const double target : times) {
    while (t < target) {
      t = std::min(t + dt, target);
      out.push_back(t);
      dt = std::min(1.25 * dt, 0.25);
    }
  }
  return out;
}

// One sphere (R = 1) per L = 2 cell under P with a(0) = 0.25: a spot small in its cell.
constexpr double kCell = 2.0;
constexpr double kLoad = 4.0 / 3.0 * 0.25 * 0.25 * 0.25;

/// Runs a single Hertz punch and checks a(t) against the correspondence principle,
/// a(t)^3 = 3 P J(t) R_eff / 4 (hertz_periodic), within h/4 (the elastic tolerance: the
/// grid error is the same at every J), and that w = int J dp equals J(t) times the elastic
/// pressure at compliance J(t) on the same grid.
void check_hertz_creep(const model::CreepLaw& creep, CreepHistoryForm form, int n,
                       const std::vector<double>& snapshots) {
  const PeriodicGrid g = PeriodicGrid::square(n, kCell);
  const std::vector<double> f = punch_profile(g, {2, 0.5}, 0.0, 0.0);
  const double pbar = kLoad / (kCell * kCell);
  ViscoelasticStepper stepper(g, f, pbar, creep, {1e-12, 5000}, form);
  ContactSolver elastic(g, {1e-12, 5000});
  ASSERT_TRUE(stepper.start().converged);
  auto check = [&](double t) {
    const double J = creep.creep(t);
    const double a_exact = hertz_periodic(kLoad, 1.0, kCell, J).a;
    const double a_N = std::sqrt(pressed_nodes(stepper.pressure()) * g.cell_area() / pi);
    std::printf("%s, t = %.2f: J = %.4f, a = %.6f, correspondence %.6f, error %+.2e (h = %.4f)\n",
                creep.describe().c_str(), t, J, a_N, a_exact, a_N / a_exact - 1.0, g.hx());
    EXPECT_NEAR(a_N, a_exact, 0.25 * g.hx()) << "t = " << t;
    const ContactSolution el = elastic.solve(f, pbar, J);
    const auto w = stepper.creep_pressure();
    const double w_max = *std::max_element(w.begin(), w.end());
    double worst = 0.0;
    for (std::size_t i = 0; i < g.size(); ++i)
      worst = std::max(worst, std::abs(w[i] - J * el.pressure[i]));
    EXPECT_LT(worst, 1e-7 * w_max) << "t = " << t;
  };
  if (snapshots.front() == 0.0) check(0.0);
  for (const double t : step_times(snapshots)) {
    ASSERT_TRUE(stepper.advance(t).converged);
    if (std::find(snapshots.begin(), snapshots.end(), t) != snapshots.end()) check(t);
  }
}

}  // namespace

TEST(ViscoelasticStepper, standard_linear_solid_hertz_radius_follows_correspondence_principle) {
  // T = 2.5: a grows by 2.5^(1/3) = 1.357 from t = 0 to infinity.
  const model::StandardLinearSolid sls(2.5);
  check_hertz_creep(sls, CreepHistoryForm::exponential, 128, {0.0, 0.5, 1.0, 2.0, 5.0});
}

TEST(ViscoelasticStepper, generic_creep_law_hertz_radius_follows_correspondence_principle) {
  // A Maxwell fluid (eta = 2) is no standard linear solid: the convolution form is used.
  const MaxwellFluid maxwell(2.0);
  check_hertz_creep(maxwell, CreepHistoryForm::convolution, 96, {0.0, 0.5, 1.0, 2.0});
}

TEST(ViscoelasticStepper, natural_form_is_exponential_for_sls_and_convolution_otherwise) {
  const PeriodicGrid g = PeriodicGrid::square(8, 1.0);
  const std::vector<double> f(g.size(), 0.0);
  const model::StandardLinearSolid sls(2.0);
  const model::testing::SeriesHidden opaque(sls);  // the SLS without its series: the convolution form
  EXPECT_EQ(ViscoelasticStepper(g, f, 0.1, sls).form(), CreepHistoryForm::exponential);
  EXPECT_EQ(ViscoelasticStepper(g, f, 0.1, opaque).form(), CreepHistoryForm::convolution);
  EXPECT_THROW(ViscoelasticStepper(g, f, 0.1, opaque, {}, CreepHistoryForm::exponential),
               std::invalid_argument);
}

// The largest pressure difference, over the steps to t = 2 on a two-level cell whose level
// 2 touches during the run, between the two history forms for one material, in pbar0.
double largest_form_difference(const model::CreepLaw& creep) {
  const model::ContactProblem problem{0.75, 0.05, 0.06, {2, 0.5}};
  const TwoLevelCell cell = make_two_level_cell(problem, 32);
  ViscoelasticStepper exponential(cell.grid, cell.profile, problem.pbar0, creep, {1e-13, 5000},
                                  CreepHistoryForm::exponential);
  ViscoelasticStepper convolution(cell.grid, cell.profile, problem.pbar0, creep, {1e-13, 5000},
                                  CreepHistoryForm::convolution);
  exponential.start();
  convolution.start();
  double worst = 0.0;
  for (const double t : step_times({2.0})) {
    exponential.advance(t);
    convolution.advance(t);
    for (std::size_t i = 0; i < cell.grid.size(); ++i) {
      worst = std::max(worst, std::abs(exponential.pressure()[i] - convolution.pressure()[i]));
    }
  }
  return worst / problem.pbar0;
}

TEST(ViscoelasticStepper, convolution_form_reproduces_exponential_recursion) {
  // Same material, both history forms: the pressures agree to the quadrature of the step
  // weights (8-point Gauss is exact to round-off for the exponential J) and the solver
  // tolerance.
  const double worst = largest_form_difference(model::StandardLinearSolid(2.5));
  std::printf("largest pressure difference of the two forms: %.2e pbar0\n", worst);
  EXPECT_LT(worst, 1e-8);
}

TEST(ViscoelasticStepper, a_three_term_retardation_series_steps_as_the_convolution_does) {
  // A Prony series' creep function has one retardation term per relaxation term: the
  // exponential form carries one history variable per term; the convolution form uses J
  // alone. Both step the same discrete problem.
  const model::PronySeries prony(0.3, {0.2, 0.3, 0.2}, {0.05, 0.5, 3.0});
  ASSERT_EQ(prony.retardation_series()->terms.size(), 3U);
  const double worst = largest_form_difference(prony);
  std::printf("largest pressure difference of the two forms, 3 terms: %.2e pbar0\n", worst);
  EXPECT_LT(worst, 1e-8);
}

TEST(ViscoelasticStepper, rewind_returns_to_the_saved_state) {
  const model::ContactProblem problem{0.75, 0.05, 0.06, {2, 0.5}};
  const TwoLevelCell cell = make_two_level_cell(problem, 16);
  const model::StandardLinearSolid sls(2.5);
  for (const CreepHistoryForm form :
       {CreepHistoryForm::exponential, CreepHistoryForm::convolution}) {
    ViscoelasticStepper stepper(cell.grid, cell.profile, problem.pbar0, sls, {}, form);
    stepper.start();
    stepper.advance(0.1);
    const auto saved = stepper.checkpoint();
    stepper.advance(0.3);
    const std::vector<double> first(stepper.pressure().begin(), stepper.pressure().end());
    stepper.advance(0.5);
    stepper.rewind(saved);
    EXPECT_EQ(stepper.time(), 0.1);
    stepper.advance(0.3);
    const std::vector<double> again(stepper.pressure().begin(), stepper.pressure().end());
    EXPECT_EQ(first, again);
  }
}

TEST(ViscoelasticStepper, rejects_steps_backwards_and_before_start) {
  const PeriodicGrid g = PeriodicGrid::square(8, 1.0);
  const std::vector<double> f = punch_profile(g, {2, 0.5}, 0.0, 0.0);
  const model::StandardLinearSolid sls(2.0);
  ViscoelasticStepper stepper(g, f, 0.01, sls);
  EXPECT_THROW(stepper.advance(0.1), std::logic_error);
  stepper.start();
  EXPECT_THROW(stepper.advance(0.0), std::invalid_argument);
  EXPECT_THROW(ViscoelasticStepper(g, std::vector<double>(3), 0.01, sls), std::invalid_argument);
}
