#pragma once
/// @file
/// Every output quantity of a point, declared once: its name (the map's variable, the
/// point command's JSON key and CSV column), its type, whether it runs over the snapshot
/// times, whether the model or the BEM reference gives it, its units and long name, and
/// how it is read off the model's result. The tile's storage (TileData), the map's
/// variables and their chunk order (io/map_variables.hpp, the journal), the sweep's tile
/// evaluation and the point output formats all iterate this list; adding a quantity is a
/// field of the model's result and one entry here.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string_view>

#include "model/point/point_evaluation.hpp"

namespace punchsweep::map {

/// What a map stores: the per-point quantities only, or also the time series.
enum class Quantities { regime, full };

enum class Kind { flag, real };       ///< int8 code, or float64
/// Over the grid; over the grid, stored in full mode only; or over the grid and the times.
enum class Extent { point, point_full, series };
/// The localization model, the periodic BEM reference, the answer merged from both (the
/// BEM's where it ran, else the model's where it is valid; TileEvaluator fills it), or the
/// model over a box of tolerances about each point (output.tolerance).
enum class Source { model, bem, answer, tolerance };

/// The flag sets a flag quantity takes its codes from (the map's flag_values/flag_meanings).
enum class Flags { none, regime, validity, convergence, source };

/// The code of a point a tile or map has not computed, in every flag set.
inline constexpr std::int8_t kNotComputed = -1;

/// Flags::convergence: whether every contact solve of a BEM point met its tolerance.
enum class Convergence : std::int8_t { not_converged = 0, converged = 1 };
inline constexpr std::array<Convergence, 2> kConvergences{Convergence::not_converged, Convergence::converged};
constexpr std::string_view flag_meaning(Convergence c) {
  return c == Convergence::converged ? "converged" : "not_converged";
}

/// Flags::source: which solution a point's merged answer comes from.
enum class AnswerSource : std::int8_t { model = 0, bem = 1, none = 2 };
inline constexpr std::array<AnswerSource, 3> kAnswerSources{AnswerSource::model, AnswerSource::bem,
                                                            AnswerSource::none};
constexpr std::string_view flag_meaning(AnswerSource s) {
  return s == AnswerSource::model ? "model" : s == AnswerSource::bem ? "bem" : "none";
}

struct QuantitySpec {
  std::string_view name;
  Kind kind;
  Extent extent;
  Source source;
  Flags flags;                 ///< Flags::none for reals
  /// The scale the value is measured in (model/numerics/units.hpp): "R", "T_eps", "R^2 E0/(1-nu^2)",
  /// or "1" for a pure number; empty for flags. The map writes `units = "1"` for every real
  /// and names the scale in `scaled_by` (UDUNITS would read "R" as the roentgen).
  std::string_view scale;
  std::string_view long_name;
  std::string_view comment;    ///< empty when there is none
  /// Reads the quantity off a point's result (for Source::bem, off the reference's result
  /// in the model's terms, reference::as_point_result): `code` for flags, `value` for
  /// per-point reals, `series_value` for series reals.
  std::int8_t (*code)(const model::PointSummary&) = nullptr;
  double (*value)(const model::PointSummary&) = nullptr;
  double (*series_value)(const model::Snapshot&) = nullptr;
};

namespace quantity_access {
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline std::int8_t regime(const model::PointSummary& s) { return static_cast<std::int8_t>(s.regime); }
inline std::int8_t validity(const model::PointSummary& s) { return static_cast<std::int8_t>(s.validity); }
inline double t_star(const model::PointSummary& s) { return s.t_star.value_or(kNaN); }
inline double h_0(const model::PointSummary& s) { return s.h_0; }
inline double h_inf(const model::PointSummary& s) { return s.h_inf; }
inline double a1_inf(const model::PointSummary& s) { return s.a1_inf; }
inline double dt_star_ddh(const model::PointSummary& s) { return s.dt_star_ddh; }
inline double dt_star_dpbar(const model::PointSummary& s) { return s.dt_star_dpbar; }
inline double dt_star_dl(const model::PointSummary& s) { return s.dt_star_dl; }
inline double a2_inf(const model::PointSummary& s) { return s.a2_inf; }
inline double area_fraction_inf(const model::PointSummary& s) { return s.area_fraction_inf; }
inline double a1(const model::Snapshot& s) { return s.a1; }
inline double a2(const model::Snapshot& s) { return s.a2; }
inline double P1(const model::Snapshot& s) { return s.P1; }
inline double P2(const model::Snapshot& s) { return s.P2; }
inline double area_fraction(const model::Snapshot& s) { return s.area_fraction; }
inline std::int8_t converged(const model::PointSummary& s) {
  return static_cast<std::int8_t>(s.solver.converged ? Convergence::converged : Convergence::not_converged);
}
inline double iterations(const model::PointSummary& s) { return s.solver.iterations; }
// Over a box of tolerances: t* at its ends (NaN for never, as t_star; and where a corner
// could not be computed), and the regimes there (not computed likewise).
inline bool has_range(const model::PointSummary& s) { return s.t_star_range && !std::isnan(s.t_star_range->low); }
inline double finite_or_nan(double t) { return std::isfinite(t) ? t : kNaN; }
inline double t_star_low(const model::PointSummary& s) { return has_range(s) ? finite_or_nan(s.t_star_range->low) : kNaN; }
inline double t_star_high(const model::PointSummary& s) {
  return has_range(s) ? finite_or_nan(s.t_star_range->high) : kNaN;
}
inline std::int8_t regime_low(const model::PointSummary& s) {
  return has_range(s) ? static_cast<std::int8_t>(s.t_star_range->regime_low) : std::int8_t{-1};
}
inline std::int8_t regime_high(const model::PointSummary& s) {
  return has_range(s) ? static_cast<std::int8_t>(s.t_star_range->regime_high) : std::int8_t{-1};
}
inline double residual(const model::PointSummary& s) { return s.solver.residual; }
}  // namespace quantity_access

/// The quantities in the order the map creates its variables, the journal stores a tile's
/// chunks and the point command prints them.
inline constexpr std::array<QuantitySpec, 33> kQuantities{{
    {"regime", Kind::flag, Extent::point, Source::model, Flags::regime, "", "contact regime of the level-2 punches",
     "immediate: level 2 touches by the end of the load's rise (at once for a step load); delayed: later, while "
     "the load is held; never: not at all", quantity_access::regime},
    {"t_star", Kind::real, Extent::point, Source::model, Flags::none, "T_eps",
     "time at which the level-2 punches touch",
     "0 for the immediate regime under a step load (under a ramp or table its time during the rise), NaN for never",
     nullptr, quantity_access::t_star},
    {"h_0", Kind::real, Extent::point, Source::model, Flags::none, "R",
     "displacement difference between punch tip and square centre at t = 0", "", nullptr, quantity_access::h_0},
    {"h_inf", Kind::real, Extent::point, Source::model, Flags::none, "R",
     "displacement difference between punch tip and square centre as t -> infinity", "", nullptr,
     quantity_access::h_inf},
    {"valid", Kind::flag, Extent::point, Source::model, Flags::validity, "", "validity of the localization method",
     "", quantity_access::validity},
    {"a1_inf", Kind::real, Extent::point, Source::model, Flags::none, "R",
     "long-term contact radius of a level-1 punch", "", nullptr, quantity_access::a1_inf},
    {"a2_inf", Kind::real, Extent::point, Source::model, Flags::none, "R",
     "long-term contact radius of a level-2 punch", "", nullptr, quantity_access::a2_inf},
    {"area_fraction_inf", Kind::real, Extent::point, Source::model, Flags::none, "1",
     "long-term contact area fraction", "", nullptr, quantity_access::area_fraction_inf},
    {"dt_star_ddh", Kind::real, Extent::point_full, Source::model, Flags::none, "T_eps/R",
     "rate of change of t* with the height difference",
     "Richardson-extrapolated central difference of the model's t* (docs/model.md, Sensitivity); NaN where t* is "
     "not delayed or not smooth within the step", nullptr, quantity_access::dt_star_ddh},
    {"dt_star_dpbar", Kind::real, Extent::point_full, Source::model, Flags::none, "T_eps/(E0/(1-nu^2))",
     "rate of change of t* with the nominal pressure", "as dt_star_ddh", nullptr, quantity_access::dt_star_dpbar},
    {"dt_star_dl", Kind::real, Extent::point_full, Source::model, Flags::none, "T_eps/R",
     "rate of change of t* with the lattice pitch", "as dt_star_ddh", nullptr, quantity_access::dt_star_dl},
    {"a1", Kind::real, Extent::series, Source::model, Flags::none, "R", "contact radius of a level-1 punch", "",
     nullptr, nullptr, quantity_access::a1},
    {"a2", Kind::real, Extent::series, Source::model, Flags::none, "R", "contact radius of a level-2 punch", "",
     nullptr, nullptr, quantity_access::a2},
    {"P1", Kind::real, Extent::series, Source::model, Flags::none, "R^2 E0/(1-nu^2)", "load on one level-1 punch",
     "", nullptr, nullptr, quantity_access::P1},
    {"P2", Kind::real, Extent::series, Source::model, Flags::none, "R^2 E0/(1-nu^2)", "load on one level-2 punch",
     "", nullptr, nullptr, quantity_access::P2},
    {"area_fraction", Kind::real, Extent::series, Source::model, Flags::none, "1", "contact area fraction", "",
     nullptr, nullptr, quantity_access::area_fraction},
    {"bem_regime", Kind::flag, Extent::point, Source::bem, Flags::regime, "",
     "periodic BEM reference: contact regime of the level-2 punches",
     "not_computed at grid points outside the reference sample", quantity_access::regime},
    {"bem_converged", Kind::flag, Extent::point, Source::bem, Flags::convergence, "",
     "periodic BEM reference: whether every contact solve of the point met its tolerance",
     "not_converged: a conjugate-gradient solve stopped at its iteration limit above the tolerance (its numbers "
     "are kept, and are not to be trusted); not_computed outside the reference sample",
     quantity_access::converged},
    {"bem_iterations", Kind::real, Extent::point, Source::bem, Flags::none, "1",
     "periodic BEM reference: conjugate-gradient iterations over all contact solves of the point",
     "NaN outside the reference sample", nullptr, quantity_access::iterations},
    {"bem_residual", Kind::real, Extent::point, Source::bem, Flags::none, "1",
     "periodic BEM reference: largest final residual of the point's contact solves",
     "max(|gap| over the contact, penetration elsewhere) divided by the displacement range; the solves stop at "
     "1e-10. NaN outside the reference sample",
     nullptr, quantity_access::residual},
    {"bem_t_star", Kind::real, Extent::point, Source::bem, Flags::none, "T_eps",
     "periodic BEM reference: time at which the level-2 punches touch",
     "0 for the immediate regime; NaN for never, for delayed beyond the last snapshot time, and outside the "
     "reference sample",
     nullptr, quantity_access::t_star},
    {"bem_a1", Kind::real, Extent::series, Source::bem, Flags::none, "R",
     "periodic BEM reference: contact radius of a level-1 punch",
     "equivalent radius sqrt(area / pi) of the grid nodes in contact; NaN outside the reference sample", nullptr,
     nullptr, quantity_access::a1},
    {"bem_a2", Kind::real, Extent::series, Source::bem, Flags::none, "R",
     "periodic BEM reference: contact radius of a level-2 punch",
     "equivalent radius sqrt(area / pi) of the grid nodes in contact; NaN outside the reference sample", nullptr,
     nullptr, quantity_access::a2},
    {"bem_P1", Kind::real, Extent::series, Source::bem, Flags::none, "R^2 E0/(1-nu^2)",
     "periodic BEM reference: load on one level-1 punch", "NaN outside the reference sample", nullptr, nullptr,
     quantity_access::P1},
    {"bem_P2", Kind::real, Extent::series, Source::bem, Flags::none, "R^2 E0/(1-nu^2)",
     "periodic BEM reference: load on one level-2 punch", "NaN outside the reference sample", nullptr, nullptr,
     quantity_access::P2},
    {"bem_area_fraction", Kind::real, Extent::series, Source::bem, Flags::none, "1",
     "periodic BEM reference: contact area fraction", "NaN outside the reference sample", nullptr, nullptr,
     quantity_access::area_fraction},
    {"answer_regime", Kind::flag, Extent::point, Source::answer, Flags::regime, "",
     "contact regime of the level-2 punches, the best answer at the point",
     "the periodic BEM's where it ran, else the model's where the model is valid; not_computed where neither "
     "answers (answer_source says which)"},
    {"answer_t_star", Kind::real, Extent::point, Source::answer, Flags::none, "T_eps",
     "time at which the level-2 punches touch, the best answer at the point",
     "from the same solution as answer_regime; NaN for never and where neither answers"},
    {"answer_source", Kind::flag, Extent::point, Source::answer, Flags::source, "",
     "which solution answer_regime and answer_t_star come from",
     "model: the localization model, valid there and no BEM run; bem: the periodic BEM reference; none: the "
     "model is invalid there and the BEM did not run"},
    {"t_star_low", Kind::real, Extent::point, Source::tolerance, Flags::none, "T_eps",
     "least time at which the level-2 punches touch over the box of tolerances about the point",
     "the model's t* at every corner of the box (the map's tolerance attribute), the least; NaN where a corner "
     "could not be computed, and for never at every corner", nullptr, quantity_access::t_star_low},
    {"t_star_high", Kind::real, Extent::point, Source::tolerance, Flags::none, "T_eps",
     "greatest time at which the level-2 punches touch over the box of tolerances about the point",
     "as t_star_low, the greatest; NaN where some corner never touches (regime_high never)", nullptr,
     quantity_access::t_star_high},
    {"regime_low", Kind::flag, Extent::point, Source::tolerance, Flags::regime, "",
     "contact regime at the corner of the tolerance box where level 2 touches first",
     "where regime_low equals regime_high, the regime holds over the whole box", quantity_access::regime_low},
    {"regime_high", Kind::flag, Extent::point, Source::tolerance, Flags::regime, "",
     "contact regime at the corner of the tolerance box where level 2 touches last", "as regime_low",
     quantity_access::regime_high},
}};

inline constexpr std::size_t kQuantityCount = kQuantities.size();

/// The index of the quantity called `name` in kQuantities (a compile-time lookup:
/// `quantity("t_star")`); kQuantityCount if none.
constexpr std::size_t quantity(std::string_view name) {
  for (std::size_t q = 0; q < kQuantityCount; ++q) {
    if (kQuantities[q].name == name) return q;
  }
  return kQuantityCount;
}

/// Whether a map of `quantities`, with or without a BEM reference and a box of
/// tolerances, stores quantity `q`.
constexpr bool is_stored(const QuantitySpec& q, Quantities quantities, bool bem, bool tolerance = false) {
  if (q.source == Source::tolerance) return tolerance;
  if (q.source == Source::bem || q.source == Source::answer) return bem;
  return q.extent == Extent::point || quantities == Quantities::full;  // point_full and series: full only
}

}  // namespace punchsweep::map
