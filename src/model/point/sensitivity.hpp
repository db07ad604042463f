#pragma once
/// @file
/// How t* moves with each input (docs/model.md, "Sensitivity"): d t*/dx along every
/// real-valued parameter of the point (l, dh, pbar, C, and the creep law's: T, a
/// material's temperature), by central differences of the engine's own t* checked
/// against the difference at half the step; and the range of t* over a box of tolerances.

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "model/laws/creep_laws.hpp"
#include "model/problem/contact_problem.hpp"
#include "model/problem/parameter.hpp"
#include "model/contact/regime.hpp"

namespace punchsweep::model {

/// d t*/dx at one point along one parameter.
struct TStarDerivative {
  const Parameter* parameter = nullptr;
  double value = 0.0;  ///< x at the point, in the parameter's scale
  /// d t*/dx in the time unit of t* per the parameter's scale (R, E0*, degC, 1): the
  /// Richardson extrapolation of the central differences at steps h and h/2
  /// (h = kRelativeStep max(|x|, 1) for temperature, kRelativeStep |x| else). NaN where t*
  /// is not delayed at the point, or not delayed at every step, or where the two
  /// differences disagree by more than kAgreement (t* is not smooth within the step).
  double derivative = 0.0;
  /// d ln t* / d ln x = (x / t*) d t*/dx: the relative change of t* per relative change of
  /// x (NaN as derivative, and for temperature, whose zero is arbitrary).
  double elasticity = 0.0;
};

inline constexpr double kRelativeStep = 1e-4;
inline constexpr double kAgreement = 1e-3;

/// t* of the point (problem, law at law_values), in the time unit of the law: 0 immediate,
/// +inf never.
double t_star_of(const ContactProblem& problem, const CreepLawSpec& law, std::span<const double> law_values);

/// d t*/dx by the rule TStarDerivative states, t_at(x) giving t* at x (NaN where x is
/// inadmissible); elasticity (x / t*) d t*/dx unless `temperature`.
TStarDerivative t_star_derivative(const Parameter& parameter, double x, double t_star, bool temperature,
                                  const std::function<double(double)>& t_at);

/// The derivative along one of the problem's own parameters (l, dh, pbar, C), the creep
/// law held: what a map's full mode stores for dh, pbar and l.
TStarDerivative t_star_derivative(const ContactProblem& problem, const CreepLaw& creep, std::string_view name,
                                  double t_star);

/// The derivatives along the problem's l, dh, pbar, C and law's real-valued parameters
/// (in that order), at a point whose t* is `t_star` (as t_star_of gives it).
std::vector<TStarDerivative> t_star_derivatives(const ContactProblem& problem, const CreepLawSpec& law,
                                                std::span<const double> law_values, double t_star);

/// A tolerance on one parameter: x within [value - minus, value + plus].
struct Tolerance {
  const Parameter* parameter = nullptr;
  double minus = 0.0, plus = 0.0;
};

/// A tolerance as a user states it ("dh=0.5um", "pressure=10%"): a half-width in the
/// parameter's scale, or a fraction of the value (`relative`).
struct StatedTolerance {
  const Parameter* parameter = nullptr;
  double width = 0.0;
  bool relative = false;
  std::string text;  ///< the value as stated ("0.5um"), for messages
  /// About `value`: the half-width there, and below a range that starts at 0 (dh: the two
  /// levels at one height) the low side clipped at 0 (`clipped` says so).
  Tolerance at(double value, bool* clipped = nullptr) const;
};

/// The least and greatest t* over the box of tolerances (its 2^k corners, k <= 6: t* is
/// monotone in dh, pbar, l and temperature, so the extremes lie at corners; 0 where a
/// corner touches at once, +inf where one never touches), and how many corners fall in
/// each regime; where a corner's t* cannot be computed, low and high are NaN (never a
/// range that leaves it out). Throws std::invalid_argument naming a tolerance that takes
/// its parameter out of range, or one on no real-valued parameter of the point.
struct TStarRange {
  double low = 0.0, high = 0.0;
  /// The regimes at the corners of least and greatest t*: where they agree, the regime
  /// holds across the box (t* is monotone; the regimes are ordered by t*).
  Regime regime_low = Regime::immediate, regime_high = Regime::never;
  int immediate = 0, delayed = 0, never = 0, not_computed = 0;  ///< corners in each
  /// Counts a corner of t* `t_star` (NaN: not computed) and regime `regime`, and keeps it
  /// as the low or high end where its t* is the least or greatest so far (of equal t*, the
  /// lesser regime low and the greater high: all corners never gives never at both ends).
  void take(double t_star, Regime regime);
};
TStarRange t_star_range(const ContactProblem& problem, const CreepLawSpec& law, std::span<const double> law_values,
                        std::span<const Tolerance> tolerances);

/// The same for tolerances as stated, each taken about the point's own value of its
/// parameter (StatedTolerance::at): what a map's output.tolerance gives every point.
TStarRange t_star_range(const ContactProblem& problem, const CreepLawSpec& law, std::span<const double> law_values,
                        std::span<const StatedTolerance> stated);

/// The most tolerances a box may have (2^6 = 64 corners).
inline constexpr std::size_t kMaxTolerances = 6;

/// What a t* on a knife edge says, in `point` and `surface` alike: the input whose 1% moves
/// t* most, where that is more than 10% (|x/t* d t*/dx| > 10); empty where no input does.
std::string knife_edge_note(const std::vector<TStarDerivative>& derivatives);

/// Where |x/t* d t*/dx| exceeds this, t* is on a knife edge (a 1% change of x moves it by
/// more than 10%): knife_edge_note and design's note at an edge.
inline constexpr double kKnifeEdgeElasticity = 10.0;

}  // namespace punchsweep::model
