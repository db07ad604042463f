#pragma once
/// @file
/// The periodic cell's elastic solution where its spots are small against the pitch
/// (docs/model.md, section 14.7): the loads below those the boundary-element tables resolve
/// (periodic_table.hpp), down to the unloaded state. Numbers only; they are made by the
/// refined localization (small_spot_builder.hpp, which reads model/shells).
///
/// As xi -> 0 the spots shrink to points and the cell's solution tends to isolated punches
/// in the lattice's smooth far field: h = K_d a^s + Psi xi + ..., two levels d1 - d2 =
/// K_d (a1^s - a2^s) + Psi (Q1 - Q2) + ... (lattice.hpp, lattice_far_field_constant; scaled
/// variables of section 14.2: l = 1, C = 1, unit compliance). The refined localization
/// (D = 200 distances of neighbours spread over their own spots) is that limit with its
/// next orders, but keeps Psi_D = Psi - 2.2e-4 (its far field is the nominal pressure
/// beyond 17 l): the table holds its states with the exact Psi, which the single level
/// adds as (Psi - Psi_D) xi to h and the two levels take as a rescaled height difference
/// (below).
///
/// Stored as ratios to the isolated punch, smooth in v = xi^(1/(s+1)) down to v = 0 (where
/// they are their isolated limits exactly), with a0 = (xi / K_P)^(1/(s+1)), h0 = K_d a0^s:
///   single level, over v_k = v_top k / M:        a1 / a0 and h / h0;
///   two levels, over (v_k, zeta_m = m / Z):      a1 / a0, a2 / a0, Q2 / xi,
/// at eta = delta / h(xi) = 1 - zeta^s: zeta = (1 - eta)^(1/s) runs from touchdown (0; a2
/// grows as zeta there, Q2 as zeta^(s+1)) to the two levels at one height (1). A state at
/// eta is the refined model's at height difference eta h_D(xi), h_D its own single-level
/// gap: exact at both ends (touchdown at the exact h; delta = 0 symmetric) and within
/// (Psi - Psi_D)/Psi ~ 3e-4 of the exact far field's in between.

#include <cstdint>
#include <optional>
#include <vector>

#include "model/periodic/periodic_table.hpp"
#include "model/periodic/ratio_curve.hpp"
#include "model/numerics/uniform_cubic.hpp"

namespace punchsweep::model {

class SmallSpotTable {
 public:
  /// The file format: its version, first in tables().
  static constexpr double kFormat = 1.0;

  int s = 2;
  /// The boundary elements take over the gap h over [v_gap_hand, v_gap_top], and the rest
  /// (the radii, the two levels) over [v_hand, v_top], where the periodic solution blends the
  /// two (periodic_solution.hpp); v_top, the grid's last sample, ends both.
  double v_gap_hand = 0.0, v_gap_top = 0.0;
  double v_hand = 0.0, v_top = 0.0;
  int M = 0;  ///< v samples: M + 1
  int Z = 0;  ///< zeta samples: Z + 1
  /// The localization that made it (its D) and the far field it was given: Psi - Psi_D.
  int shells = 0;
  double far_field_correction = 0.0;
  std::vector<double> a1_single, h_single;  ///< M + 1: a1 / a0, h / h0
  std::vector<double> a1, a2, q2;           ///< (M + 1) x (Z + 1), by v, then zeta

  double sample_v(int k) const { return v_top * k / M; }
  double sample_zeta(int m) const { return static_cast<double>(m) / Z; }
  /// eta = 1 - zeta^s.
  double eta_of_zeta(double zeta) const;
  double xi_top() const;
  double xi_hand() const;
  double xi_gap_hand() const;
  double xi_gap_top() const;

  /// The isolated punch's radius a0 and depth h0 at load xi (the ratios' scales).
  double isolated_radius(double xi) const;
  double isolated_depth(double xi) const;

  /// Single level at 0 <= xi <= xi_top(): h, a1, Q1 = xi.
  PeriodicState single(double xi) const;
  /// Two levels at 0 <= xi <= xi_top() and eta = delta / h(xi) in [0, 1] (clamped): a1, a2,
  /// Q1, Q2 (h not set).
  PeriodicState two_level(double xi, double eta) const;
  /// The same at v = xi^(1/(s+1)) (the caller's, computed once); the two levels with the
  /// stencil of the samples about v already placed (curve().stencil(v): the periodic solution
  /// reads its own curve on the same grid).
  PeriodicState single_at(double xi, double v) const;
  PeriodicState two_level_at(double xi, double v, double eta) const;
  PeriodicState two_level_with(double xi, double v, double eta, const Stencil& along) const;
  /// The single level's curve.
  const RatioCurve& curve() const { return curve_; }
  /// The load at which h(xi) = delta (v <= v_top), by the curve single() evaluates; empty
  /// above h(xi_top).
  std::optional<double> touchdown(double delta) const;

  /// Two isolated punches (the v = 0 limit): the ratios (a1 / a0, a2 / a0) at eta, from
  /// y1^s - y2^s = eta and y1^(s+1) + y2^(s+1) = 1.
  static std::pair<double, double> isolated_two_level(int s, double eta);

  /// As numbers: kFormat, the header, every array; and back, empty for anything
  /// inconsistent (sizes, non-finite values, a bad header, ratios off their limits at v = 0).
  std::vector<double> tables() const;
  static std::optional<SmallSpotTable> from_tables(const std::vector<double>& numbers);
  /// A file name: small_spot-s<s>.
  static std::string table_name(int s);

  /// Derived numbers (the isolated punch's coefficients, the gap at each sample) once the
  /// arrays are filled.
  void finish();

 private:
  double K_P_ = 1.0, K_d_ = 1.0;
  RatioCurve curve_;
  UniformGrid zeta_grid_;
  std::vector<double> fields_;  ///< a1, a2, q2 of each sample side by side, for two_level_with()
  double v_of(double xi) const;
};

}  // namespace punchsweep::model
