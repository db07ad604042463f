#pragma once

#include <cstdint>
#include <string_view>

#include "model/problem/contact_problem.hpp"
#include "model/load/creep_weighted_load.hpp"

namespace punchsweep::model {

/// When level 2 touches (docs/model.md, section 4). The integer codes are a file format
/// contract (the regime map stores them); never renumber.
enum class Regime : std::int8_t {
  /// By the end of the load's rise: for a step at once (h(0) >= dh, t* = 0); under a ramp
  /// or table while the load still rises (0 < t* <= rise time).
  immediate = 0,
  delayed = 1,    ///< later, while the load is held: at t* > rise time with h(t*) = dh
  never = 2,      ///< h(inf) < dh: never (limited creep only)
};

std::string_view regime_name(Regime regime);

/// Regime and t* of one point, from a single root (docs/model.md, section 10): the level-1
/// radius a1* with h(a1*) = dh gives the creep-weighted load X* at which level 2 touches;
/// comparing g* = X*/pbar0 with g(0+) and g(inf) classifies, and t* = g^-1(g*) (for a step
/// g = J, so g* = J*).
struct Classification {
  Regime regime = Regime::never;
  double t_star = 0.0;  ///< in T_eps; 0 for immediate, +infinity for never
  double a1_star = 0.0; ///< level-1 radius at touchdown, in R (0 when dh = 0)
  double J_star = 0.0;  ///< g* = X*/pbar0 at touchdown (the creep J* for a step), in 1/E0*
  double X_star = 0.0;  ///< creep-weighted load at touchdown, in E0*
  /// Level 2 touches at t = 0+ under a load X(0+) > 0, so the two-level phase starts from
  /// the elastic two-level solution (eqs 9.12-9.15); otherwise it starts at t* from the
  /// single-level state with a2 = 0 (also when an immediate touch comes during a ramp).
  bool elastic_start = false;
};

/// Where level 2 touches along the single-level solution: the level-1 radius a1* with
/// h(a1*) = dh and the creep-scaled pressure X* = pbar0 J* there. Depends on (l, s, C, dh)
/// only, so a sweep computes it once per dh.
struct Touchdown {
  double a1_star = 0.0;  ///< in R (0 when dh = 0)
  double X_star = 0.0;   ///< in E0*
};

/// The touchdown point of a single-level phase `single` (SingleLevel or SingleLevelShells:
/// its l, shape and localization) for height difference dh. X* is +infinity where h never
/// reaches dh before the spots reach their limit (only under a refined localization, whose
/// h stays finite as spots merge).
template <class Single>
Touchdown touchdown(const Single& single, double dh) {
  Touchdown t;
  t.a1_star = single.contact_radius_at_gap(dh);
  t.X_star = t.a1_star > 0.0 ? single.creep_scaled_pressure(t.a1_star) : 0.0;
  return t;
}

/// Classifies from a touchdown point: cheap (no root).
Classification classify(const Touchdown& touch, const CreepWeightedLoad& load);

}  // namespace punchsweep::model
