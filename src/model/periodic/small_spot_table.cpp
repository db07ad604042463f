#include "model/periodic/small_spot_table.hpp"

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

double SmallSpotTable::isolated_radius(double xi) const { return curve_.a_per_v() * v_of(xi); }
double SmallSpotTable::isolated_depth(double xi) const { return curve_.h_per_v() * ipow(v_of(xi), s); }

PeriodicState SmallSpotTable::single_at(double xi, double v) const {
  PeriodicState out = curve_.at(xi, v);
  out.in_range = v <= v_top * (1.0 + 1e-12);
  return out;
}

PeriodicState SmallSpotTable::two_level_at(double xi, double v, double eta) const {
  if (!(xi > 0.0)) return {};
  return two_level_with(xi, v, eta, curve_.stencil(v));
}

PeriodicState SmallSpotTable::two_level_with(double xi, double v, double eta, const Stencil& along) const {
  PeriodicState out;
  if (!(xi > 0.0)) return out;
  const double zeta = iroot(std::clamp(1.0 - eta, 0.0, 1.0), s);
  const Stencil across(zeta_grid_.at(zeta), Z + 1);
  // Across zeta on each of the four v samples about v, then along v.
  const Three sum = bicubic3(fields_.data(), Z + 1, along.first, along.w, across);
  const double a0 = curve_.a_per_v() * v;
  out.a1 = a0 * sum.f0;
  out.a2 = a0 * std::clamp(sum.f1, 0.0, sum.f0);
  out.Q2 = xi * std::clamp(sum.f2, 0.0, 0.5);
  out.Q1 = xi - out.Q2;
  out.in_range = v <= v_top * (1.0 + 1e-12);
  return out;
}

PeriodicState SmallSpotTable::single(double xi) const { return single_at(xi, v_of(xi)); }
PeriodicState SmallSpotTable::two_level(double xi, double eta) const { return two_level_at(xi, v_of(xi), eta); }
std::optional<double> SmallSpotTable::touchdown(double delta) const { return curve_.touchdown(delta); }

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
  const std::vector<double>& h = t.curve_.h_samples();
  for (std::size_t k = 1; k < M1; ++k) {
    if (!(h[k] > h[k - 1])) return std::nullopt;
  }
  return t;
}

std::string SmallSpotTable::table_name(int s) { return "small_spot-s" + std::to_string(s); }

void SmallSpotTable::finish() {
  const Shape unit{s, 1.0};
  K_P_ = load_coefficient(unit);
  K_d_ = depth_coefficient(unit);
  zeta_grid_ = UniformGrid(0.0, 1.0, Z + 1);
  fields_.clear();
  // The single level's samples: the builder reads the isolated punch's scales before it has
  // them (ratios of one).
  const bool sampled = h_single.size() == static_cast<std::size_t>(M + 1);
  curve_ = RatioCurve(s, v_top, sampled ? a1_single : std::vector<double>(static_cast<std::size_t>(M + 1), 1.0),
                      sampled ? h_single : std::vector<double>(static_cast<std::size_t>(M + 1), 1.0));
  if (!sampled) return;
  for (std::size_t k = 0; k < a1.size(); ++k) fields_.insert(fields_.end(), {a1[k], a2[k], q2[k]});
}

}  // namespace punchsweep::model
