#include "model/contact/regime.hpp"

#include <algorithm>
#include <cmath>
#include <limits>


namespace punchsweep::model {

std::string_view regime_name(Regime regime) {
  switch (regime) {
    case Regime::immediate: return "immediate";
    case Regime::delayed: return "delayed";
    case Regime::never: return "never";
  }
  return "unknown";
}

Classification classify(const Touchdown& touch, const CreepWeightedLoad& load) {
  Classification out;
  out.a1_star = touch.a1_star;
  out.X_star = touch.X_star;
  out.J_star = touch.X_star / load.pbar0();
  if (out.J_star <= load.response_initial()) {
    out.regime = Regime::immediate;
    out.t_star = 0.0;
    out.elastic_start = load.initial() > 0.0;
  } else {
    // g* = g(inf) exactly would mean touching only as t -> infinity: that is "never".
    out.t_star = out.J_star < load.response_final() ? std::max(0.0, load.time_at_response(out.J_star))
                                                    : std::numeric_limits<double>::infinity();
    const double rise = load.shape().rise_time();
    const bool while_rising = rise > 0.0 && out.t_star <= rise;
    out.regime = !std::isfinite(out.t_star) ? Regime::never : while_rising ? Regime::immediate : Regime::delayed;
  }
  return out;
}

}  // namespace punchsweep::model
