#include "model/localization/small_spot_table.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "model/numerics/integer_power.hpp"
#include "model/numerics/root_finding.hpp"
#include "model/numerics/uniform_cubic.hpp"
#include "model/problem/shape.hpp"

namespace punchsweep::model {

double SmallSpotTable::eta_of_zeta(double zeta) const { return 1.0 - ipow(zeta, s); }
double SmallSpotTable::xi_top() const { return ipow(v_top, s + 1); }
double SmallSpotTable::xi_hand() const { return ipow(v_hand, s + 1); }
double SmallSpotTable::xi_gap_hand() const { return ipow(v_gap_hand, s + 1); }
double SmallSpotTable::xi_gap_top() const { return ipow(v_gap_top, s + 1); }
double SmallSpotTable::v_of(double xi) const { return iroot(std::max(xi, 0.0), s + 1); }

double SmallSpotTable::isolated_radius(double xi) const { return a_per_v_ * v_of(xi); }
double SmallSpotTable::isolated_depth(double xi) const { return K_d_ * ipow(isolated_radius(xi), s); }

double SmallSpotTable::gap_at(double v) const {
  return h_per_v_ * ipow(v, s) * Stencil(v_grid_.at(v), M + 1)(h_single.data());
}

double SmallSpotTable::radius_at(double v) const {
  return a_per_v_ * v * Stencil(v_grid_.at(v), M + 1)(a1_single.data());
}

double SmallSpotTable::gap_at(double v, double* slope) const {
  const GridPosition at = v_grid_.at(v);
  const Stencil stencil(at, M + 1);
  const double* p = &h_single[static_cast<std::size_t>(stencil.first)];
  const double ratio = stencil.w.apply(p[0], p[1], p[2], p[3]);
  const double ratio_slope = cubic_slope_weights(at.u + (at.i - stencil.first - 1)).apply(p[0], p[1], p[2], p[3]) / v_grid_.step;
  const double vs1 = ipow(v, s - 1);
  *slope = h_per_v_ * vs1 * (s * ratio + v * ratio_slope);
  return h_per_v_ * vs1 * v * ratio;
}

PeriodicState SmallSpotTable::single_at(double xi, double v) const {
  PeriodicState out;
  out.Q1 = xi;
  if (!(xi > 0.0)) return out;
  const Stencil at(v_grid_.at(v), M + 1);
  out.a1 = a_per_v_ * v * at(a1_single.data());
  out.h = h_per_v_ * ipow(v, s) * at(h_single.data());
  out.in_range = v <= v_top * (1.0 + 1e-12);
  return out;
}

PeriodicState SmallSpotTable::two_level_at(double xi, double v, double eta) const {
  if (!(xi > 0.0)) return {};
  return two_level_with(xi, v, eta, Stencil(v_grid_.at(v), M + 1));
}

PeriodicState SmallSpotTable::two_level_below(double xi, double v, double delta) const {
  if (!(xi > 0.0)) return {};
  const Stencil along(v_grid_.at(v), M + 1);
  const double h = h_per_v_ * ipow(v, s) * along(h_single.data());
  return two_level_with(xi, v, h > 0.0 ? delta / h : 0.0, along);
}

PeriodicState SmallSpotTable::two_level_with(double xi, double v, double eta, const Stencil& along) const {
  PeriodicState out;
  const double zeta = iroot(std::clamp(1.0 - eta, 0.0, 1.0), s);
  const Stencil across(zeta_grid_.at(zeta), Z + 1);
  // Across zeta on each of the four v samples about v, then along v.
  const Three sum = bicubic3(fields_.data(), Z + 1, along.first, along.w, across);
  const double a0 = a_per_v_ * v;
  out.a1 = a0 * sum.f0;
  out.a2 = a0 * std::clamp(sum.f1, 0.0, sum.f0);
  out.Q2 = xi * std::clamp(sum.f2, 0.0, 0.5);
  out.Q1 = xi - out.Q2;
  out.in_range = v <= v_top * (1.0 + 1e-12);
  return out;
}

PeriodicState SmallSpotTable::single(double xi) const { return single_at(xi, v_of(xi)); }
PeriodicState SmallSpotTable::two_level(double xi, double eta) const { return two_level_at(xi, v_of(xi), eta); }

std::optional<double> SmallSpotTable::touchdown(double delta) const {
  if (!(delta > 0.0)) return 0.0;
  if (delta > h_nodes_.back()) return std::nullopt;
  // h = h0(v) rho(v), h0 = h_per_v v^s: (h / h_per_v)^(1/s) = v rho^(1/s) is nearly linear in
  // v, so its chord finds the interval that holds delta and a start within about 1e-6 of
  // the root; then Newton on the curve gap_at() evaluates, h0(v) times the interval's cubic
  // of rho, one or two steps.
  const double target = iroot(delta / h_per_v_, s);
  const int i = std::clamp(static_cast<int>(std::upper_bound(root_nodes_.begin(), root_nodes_.end(), target) -
                                            root_nodes_.begin()) - 1,
                           0, M - 1);
  const IntervalCubic ratio(h_single.data(), i, M + 1);
  const double step = v_top / M;
  const double chord = root_nodes_[static_cast<std::size_t>(i) + 1] - root_nodes_[static_cast<std::size_t>(i)];
  const double start = chord > 0.0 ? std::clamp((target - root_nodes_[static_cast<std::size_t>(i)]) / chord, 0.0, 1.0) : 0.5;
  const double u = newton_in_interval(
      [&](double w, double* rate) {
        const double x = w + ratio.shift, v = step * (i + w);
        const double vs1 = ipow(v, s - 1), r = ratio.value(x);
        *rate = h_per_v_ * vs1 * (s * step * r + v * ratio.slope(x));
        return h_per_v_ * vs1 * v * r - delta;
      },
      start);
  return ipow(step * (i + u), s + 1);
}

std::pair<double, double> SmallSpotTable::isolated_two_level(int s, double eta) {
  // y2 from (1 - y2^(s+1))^(s/(s+1)) - y2^s = eta, decreasing in y2 on [0, 2^(-1/(s+1))].
  if (!(eta < 1.0)) return {1.0, 0.0};
  const double top = std::pow(0.5, 1.0 / (s + 1));
  if (!(eta > 0.0)) return {top, top};
  const auto g = [&](double y2) { return std::pow(1.0 - ipow(y2, s + 1), static_cast<double>(s) / (s + 1)) - ipow(y2, s) - eta; };
  const auto below = [&](double y2) { return g(y2) > 0.0; };
  const auto [lo, hi] = bisect_boundary(below, 0.0, top, 1e-16);
  const double y2 = 0.5 * (lo + hi);
  return {std::pow(1.0 - ipow(y2, s + 1), 1.0 / (s + 1)), y2};
}

std::vector<double> SmallSpotTable::tables() const {
  std::vector<double> out{kFormat,   double(s), v_gap_hand,     v_gap_top, v_hand, v_top, double(M), double(Z),
                          double(shells), far_field_correction};
  const auto append = [&](const std::vector<double>& values) { out.insert(out.end(), values.begin(), values.end()); };
  append(a1_single);
  append(h_single);
  append(a1);
  append(a2);
  append(q2);
  return out;
}

std::optional<SmallSpotTable> SmallSpotTable::from_tables(const std::vector<double>& numbers) {
  constexpr std::size_t kHeader = 10;
  if (numbers.size() < kHeader || numbers[0] != kFormat) return std::nullopt;
  for (const double x : numbers) {
    if (!std::isfinite(x)) return std::nullopt;
  }
  const auto whole = [](double x, double lo, double hi) { return x == std::floor(x) && x >= lo && x <= hi; };
  if (!whole(numbers[1], Shape::kMinExponent, Shape::kMaxExponent) || !whole(numbers[6], 3, 1e4) ||
      !whole(numbers[7], 3, 1e4) || !whole(numbers[8], 1, 1e4)) {
    return std::nullopt;
  }
  SmallSpotTable t;
  t.s = static_cast<int>(numbers[1]);
  t.v_gap_hand = numbers[2];
  t.v_gap_top = numbers[3];
  t.v_hand = numbers[4];
  t.v_top = numbers[5];
  t.M = static_cast<int>(numbers[6]);
  t.Z = static_cast<int>(numbers[7]);
  t.shells = static_cast<int>(numbers[8]);
  t.far_field_correction = numbers[9];
  const auto M1 = static_cast<std::size_t>(t.M + 1), Z1 = static_cast<std::size_t>(t.Z + 1);
  if (numbers.size() != kHeader + 2 * M1 + 3 * M1 * Z1 ||
      !(0.0 < t.v_gap_hand && t.v_gap_hand < t.v_gap_top && t.v_gap_top <= t.v_top && 0.0 < t.v_hand &&
        t.v_hand < t.v_top)) {
    return std::nullopt;
  }
  std::size_t at = kHeader;
  const auto take = [&](std::vector<double>& into, std::size_t count) {
    into.assign(numbers.begin() + static_cast<std::ptrdiff_t>(at), numbers.begin() + static_cast<std::ptrdiff_t>(at + count));
    at += count;
  };
  take(t.a1_single, M1);
  take(t.h_single, M1);
  take(t.a1, M1 * Z1);
  take(t.a2, M1 * Z1);
  take(t.q2, M1 * Z1);
  // The isolated punch at v = 0, exactly; ratios near one elsewhere; a gap that grows.
  if (t.a1_single[0] != 1.0 || t.h_single[0] != 1.0) return std::nullopt;
  for (std::size_t m = 0; m < Z1; ++m) {
    // Two isolated punches: y1^s - y2^s = eta, y1^(s+1) + y2^(s+1) = 1 (isolated_two_level's
    // equations, checked rather than solved again).
    const double y1 = t.a1[m], y2 = t.a2[m], eta = t.eta_of_zeta(t.sample_zeta(static_cast<int>(m)));
    if (std::abs(ipow(y1, t.s) - ipow(y2, t.s) - eta) > 1e-12 || std::abs(ipow(y1, t.s + 1) + ipow(y2, t.s + 1) - 1.0) > 1e-12 ||
        std::abs(t.q2[m] - ipow(y2, t.s + 1)) > 1e-12 || (m + 1 == Z1 && (t.q2[m] != 0.5 || t.a1[m] != t.a2[m]))) {
      return std::nullopt;
    }
  }
  for (std::size_t k = 0; k < M1 * Z1; ++k) {
    if (!(t.a1[k] > 0.0 && t.a1[k] < 2.0 && t.a2[k] >= 0.0 && t.a2[k] <= t.a1[k] && t.q2[k] >= 0.0 && t.q2[k] <= 0.5)) {
      return std::nullopt;
    }
  }
  t.finish();
  for (std::size_t k = 1; k < M1; ++k) {
    if (!(t.h_nodes_[k] > t.h_nodes_[k - 1])) return std::nullopt;
  }
  return t;
}

std::string SmallSpotTable::table_name(int s) { return "small_spot-s" + std::to_string(s); }

void SmallSpotTable::finish() {
  const Shape unit{s, 1.0};
  K_P_ = load_coefficient(unit);
  K_d_ = depth_coefficient(unit);
  a_per_v_ = std::pow(K_P_, -1.0 / (s + 1));
  h_per_v_ = K_d_ * ipow(a_per_v_, s);
  v_grid_ = UniformGrid(0.0, v_top, M + 1);
  zeta_grid_ = UniformGrid(0.0, 1.0, Z + 1);
  h_nodes_.clear();
  fields_.clear();
  if (h_single.size() != static_cast<std::size_t>(M + 1)) return;  // the builder, before the samples
  for (int k = 0; k <= M; ++k) h_nodes_.push_back(gap_at(sample_v(k)));
  root_nodes_.clear();
  for (int k = 0; k <= M; ++k) root_nodes_.push_back(sample_v(k) * iroot(h_single[k], s));
  for (std::size_t k = 0; k < a1.size(); ++k) fields_.insert(fields_.end(), {a1[k], a2[k], q2[k]});
}

}  // namespace punchsweep::model
