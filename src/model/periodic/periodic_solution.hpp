#pragma once
/// @file
/// The elastic periodic solution of the two-level cell at every load (docs/model.md,
/// sections 14.3 and 14.7): the boundary elements' tables (periodic_table.hpp) where they
/// resolve the spots, the small-spot table (small_spot_table.hpp) below, and a smooth
/// hand-over between them. What the `periodic` model reads (periodic_model.hpp, beside it).
///
/// The hand-over: over v = xi^(1/(s+1)) in a band (the small-spot table's) every field is
///     w(v) small + (1 - w(v)) tables,     w = 1 - u^2 (3 - 2 u), u = (v - v_from)/(v_to - v_from);
/// below the band the small-spot table alone, above it the boundary elements' alone. The gap
/// h has a band of its own, lower (the single level's contact radius from about 0.1 l to
/// 0.15 l, where both give h within 5e-6 of the boundary elements at N = 2048), the radii
/// and loads theirs (about 0.3 l to 0.35 l, where both give loads within 1e-4 of the load
/// and radii within 1e-3; the bands of each s are small_spot_builder.hpp's
/// hand_over_radii).
/// The single level below v_top is one curve (ratio_curve.hpp) at the small-spot table's
/// samples, two more past v_top: the small spots' ratios below the bands, the blends in
/// them, the boundary elements' above; one reading per state, and its touchdown the small
/// spots' own inversion. The two levels are read in the small-spot table at eta = delta / h,
/// h that curve's, so that they touch down exactly where it says; the boundary elements'
/// surface, read from the radii's band up (above the gap's, where h is theirs), from the
/// touchdown said here (row()).

#include <functional>
#include <memory>
#include <optional>

#include "model/periodic/periodic_table.hpp"
#include "model/periodic/ratio_curve.hpp"
#include "model/periodic/small_spot_table.hpp"

namespace punchsweep::model {

class PeriodicSolution {
 public:
  /// Both tables of one s (std::invalid_argument if either is missing or they differ in s,
  /// or if the blended h does not increase through the band).
  PeriodicSolution(std::shared_ptr<const PeriodicTable> tables, std::shared_ptr<const SmallSpotTable> small);

  int s() const { return tables_->s; }
  const PeriodicTable& tables() const { return *tables_; }
  const SmallSpotTable& small() const { return *small_; }
  double delta_hidden() const { return tables_->delta_hidden(); }
  double delta_top() const { return tables_->delta_top; }

  /// Single level at xi >= 0: h, a1, Q1 = xi.
  PeriodicState single(double xi) const;
  /// The touchdown load xi*(delta): h(xi*) = delta; 0 for delta <= 0, +infinity for
  /// delta >= delta_hidden().
  double touchdown(double delta) const;

  /// What the two-level queries at one delta share; a caller that asks many loads at one
  /// delta computes it once.
  struct Row {
    double delta = 0.0;
    double xi_star = 0.0;      ///< touchdown (+infinity where level 2 hides)
    PeriodicTable::Row table;  ///< the boundary elements' row of delta (their own touchdown)
    bool in_range = true;      ///< delta <= delta_top() (or level 2 never touches)
  };
  Row row(double delta) const { return row(delta, touchdown(delta)); }
  /// The same where touchdown(delta) is known.
  Row row(double delta, double xi_star) const;
  /// Two levels at xi >= xi*(delta). in_range false for delta > delta_top(). delta = 0 (one
  /// height): the levels' states are equal, each carrying xi / 2.
  PeriodicState two_level(double xi, const Row& row) const;
  PeriodicState two_level(double xi, double delta) const { return two_level(xi, row(delta)); }
  /// Whether the pressure grows at every node along loads xi_a .. xi_b (the boundary
  /// elements' record where they are read; small spots' pressures grow with their load).
  bool pressure_monotone(double xi_a, double xi_b, const Row& row) const;

  /// The weight of the small-spot table's two levels at v (1 below their band, 0 above).
  double small_weight(double v) const;

  /// The single level below v_top (the small-spot table's samples, blended in the bands).
  const RatioCurve& curve() const { return curve_; }

 private:
  std::shared_ptr<const PeriodicTable> tables_;
  std::shared_ptr<const SmallSpotTable> small_;
  RatioCurve curve_;
  double v_hand_ = 0.0, v_top_ = 0.0;
  double xi_top_ = 0.0;  ///< v_top^(s+1): above it the boundary elements' tables alone
  double xi_gap_hand_ = 0.0;
  double h_top_ = 0.0;   ///< h at v_top
};

/// Where the model gets the solution of s: set by the application (the shipped tables, a
/// cache folder, or built; texture/periodic_tables.hpp). Without a source the periodic model
/// cannot be evaluated (std::runtime_error naming what is missing).
using PeriodicSolutionSource = std::function<std::shared_ptr<const PeriodicSolution>(int s)>;
void set_periodic_solution_source(PeriodicSolutionSource source);
/// The solution of s, from the source on first use, then shared (thread-safe).
const PeriodicSolution& periodic_solution(int s);

}  // namespace punchsweep::model
