#pragma once
/// @file
/// The elastic periodic solution of the two-level cell, tabulated in its scaled variables
/// (docs/model.md, section 14): what the `periodic` model reads instead of the localization
/// formulas. The tables are numbers only; the periodic boundary-element solver that fills
/// them lives a layer up (reference/periodic_table_builder.hpp).
///
/// Scaling (docs/model.md, section 14.2). With xi = X / (C l^(s-1)) and delta = dh / (C l^s),
/// the elastic solution at unit compliance and load X has h / (C l^s), a_i / l,
/// Q_i / (C l^(s+1)) and the area fraction depending on (s, xi) while level 2 is free and on
/// (s, xi, delta) once it touches. The tables hold those scaled values:
///   single level: over v = xi^(1/(s+1)) on [v_lo, v_full] (uniform), h and a1;
///     beyond v_full every node is in contact: h = 2^(-s/2), a1 = 1/sqrt(pi) exactly.
///   two levels: over delta on [0, delta_top] (uniform) and r in [0, 1] (uniform), with
///     xi = xi*(delta) + (r w_full(delta))^(s+1), xi*(delta) the touchdown load (h = delta),
///     xi*(delta) + w_full(delta)^(s+1) = xi_cap the same for every row, 1.05 times the
///     single level's full-contact load (the two levels fill the cell sooner): a1, a2 and Q2
///     (Q1 = xi - Q2 exactly, the cell's load balance); beyond xi_cap the areas are the
///     levels' shares of the cell and the extra load spreads evenly: Q2 grows by (share of
///     level 2) dxi.
/// a_i are equivalent radii sqrt(area_i / pi): a level's area is the nodes of its share of
/// the cell in contact, so once spots merge they still say how much of each level touches.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/numerics/uniform_cubic.hpp"

namespace punchsweep::model {

/// The elastic periodic state of one scaled point.
struct PeriodicState {
  double h = 0.0;       ///< u(O) - u(M), in C l^s (meaningful while level 2 is free)
  double a1 = 0.0;      ///< equivalent radius of the level-1 contact, in l
  double a2 = 0.0;      ///< the same for level 2, in l
  double Q1 = 0.0;      ///< level-1 load, in C l^(s+1)
  double Q2 = 0.0;      ///< level-2 load, in C l^(s+1); Q1 + Q2 = xi
  bool in_range = true;  ///< false where the query lies outside what the table covers
};

class PeriodicTable {
 public:
  /// The file format: its version, first in tables().
  static constexpr double kFormat = 2.0;
  /// The rows reach delta_top = kTopShare 2^(-s/2), just short of where level 2 hides.
  static constexpr double kTopShare = 0.99;
  /// Where the samples sit: v of single-level sample k, delta of row j, and xi - xi* of
  /// sample k of row j (what the builder solves at and the spot check solves again).
  double sample_v(int k) const { return v_lo + (v_full - v_lo) * k / (static_cast<int>(h1.size()) - 1); }
  double sample_delta(int j) const { return delta_top * j / (J - 1); }
  double sample_excess(int j, int k) const;
  /// The power p of the rows' variable: xi - xi*(delta) = (r w_full)^p. s + 1 puts the
  /// samples close together after touchdown, where level 2's spot and load change fastest
  /// (measured at s = 1, 2, 3 against direct solves: a power s, with which an isolated
  /// punch's radius would grow linearly in r, left errors 3-10 times larger there).
  int row_power() const { return s + 1; }

  int s = 2;
  int n = 512;  ///< boundary-element grid (n x n on the cell, solved on its quarter)
  double v_lo = 0.0, v_full = 0.0;
  std::vector<double> h1, a11;  ///< single level, by v
  double delta_top = 0.0;
  int J = 0, K = 0;  ///< two-level samples: J deltas, K values of r
  std::vector<double> xi_star;     ///< touchdown load per delta (J)
  std::vector<double> w_full;      ///< per delta (J)
  std::vector<double> share2;      ///< level-2 share of the cell's area per delta (J)
  std::vector<double> a1, a2, Q2;  ///< J x K, row-major by delta
  /// Whether the pressure at every node did not decrease between consecutive samples
  /// (single level: K1 - 1 intervals; two levels: J x (K - 1)), the sufficient condition
  /// for the viscoelastic pressure to stay >= 0 (docs/model.md, section 14.1).
  std::vector<std::uint8_t> monotone1, monotone2;

