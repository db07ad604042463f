#include "model/surface/load_curve.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace punchsweep::model {

namespace {

/// Count of entries of `touchdown` (restricted to `level`, or all for level < 0) at or
/// below X, over their number.
double touched_share(const LoadCurve& c, double X, int level) {
  double touched = 0.0, all = 0.0;
  for (std::size_t k = 0; k < c.sites(); ++k) {
    if (level >= 0 && c.site_level[k] != level) continue;
    all += 1.0;
    if (c.site_touchdown[k] <= X) touched += 1.0;
  }
  return all > 0.0 ? touched / all : 0.0;
}

}  // namespace

CurveState LoadCurve::at(double X) const {
  CurveState out;
  out.X = X;
  const std::size_t L = static_cast<std::size_t>(levels());
  out.level_load.assign(L, 0.0);
  out.level_area.assign(L, 0.0);
  if (X <= 0.0) {
    out.range = CurveRange::below_resolution;
    return out;
  }
  if (X >= X_full) {
    out.range = CurveRange::full_contact;
    const LoadCurveSample& last = samples.back();
    for (std::size_t level = 0; level < L; ++level) {
      out.level_area[level] = level_share[level] * cell_area;
      out.level_load[level] = last.level_load[level] + (X - last.X) * level_share[level] * cell_area;
    }
  } else if (X > X_last()) {
    out.range = CurveRange::above_top;
    return out;
  } else if (X < X_first()) {
    out.range = CurveRange::below_resolution;
    const LoadCurveSample& first = samples.front();
    const double area_scale = std::pow(X / first.X, 2.0 / (s_tallest + 1.0));
    for (std::size_t level = 0; level < L; ++level) {
      out.level_load[level] = first.level_load[level] * (X / first.X);
      out.level_area[level] = first.level_area[level] * area_scale;
    }
  } else {
    out.range = CurveRange::sampled;
    const auto after = std::upper_bound(samples.begin(), samples.end(), X,
                                        [](double x, const LoadCurveSample& s) { return x < s.X; });
    const LoadCurveSample& b = after == samples.end() ? samples.back() : *after;
    const LoadCurveSample& a = after == samples.end() ? samples.back() : *(after - 1);
    const double w = b.X > a.X ? std::log(X / a.X) / std::log(b.X / a.X) : 0.0;
    const double w_linear = b.X > a.X ? (X - a.X) / (b.X - a.X) : 0.0;
    for (std::size_t level = 0; level < L; ++level) {
      const double qa = a.level_load[level] / a.X, qb = b.level_load[level] / b.X;
      out.level_load[level] = X * (qa + w * (qb - qa));
      const double Aa = a.level_area[level], Ab = b.level_area[level];
      // From a level's touchdown its new spots grow as X - X* (their depth does, and a^2
      // with it): linearly in X over the interval that starts there.
      const bool starts_at_touchdown = level < level_touchdown.size() && a.X <= level_touchdown[level];
      out.level_area[level] =
          Aa > 0.0 && Ab > 0.0 && !starts_at_touchdown ? Aa * std::pow(Ab / Aa, w) : Aa + w_linear * (Ab - Aa);
      // Before its touchdown a level has no contact (the interval up to its touchdown's
      // sample would otherwise lend it some of the sample's first rim).
      if (level < level_touchdown.size() && X < level_touchdown[level]) out.level_area[level] = 0.0;
    }
  }
  double area = 0.0;
  for (double a : out.level_area) area += a;
  out.area_fraction = area / cell_area;
  out.sites_touched = touched_share(*this, X, -1);
  out.level_sites_touched.resize(L);
  for (std::size_t level = 0; level < L; ++level) out.level_sites_touched[level] = touched_share(*this, X, static_cast<int>(level));
  return out;
}

bool LoadCurve::monotone_between(double X_a, double X_b) const {
  for (std::size_t k = 0; k + 1 < samples.size(); ++k) {
    if (samples[k + 1].X <= X_a || samples[k].X >= X_b) continue;
    if (!pressure_monotone[k]) return false;
  }
  return true;
}

std::string load_curve_error(const LoadCurve& c) {
  std::ostringstream out;
  const std::size_t L = c.level_touchdown.size();
  if (c.samples.empty()) return "the load curve has no samples";
  if (L == 0 || c.level_share.size() != L) return "the load curve's levels do not match";
  if (c.site_touchdown.size() != c.site_level.size() || c.site_level.empty()) return "the load curve's sites do not match";
  if (c.pressure_monotone.size() + 1 != c.samples.size()) return "the load curve's monotonicity record does not match its samples";
  if (!(c.cell_area > 0.0 && std::isfinite(c.cell_area)) || c.nx < 1 || c.ny < 1) return "the load curve's cell is not valid";
  for (int level : c.site_level) {
    if (level < 0 || static_cast<std::size_t>(level) >= L) return "a site's level is outside the curve's levels";
  }
  double previous = 0.0;
  for (std::size_t k = 0; k < c.samples.size(); ++k) {
    const LoadCurveSample& s = c.samples[k];
    if (!(s.X > previous && std::isfinite(s.X))) {
      out << "sample " << k << ": X = " << s.X << " does not increase";
      return out.str();
    }
    previous = s.X;
    if (s.level_load.size() != L || s.level_area.size() != L) {
      out << "sample " << k << " has not one load and one area per level";
      return out.str();
    }
    for (std::size_t level = 0; level < L; ++level) {
      if (!std::isfinite(s.level_load[level]) || !(s.level_area[level] >= 0.0 && std::isfinite(s.level_area[level]))) {
        out << "sample " << k << ": level " << level << "'s load or area is not finite";
        return out.str();
      }
    }
  }
  return {};
}

}  // namespace punchsweep::model
