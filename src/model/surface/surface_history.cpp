#include "model/surface/surface_history.hpp"

#include <cmath>

namespace punchsweep::model {

std::string_view surface_validity_name(SurfaceValidity validity) {
  switch (validity) {
    case SurfaceValidity::valid: return "valid";
    case SurfaceValidity::below_resolution: return "below_resolution";
    case SurfaceValidity::above_top: return "above_top";
    case SurfaceValidity::unloading: return "unloading";
  }
  return "unknown";
}

SurfaceHistory surface_history(const LoadCurve& curve, const CreepWeightedLoad& load, std::span<const double> times) {
  SurfaceHistory out;
  for (const double X_star : curve.level_touchdown) {
    const Classification c = classify(Touchdown{0.0, X_star}, load);
    const bool resolved = X_star == 0.0 || !std::isfinite(X_star) || X_star >= curve.X_first();
    out.levels.push_back({c.regime, c.t_star, X_star, resolved});
  }
  const double X0 = load.initial();
  for (const double t : times) {
    SurfaceSnapshot s;
    s.t = t;
    // X at 0 is the load at once (X(0+)); a history without a jump starts unloaded.
    s.X = t > 0.0 ? load(t) : load.initial();
    s.state = curve.at(s.X);
    if (s.state.range == CurveRange::above_top) {
      s.validity = SurfaceValidity::above_top;
    } else if (!curve.monotone_between(std::min(X0, s.X), s.X)) {
      s.validity = SurfaceValidity::unloading;
    } else if (s.state.range == CurveRange::below_resolution && s.X > 0.0) {
      s.validity = SurfaceValidity::below_resolution;
    }
    out.snapshots.push_back(std::move(s));
  }
  return out;
}

}  // namespace punchsweep::model
