#include "model/surface/load_curve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
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
  out.level_sites_touched.assign(L, 0.0);  // where it returns early (no load, past the top) as sites_touched
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
    // A level that touches between X and the first sample has no contact yet at X: no area,
    // and its share of the load is the tallest level's (the loads still sum to X Lx Ly).
    for (std::size_t level = 1; level < L && level < level_touchdown.size(); ++level) {
      if (X >= level_touchdown[level]) continue;
      out.level_area[level] = 0.0;
      out.level_load[0] += out.level_load[level];
      out.level_load[level] = 0.0;
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

LoadCurve LoadCurve::up_to(double X_end) const {
  LoadCurve out = *this;
  const auto past = std::upper_bound(out.samples.begin(), out.samples.end(), X_end,
                                     [](double x, const LoadCurveSample& s) { return x < s.X; });
  out.samples.erase(past == out.samples.begin() ? past + 1 : past, out.samples.end());
  out.pressure_monotone.resize(out.samples.size() - 1);
  if (X_full > out.X_last()) out.X_full = std::numeric_limits<double>::infinity();
  for (double& X : out.site_touchdown) X = X > out.X_last() ? std::numeric_limits<double>::infinity() : X;
  out.level_touchdown = out.least_site_touchdowns(levels());
  out.level_small_spot.clear();
  out.site_small_spot.clear();
  out.X_small_spot = 0.0;
  return out;
}

std::vector<double> LoadCurve::least_site_touchdowns(int levels) const {
  std::vector<double> least(static_cast<std::size_t>(levels), std::numeric_limits<double>::infinity());
  for (std::size_t k = 0; k < sites(); ++k) {
    double& level = least[static_cast<std::size_t>(site_level[k])];
    level = std::min(level, site_touchdown[k]);
  }
  return least;
}

std::vector<double> LoadCurve::tables() const {
  std::vector<double> out{kFormat, cell_area, static_cast<double>(nx), static_cast<double>(ny),
                          static_cast<double>(levels()), static_cast<double>(sites()), static_cast<double>(s_tallest),
                          X_full, static_cast<double>(samples.size()), X_resolved};
  for (int level : site_level) out.push_back(level);
  out.insert(out.end(), site_touchdown.begin(), site_touchdown.end());
  out.insert(out.end(), level_touchdown.begin(), level_touchdown.end());
  out.insert(out.end(), level_share.begin(), level_share.end());
  for (char grew : pressure_monotone) out.push_back(grew ? 1.0 : 0.0);
  for (const LoadCurveSample& sample : samples) {
    out.push_back(sample.X);
    out.insert(out.end(), sample.level_load.begin(), sample.level_load.end());
    out.insert(out.end(), sample.level_area.begin(), sample.level_area.end());
  }
  return out;
}

std::optional<LoadCurve> LoadCurve::from_tables(const std::vector<double>& numbers) {
  constexpr std::size_t kHeader = 10;
  if (numbers.size() < kHeader || numbers[0] != kFormat) return std::nullopt;
  const auto count = [](double v) { return v >= 0.0 && v < 1e9 && v == std::floor(v) ? static_cast<std::size_t>(v) : std::size_t{0}; };
  const std::size_t L = count(numbers[4]), S = count(numbers[5]), N = count(numbers[8]);
  if (L == 0 || S == 0 || N == 0 || numbers.size() != kHeader + 2 * S + 2 * L + (N - 1) + N * (1 + 2 * L)) return std::nullopt;
  LoadCurve c;
  c.cell_area = numbers[1];
  c.nx = static_cast<int>(count(numbers[2]));
  c.ny = static_cast<int>(count(numbers[3]));
  c.s_tallest = static_cast<int>(count(numbers[6]));
  c.X_full = numbers[7];
  c.X_resolved = numbers[9];
  std::size_t k = kHeader;
  const auto take = [&](std::size_t n) {
    std::vector<double> part(numbers.begin() + static_cast<std::ptrdiff_t>(k), numbers.begin() + static_cast<std::ptrdiff_t>(k + n));
    k += n;
    return part;
  };
  for (double level : take(S)) c.site_level.push_back(static_cast<int>(count(level)));
  c.site_touchdown = take(S);
  c.level_touchdown = take(L);
  c.level_share = take(L);
  for (double grew : take(N - 1)) c.pressure_monotone.push_back(grew != 0.0 ? 1 : 0);
  for (std::size_t n = 0; n < N; ++n) {
    LoadCurveSample sample;
    sample.X = take(1)[0];
    sample.level_load = take(L);
    sample.level_area = take(L);
    c.samples.push_back(std::move(sample));
  }
  if (!load_curve_error(c).empty()) return std::nullopt;
  return c;
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
