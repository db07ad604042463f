#include "model/periodic/small_spot_builder.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "model/shells/single_level_shells.hpp"
#include "model/numerics/integer_power.hpp"
#include "model/numerics/lattice.hpp"
#include "model/numerics/number_text.hpp"
#include "model/problem/contact_problem.hpp"
#include "model/shells/two_level_shells.hpp"

namespace punchsweep::model {

SmallSpotOptions::Bands hand_over_radii(int s) {
  if (s <= 1) return {0.08, 0.14, 0.22, 0.28};
  if (s == 2) return {0.09, 0.15, 0.30, 0.35};
  if (s <= 6) return {0.12, 0.18, 0.34, 0.40};
  // Flatter caps' radii grow slowly with the load: at two equal levels (eta = 0) each spot is
  // nearly the single level's, so a band to 0.40 l left them within 2% of merging at the
  // table's top (a1 + a2 = 0.696 l, s = 7), where the two-level solve has no state.
  return {0.12, 0.18, 0.28, 0.34};
}

SmallSpotOptions::Samples small_spot_samples(int s) {
  if (s <= 6) return {64, 32};
  return {64, 128};
}

SmallSpotTable build_small_spot_table(int s, const SmallSpotOptions& options) {
  if (s < Shape::kMinExponent || s > Shape::kMaxExponent) {
    throw std::invalid_argument("s = " + std::to_string(s) + " is outside 1 .. 32");
  }
  Localization localization;
  localization.shells = options.shells;
  localization.distributed = true;
  const Shape unit{s, 1.0};
  const SingleLevelShells single(1.0, unit, localization);

  SmallSpotTable t;
  t.s = s;
  const SmallSpotOptions::Samples samples = options.samples.v_intervals > 0 ? options.samples : small_spot_samples(s);
  t.M = samples.v_intervals;
  t.Z = samples.zeta_intervals;
  t.shells = options.shells;
  // The localization's far field per unit load, h - K_d a^s as a -> 0 (its gap at a = 0
  // under unit load: what its kept neighbours and the nominal pressure beyond them give),
  // and what the exact lattice adds to it.
  t.far_field_correction = lattice_far_field_constant() - single.displacement_difference(0.0, 1.0);
  const SmallSpotOptions::Bands bands = options.bands.to > 0.0 ? options.bands : hand_over_radii(s);
  const auto v_at = [&](double radius) { return iroot(single.creep_scaled_pressure(radius), s + 1); };
  t.v_gap_hand = v_at(bands.gap_from);
  t.v_gap_top = v_at(bands.gap_to);
  t.v_hand = v_at(bands.from);
  t.v_top = v_at(bands.to);
  t.finish();  // the isolated punch's scales

  const std::size_t M1 = static_cast<std::size_t>(t.M) + 1, Z1 = static_cast<std::size_t>(t.Z) + 1;
  t.a1_single.assign(M1, 1.0);
  t.h_single.assign(M1, 1.0);
  t.a1.assign(M1 * Z1, 0.0);
  t.a2.assign(M1 * Z1, 0.0);
  t.q2.assign(M1 * Z1, 0.0);
  // v = 0: two isolated punches, exactly.
  for (int m = 0; m <= t.Z; ++m) {
    const auto [y1, y2] = SmallSpotTable::isolated_two_level(s, t.eta_of_zeta(t.sample_zeta(m)));
    t.a1[m] = y1;
    t.a2[m] = y2;
    t.q2[m] = m == t.Z ? 0.5 : ipow(y2, s + 1);  // one height: half the load each, exactly
  }

  ContactProblem problem;
  problem.l = 1.0;
  problem.shape = unit;
  problem.localization = localization;
  for (int k = 1; k <= t.M; ++k) {
    options.stop.throw_if_requested();
    const double xi = ipow(t.sample_v(k), s + 1);
    const double a0 = t.isolated_radius(xi), h0 = t.isolated_depth(xi);
    const double a_single = single.contact_radius(xi);
    const double h_own = single.displacement_difference(a_single, xi);
    t.a1_single[k] = a_single / a0;
    t.h_single[k] = (h_own + t.far_field_correction * xi) / h0;

    const std::size_t row = static_cast<std::size_t>(k) * Z1, before = row - Z1;
    t.a1[row] = t.a1_single[k];  // touchdown: the single level's state
    for (int m = 1; m <= t.Z; ++m) {
      problem.dh = t.eta_of_zeta(t.sample_zeta(m)) * h_own;
      const TwoLevelShells system(problem, localization);
      // From the state at the same zeta one sample of v before, in its ratios.
      const std::size_t at = row + static_cast<std::size_t>(m);
      const double q2 = t.q2[before + m];
      const TwoLevelState guess{a0 * t.a1[before + m], a0 * t.a2[before + m], (1.0 - q2) * xi, q2 * xi};
      TwoLevelSolve solved = system.solve(xi, guess);
      if (!solved.converged) {
        // From the state one zeta before at this v.
        const double q = t.q2[at - 1];
        solved = system.solve(xi, {a0 * t.a1[at - 1], a0 * std::max(t.a2[at - 1], 1e-3 * a0), (1.0 - q) * xi, q * xi});
      }
      if (!solved.converged) {
        throw std::runtime_error("the small-spot table of s = " + std::to_string(s) + " found no two-level state at xi = " +
                                 number_text(xi, 6) + ", dh = " + number_text(t.eta_of_zeta(t.sample_zeta(m)), 6) +
                                 " h(xi) = " + number_text(problem.dh, 6) + " C l^s");
      }
      TwoLevelState state = solved.state;
      if (m == t.Z) {
        // One height: the two levels are one lattice, their states equal (Newton leaves
        // them within its tolerance).
        const double a = 0.5 * (state.a1 + state.a2);
        state = {a, a, 0.5 * xi, 0.5 * xi};
      }
      t.a1[at] = state.a1 / a0;
      t.a2[at] = std::min(state.a2, state.a1) / a0;
      t.q2[at] = state.Q2 / xi;
    }
    if (options.progress) options.progress(k, t.M);
  }
  t.finish();
  return t;
}

}  // namespace punchsweep::model