  /// The level-2 surface hides under level 1 (it never touches) for delta >= 2^(-s/2).
  double delta_hidden() const;
  double xi_full_single() const;

  /// Single level at xi >= 0: h, a1, Q1 = xi.
  PeriodicState single(double xi) const;
  /// The touchdown load xi*(delta) (h(xi*) = delta); +infinity for delta >= delta_hidden;
  /// empty below the table (delta < h(v_lo)) unless delta == 0 (xi* = 0); v_lo is 0 in the
  /// tables the builder makes (the first sample is the unloaded state, exactly).
  std::optional<double> touchdown(double delta) const;
  /// What the two-level queries at one delta share (its touchdown, where it falls between
  /// the rows, the row end and level-2 share there): a caller that asks many loads at one
  /// delta (a point's times, a sweep's pressures and materials) computes it once.
  struct Row {
    double delta = 0.0;
    double xi_star = 0.0;     ///< touchdown (+infinity where level 2 hides)
    double w_full = 0.0;      ///< the row's end, interpolated
    double share2 = 0.0;      ///< level-2 share of the cell, interpolated
    int interval = 0;         ///< the rows j, j + 1 about delta
    double offset = 0.0;      ///< delta's place between them
    bool in_range = true;     ///< delta <= delta_top
  };
  Row row(double delta) const;
  /// The same where touchdown(delta) is known (delta <= delta_top; else the row's end).
  Row row(double delta, double xi_star) const;
  /// Two levels at (xi, delta), xi >= xi*(delta). in_range false for delta > delta_top.
  PeriodicState two_level(double xi, double delta) const { return two_level(xi, row(delta)); }
  PeriodicState two_level(double xi, const Row& row) const;
  /// Whether the pressure grows everywhere along the path from xi_a to xi_b at delta (two
  /// levels once past touchdown): the samples' intervals it crosses are all monotone.
  bool pressure_monotone(double xi_a, double xi_b, const Row& row) const;
  bool pressure_monotone(double xi_a, double xi_b, double delta) const {
    return pressure_monotone(xi_a, xi_b, row(delta));
  }

  /// As numbers: kFormat, the header (s, n, sizes, ranges), then every array; and back,
  /// empty for anything inconsistent (sizes, non-finite values, a bad header).
  std::vector<double> tables() const;
  static std::optional<PeriodicTable> from_tables(const std::vector<double>& numbers);

  /// A file name: periodic-s<s>-n<n>.
  static std::string table_name(int s, int n);

 private:
  double touchdown_v(double delta) const;
  /// Whether every interval of monotone1 / monotone2 is monotone (the usual case: then
  /// pressure_monotone needs no search). Set by from_tables and the builder's finish().
  bool all_monotone_ = false;
  /// Q2 / (xi - xi*) at every sample (J x K), what two_level() interpolates: a cubic
  /// through Q2 itself dipped below zero just after touchdown (by 1e-6 of the load,
  /// measured), one through the ratio, clamped at zero, does not. At r = 0 the limit,
  /// extrapolated from the next three samples.
  std::vector<double> q2_rate_;
  /// a1, a2 and q2_rate_ of each sample side by side, what two_level() reads.
  std::vector<double> fields_;
  /// The samples' grids in v, delta and r.
  UniformGrid v_grid_, delta_grid_, r_grid_;

 public:
  /// Derived fields (all_monotone_, the grids) once the arrays are filled.
  void finish();
  /// The samples' grids alone, once their counts and ranges are set (the builder reads its
  /// curve while it fills the surface).
  void set_grids();
};

}  // namespace punchsweep::model
