#pragma once

#include <cstdint>
#include <string_view>

#include "model/contact_problem.hpp"
#include "model/creep_law.hpp"

namespace punchsweep::model {

/// When level 2 touches (model notes, section 4). The integer codes are a file format
/// contract (the regime map stores them); never renumber.
enum class Regime : std::int8_t {
  immediate = 0,  ///< h(0) >= dh: at once, t* = 0
  delayed = 1,    ///< h(0) < dh <= h(inf): at t* > 0 with h(t*) = dh
  never = 2,      ///< h(inf) < dh: never (limited creep only)
};

std::string_view regime_name(Regime regime);

/// Regime and t* of one point, from a single root: the level-1 radius a1* with h(a1*) = dh
/// gives the creep J* = X(a1*)/pbar0 at which level 2 touches; comparing J* with J(0) and
/// J(inf) classifies, and t* = J^-1(J*).
struct Classification {
  Regime regime = Regime::never;
  double t_star = 0.0;  ///< in T_eps; 0 for immediate, +infinity for never
  double a1_star = 0.0; ///< level-1 radius at touchdown, in R (0 when dh = 0)
  double J_star = 0.0;  ///< creep at touchdown, in 1/E0*
};

/// Classifies one point (the problem must satisfy problem_error() == "").
Classification classify(const ContactProblem& problem, const CreepLaw& creep);

}  // namespace punchsweep::model
