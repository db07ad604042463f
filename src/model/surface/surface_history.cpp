#include "model/surface/surface_history.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace punchsweep::model {

std::string_view surface_validity_name(SurfaceValidity validity) {
  switch (validity) {
    case SurfaceValidity::valid: return "valid";
    case SurfaceValidity::below_resolution: return "below_resolution";
    case SurfaceValidity::above_top: return "above_top";
    case SurfaceValidity::unloading: return "unloading";
    case SurfaceValidity::history_cost: return "history_cost";
    case SurfaceValidity::check_disagrees: return "check_disagrees";
  }
  return "unknown";
}

SurfaceValidity reading_validity(const LoadCurve& curve, double X0, const CurveState& state) {
  if (state.range == CurveRange::above_top) return SurfaceValidity::above_top;
  if (!curve.monotone_between(std::min(X0, state.X), state.X)) return SurfaceValidity::unloading;
  if (state.X > 0.0 && state.X < curve.X_resolved) return SurfaceValidity::below_resolution;
  return SurfaceValidity::valid;
}

bool touchdown_resolved(const LoadCurve& curve, std::size_t level) {
  const double X_star = curve.level_touchdown[level];
  const bool limit = level < curve.level_small_spot.size() && curve.level_small_spot[level] != 0;
  // (A level untouched by the curve's end: resolved where that end is, at full contact or
  // past X_resolved; a curve stopped below its resolution cannot say it is untouched.)
  if (!std::isfinite(X_star)) return limit || std::isfinite(curve.X_full) || curve.X_last() >= curve.X_resolved;
  return limit || X_star == 0.0 || X_star >= curve.X_resolved;
}

bool site_touchdown_resolved(const LoadCurve& curve, std::size_t site) {
  const double X_star = curve.site_touchdown[site];
  const std::size_t level = static_cast<std::size_t>(curve.site_level[site]);
  if (X_star == curve.level_touchdown[level]) return touchdown_resolved(curve, level);
  if (site < curve.site_small_spot.size() && curve.site_small_spot[site] != 0) return true;
  if (!std::isfinite(X_star)) return std::isfinite(curve.X_full) || curve.X_last() >= curve.X_resolved;
  return X_star == 0.0 || X_star >= curve.X_resolved;
}

LevelTouch level_touch(double X_star, bool resolved, const CreepWeightedLoad& load) {
  const Classification c = classify(Touchdown{0.0, X_star}, load);
  return {c.regime, c.t_star, X_star, resolved};
}

std::vector<LevelTouch> level_touches(const LoadCurve& curve, const CreepWeightedLoad& load) {
  return level_touches(curve.level_touchdown, [&](std::size_t level) { return touchdown_resolved(curve, level); }, load);
}

SurfaceHistory surface_history(const LoadCurve& curve, const CreepWeightedLoad& load, std::span<const double> times,
                               const HistoryQuadrature& quadrature) {
  SurfaceHistory out;
  out.levels = level_touches(curve, load);
  for (std::size_t site = 0; site < curve.sites(); ++site) {
    out.sites.push_back(level_touch(curve.site_touchdown[site], site_touchdown_resolved(curve, site), load));
  }
  const double X0 = load.initial();
  const auto X_at = [&](double t) { return t > 0.0 ? load(t) : X0; };
  double t_max = 0.0;
  for (const double t : times) t_max = std::max(t_max, t);

  // Each level's load history from its touch on (Q2 its load, Q1 the rest of the cell's).
  const std::size_t L = static_cast<std::size_t>(curve.levels());
  const double cell_load = load.pbar0() * curve.cell_area;  // Q1 = this g(tau) before the touch
  std::vector<std::optional<LoadHistory>> histories(L);
  // Q of `level` at tau off the curve: Q2 its load, Q1 the rest of the cell's (what a
  // history samples, and again near t for a narrow kernel).
  const auto sampler = [&curve, &load](std::size_t level) -> LoadHistory::Sampler {
    return [&curve, &load, level](double tau, double* Q1, double* Q2) {
      const double X = load(tau);
      const CurveState s = curve.at(X);
      if (s.range == CurveRange::above_top) return false;
      *Q2 = s.level_load[level];
      *Q1 = X * curve.cell_area - *Q2;
      return true;
    };
  };
  bool too_costly = false;
  for (std::size_t level = 1; level < L; ++level) {
    const double t0 = out.levels[level].t_star;
    if (!(t0 <= t_max)) continue;
    const LoadHistory::Cost cost = LoadHistory::cost(load, t0, t_max, quadrature);
    if (cost.samples > LoadHistory::kMaxSamples || cost.kernel_pieces > LoadHistory::kMaxKernelPieces) {
      too_costly = true;
      continue;
    }
    histories[level].emplace(load, cell_load, t0, t_max, quadrature, sampler(level));
  }

  for (const double t : times) {
    SurfaceSnapshot s;
    s.t = t;
    // X at 0 is the load at once (X(0+)); a history without a jump starts unloaded.
    s.X = X_at(t);
    s.state = curve.at(s.X);
    s.validity = reading_validity(curve, X0, s.state);
    const double nominal = load.nominal_pressure(t) * curve.cell_area;
    s.level_load.assign(L, 0.0);
    double rest = nominal;
    for (std::size_t level = 1; level < L && s.state.range != CurveRange::above_top; ++level) {
      if (!(out.levels[level].t_star <= t)) continue;  // untouched: no load
      const std::optional<LoadHistory>& history = histories[level];
      double P1 = 0.0, P2 = std::numeric_limits<double>::quiet_NaN();
      if (history && history->ok()) {
        if (!history->load(t, s.X * curve.cell_area - s.state.level_load[level], s.state.level_load[level], &P1, &P2,
                           sampler(level))) {
          P2 = std::numeric_limits<double>::quiet_NaN();
        }
      }
      s.level_load[level] = P2;
      rest -= P2;
    }
    s.level_load[0] = rest;
    if (s.state.range == CurveRange::above_top) std::fill(s.level_load.begin(), s.level_load.end(), std::numeric_limits<double>::quiet_NaN());
    if (s.validity == SurfaceValidity::valid && !std::isfinite(rest)) {
      s.validity = too_costly ? SurfaceValidity::history_cost : SurfaceValidity::above_top;
    }
    // A level's load below zero (beyond the quadrature's 1e-5 of the load): some node's
    // pressure would be negative, the contact receding (as the periodic model flags it).
    for (const double P : s.level_load) {
      if (s.validity == SurfaceValidity::valid && P < -1e-5 * nominal) s.validity = SurfaceValidity::unloading;
    }
    out.snapshots.push_back(std::move(s));
  }
  return out;
}

}  // namespace punchsweep::model
