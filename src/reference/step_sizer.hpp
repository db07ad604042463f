#pragma once
/// @file
/// The time steps of the time-stepping reference (reference_point.hpp, cell_stepping.hpp):
/// what a caller asks for (StepControl) and the lengths that follow (StepSizer). Units: time
/// in the creep law's unit (T_eps for the standard linear solid).

#include <algorithm>
#include <limits>

#include "model/laws/creep_law.hpp"

namespace punchsweep::reference {

/// The time steps. Under a held load the contact set at t is the elastic one at J(t)
/// (the extended correspondence principle), so the contact changes as J does: each step
/// grows J by the factor 1 + creep_growth (J's doubling-then-halving inverse, to 1/256 of
/// the step), and is at least `first_step` and at most `max_step` (the cap lifts once t is
/// past 40 max_step, where the retardation terms have died out; and once J is within 1e-3
/// of a step's growth of J(inf) the next step goes to the end, however far: the number of
/// steps grows as log t, not as t). While the load still
/// rises, and for creep_growth = 0 throughout, the steps instead grow geometrically by
/// `growth` from `first_step` to `max_step` (the fixed ladder). Steps also end on the
/// snapshot times and the load's kinks: by J's rule, a snapshot at most 1.25 steps away is
/// reached in one step, and one at most two away in two equal ones. Scaling the step lengths by k scales the
/// time-discretisation error of the loads by about k^2 (second order; tested); under a
/// held load and a retardation-series law the contact areas, hence t*, do not depend on
/// the steps at all (ViscoelasticStepper).
struct StepControl {
  double first_step = 0.02;  ///< in T_eps, > 0
  double growth = 1.25;      ///< >= 1
  double max_step = 1.0;     ///< in T_eps, >= first_step
  double creep_growth = 0.05;  ///< J(t + dt) / J(t) - 1 per step, >= 0 (0: the ladder)
};

/// The step lengths of StepControl: the fixed ladder, or steps of equal growth of the creep
/// compliance.
class StepSizer {
 public:
  static constexpr double kSaturated = 1e-3;
  static constexpr double kSettled = 40.0;

  StepSizer(const StepControl& control, const model::CreepLaw& creep, double rise_time)
      : control_(control), creep_(creep), rise_(rise_time), ladder_(control.first_step) {}

  /// The length of the step from t (a caller may shorten it to land on a snapshot or a kink).
  double step(double t) const {
    if (control_.creep_growth == 0.0) return ladder_;
    // Under a held load the contact set at t is the elastic one at J(t): steps of equal
    // growth of log J are steps of equal change of the contact. J is non-decreasing, so
    // the step is found by doubling, then halving, on it.
    const double J = creep_.creep(t);
    const double target = J * (1.0 + control_.creep_growth);
    // Once J is within a thousandth of a step's growth of J(inf), the contact set is the
    // long-term one to far better than a step's accuracy and no longer changes: one step
    // to the end, however far (to t = 1e12 as cheaply as to t = 10).
    if (t >= rise_ && creep_.creep_final() <= J * (1.0 + kSaturated * control_.creep_growth)) {
      return std::numeric_limits<double>::infinity();
    }
    // The cap resolves the retardation times; once they have died out (t beyond
    // kSettled max_step, max_step being the longest of them) only J's own growth (a
    // dashpot's, a power law's) sizes the steps, so their number grows as log t.
    const double cap = t > kSettled * control_.max_step ? std::numeric_limits<double>::infinity() : control_.max_step;
    double h = control_.first_step;
    while (h < cap && creep_.creep(t + 2.0 * h) <= target) h *= 2.0;
    double lo = h, hi = 2.0 * h;
    for (int k = 0; k < 8 && creep_.creep(t + lo) <= target; ++k) {  // (none when first_step overshoots)
      const double mid = 0.5 * (lo + hi);
      (creep_.creep(t + mid) <= target ? lo : hi) = mid;
    }
    h = std::min(lo, cap);
    // While the load rises the contact is not J's alone: the ladder's lengths bound it.
    return t < rise_ ? std::min(h, ladder_) : h;
  }

  /// The end of the step from t towards `end` (a snapshot time or a kink of the load): a
  /// step of step(t), or `end` itself when it is at most 1.25 steps away, or half the way
  /// when it is at most two (no sliver of a step before a snapshot). The ladder keeps its
  /// lengths and only ever shortens a step to land.
  double next(double t, double end) const {
    const double h = step(t);
    const double remaining = end - t;
    if (control_.creep_growth == 0.0) return std::min(t + h, end);
    if (remaining <= 1.25 * h) return end;
    return remaining < 2.0 * h ? t + 0.5 * remaining : t + h;
  }

  /// A step was taken: the ladder grows.
  void accepted() { ladder_ = std::min(ladder_ * control_.growth, control_.max_step); }

 private:
  StepControl control_;
  const model::CreepLaw& creep_;
  double rise_;
  double ladder_;
};

}  // namespace punchsweep::reference
