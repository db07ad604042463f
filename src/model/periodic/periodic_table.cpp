#include "model/periodic/periodic_table.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "model/numerics/integer_power.hpp"
#include "model/numerics/uniform_cubic.hpp"

namespace punchsweep::model {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

double PeriodicTable::sample_excess(int j, int k) const {
  return std::pow(static_cast<double>(k) / (K - 1) * w_full[static_cast<std::size_t>(j)], row_power());
}

double PeriodicTable::delta_hidden() const {
  // 2^(-s/2) without pow (a point asks for it several times): sqrt(2) 2^(-(s+1)/2) for odd
  // s, the power of two by exact halvings.
  double out = s % 2 != 0 ? std::numbers::sqrt2 : 1.0;
  for (int k = 0; k < (s + 1) / 2; ++k) out *= 0.5;
  return out;
}
double PeriodicTable::xi_full_single() const { return ipow(v_full, s + 1); }

PeriodicState PeriodicTable::single(double xi) const {
  PeriodicState out;
  out.Q1 = xi;
  if (!(xi > 0.0)) return out;
  const double v = iroot(xi, s + 1);
  if (v >= v_full) {
    out.h = delta_hidden();
    out.a1 = 1.0 / std::sqrt(std::numbers::pi);
    return out;
  }
  const int count = static_cast<int>(h1.size());
  const Stencil at(v_grid_.at(std::max(v, v_lo)), count);
  out.h = at(h1.data());
  out.a1 = at(a11.data());
  return out;
}

double PeriodicTable::touchdown_v(double delta) const {
  // h increases from sample to sample: the interval that holds delta, then the root of the
  // interval's cubic (the one single() evaluates there).
  const int count = static_cast<int>(h1.size());
  // Past the last sample level 2 touches only as level 1 makes full contact.
  if (delta >= h1.back()) return v_full;
  const int i = std::clamp(static_cast<int>(std::upper_bound(h1.begin(), h1.end(), delta) - h1.begin()) - 1, 0,
                           count - 2);
  const IntervalCubic cubic(h1.data(), i, count, delta);
  // Newton from the chord's root.
  const double chord = h1[static_cast<std::size_t>(i) + 1] - h1[static_cast<std::size_t>(i)];
  const double start = chord > 0.0 ? std::clamp((delta - h1[static_cast<std::size_t>(i)]) / chord, 0.0, 1.0) : 0.5;
  const double u = newton_in_interval(
      [&](double w, double* rate) {
        *rate = cubic.slope(w + cubic.shift);
        return cubic.value(w + cubic.shift);
      },
      start);
  return v_lo + (v_full - v_lo) * (i + u) / (count - 1);
}

std::optional<double> PeriodicTable::touchdown(double delta) const {
  if (delta <= 0.0) return 0.0;
  if (delta >= delta_hidden()) return kInf;
  if (delta < h1.front()) return std::nullopt;
  return ipow(touchdown_v(delta), s + 1);
}

PeriodicTable::Row PeriodicTable::row(double delta) const {
  const std::optional<double> star = touchdown(std::clamp(delta, 0.0, delta_top));
  return row(delta, star ? *star : kInf);
}

PeriodicTable::Row PeriodicTable::row(double delta, double xi_star) const {
  Row out;
  out.delta = delta;
  out.in_range = delta >= 0.0 && delta <= delta_top;
  const double d = std::clamp(delta, 0.0, delta_top);
  out.xi_star = xi_star;
  if (!std::isfinite(out.xi_star)) out.in_range = false;
  const GridPosition dj = delta_grid_.at(d);
  out.interval = dj.i;
  out.offset = dj.u;
  const Stencil across(dj, J);
  out.w_full = across(w_full.data());
  out.share2 = across(share2.data());
  return out;
}

PeriodicState PeriodicTable::two_level(double xi, const Row& row) const {
  PeriodicState out;
  out.in_range = row.in_range;
  if (!std::isfinite(row.xi_star)) return out;
  const double excess = std::max(xi - row.xi_star, 0.0);
  const double r = iroot(excess, row_power()) / row.w_full;
  // The bicubic: in r along each of the four rows about delta, then across them.
  const Stencil along(r_grid_.at(std::min(r, 1.0)), K);
  const int first = std::clamp(row.interval - 1, 0, J - 4);  // J >= 4 (from_tables)
  const Stencil across(GridPosition{row.interval - first, row.offset}, 4);
  const Three at = bicubic3(fields_.data(), K, first, across.w, along);
  out.a1 = at.f0;
  out.a2 = std::max(at.f1, 0.0);
  // Level 2's load is never negative; the samples' grid may leave the cubic a little below
  // zero just after touchdown, where a coarse sample sees the tip node alone.
  const double rate = std::max(at.f2, 0.0);
  if (r > 1.0) {
    // Full contact: the areas stay, the extra load spreads evenly over the cell.
    const double excess_full = ipow(row.w_full, row_power());
    out.Q2 = rate * excess_full + row.share2 * (excess - excess_full);
  } else {
    out.Q2 = rate * excess;
  }
  out.Q1 = xi - out.Q2;
  out.h = row.delta;
  return out;
}

bool PeriodicTable::pressure_monotone(double xi_a, double xi_b, const Row& row) const {
  if (all_monotone_ || xi_b <= xi_a) return true;
  if (std::isfinite(row.xi_star) && xi_b > row.xi_star) {
    const auto index = [&](double xi) {
      const double r = iroot(std::max(xi - row.xi_star, 0.0), row_power()) / row.w_full;
      return std::min(static_cast<int>(std::floor(r * (K - 1))), K - 1);  // K - 1: beyond the rows' end
    };
    const int lo = index(std::max(xi_a, row.xi_star)), hi = index(xi_b);
    for (const int j : {row.interval, row.interval + 1}) {
      for (int k = lo; k <= hi && k < K - 1; ++k) {
        if (!monotone2[static_cast<std::size_t>(j) * (K - 1) + k]) return false;
      }
    }
    xi_b = row.xi_star;
  }
  if (xi_b <= xi_a) return true;
  const int count = static_cast<int>(h1.size());
  const auto index = [&](double xi) {
    const double v = iroot(xi, s + 1);
    if (v >= v_full) return count - 1;
    return v_grid_.at(std::max(v, v_lo)).i;
  };
  for (int k = index(std::max(xi_a, 1e-300)); k <= index(xi_b) && k < count - 1; ++k) {
    if (!monotone1[static_cast<std::size_t>(k)]) return false;
  }
  return true;
}

void PeriodicTable::set_grids() {
  v_grid_ = UniformGrid(v_lo, v_full, static_cast<int>(h1.size()));
  delta_grid_ = UniformGrid(0.0, delta_top, J);
  r_grid_ = UniformGrid(0.0, 1.0, K);
}

void PeriodicTable::finish() {
  const auto all = [](const std::vector<std::uint8_t>& v) {
    return std::all_of(v.begin(), v.end(), [](std::uint8_t m) { return m != 0; });
  };
  all_monotone_ = all(monotone1) && all(monotone2);
  set_grids();
  q2_rate_.assign(Q2.size(), 0.0);
  for (int j = 0; j < J; ++j) {
    double* rate = &q2_rate_[static_cast<std::size_t>(j) * K];
    const double* load = &Q2[static_cast<std::size_t>(j) * K];
    // ipow, not sample_excess()'s pow: the two differ in the last bit, and the maps made so
    // far divided by this one.
    for (int k = 1; k < K; ++k) rate[k] = load[k] / ipow(w_full[j] * k / (K - 1), row_power());
    rate[0] = 3.0 * rate[1] - 3.0 * rate[2] + rate[3];  // the parabola through k = 1, 2, 3 at 0
  }
  fields_.clear();
  for (std::size_t k = 0; k < a1.size(); ++k) fields_.insert(fields_.end(), {a1[k], a2[k], q2_rate_[k]});
}

std::vector<double> PeriodicTable::tables() const {
  std::vector<double> out{kFormat, double(s), double(n), v_lo, v_full, double(h1.size()), delta_top, double(J), double(K)};
  const auto append = [&](const auto& values) { out.insert(out.end(), values.begin(), values.end()); };
  append(h1);
  append(a11);
  append(monotone1);
  append(xi_star);
  append(w_full);
  append(share2);
  append(a1);
  append(a2);
  append(Q2);
  append(monotone2);
  return out;
}

std::optional<PeriodicTable> PeriodicTable::from_tables(const std::vector<double>& numbers) {
  constexpr std::size_t kHeader = 9;
  if (numbers.size() < kHeader || numbers[0] != kFormat) return std::nullopt;
  for (const double x : numbers) {
    if (!std::isfinite(x)) return std::nullopt;
  }
  PeriodicTable t;
  const auto whole = [](double x, double lo, double hi) { return x == std::floor(x) && x >= lo && x <= hi; };
  if (!whole(numbers[1], 1, 32) || !whole(numbers[2], 4, 1 << 16) || !whole(numbers[5], 4, 1e6) ||
      !whole(numbers[7], 4, 1e4) || !whole(numbers[8], 4, 1e4)) {
    return std::nullopt;
  }
  t.s = static_cast<int>(numbers[1]);
  t.n = static_cast<int>(numbers[2]);
  t.v_lo = numbers[3];
  t.v_full = numbers[4];
  const auto K1 = static_cast<std::size_t>(numbers[5]);
  t.delta_top = numbers[6];
  t.J = static_cast<int>(numbers[7]);
  t.K = static_cast<int>(numbers[8]);
  const auto J = static_cast<std::size_t>(t.J), K = static_cast<std::size_t>(t.K);
  const std::size_t expected = kHeader + 3 * K1 - 1 + 3 * J + 3 * J * K + J * (K - 1);
  if (numbers.size() != expected || !(0.0 <= t.v_lo && t.v_lo < t.v_full) || !(t.delta_top > 0.0) ||
      t.delta_top >= t.delta_hidden()) {
    return std::nullopt;
  }
  std::size_t at = kHeader;
  const auto take = [&](auto& into, std::size_t count) {
    into.assign(numbers.begin() + static_cast<std::ptrdiff_t>(at), numbers.begin() + static_cast<std::ptrdiff_t>(at + count));
    at += count;
  };
  take(t.h1, K1);
  take(t.a11, K1);
  take(t.monotone1, K1 - 1);
  take(t.xi_star, J);
  take(t.w_full, J);
  take(t.share2, J);
  take(t.a1, J * K);
  take(t.a2, J * K);
  take(t.Q2, J * K);
  take(t.monotone2, J * (K - 1));
  t.finish();
  // The curves' shapes: h increases from h(v_lo) > 0, the radii are within the cell.
  for (std::size_t k = 1; k < K1; ++k) {
    if (!(t.h1[k] > t.h1[k - 1])) return std::nullopt;
  }
  if (t.h1.front() < 0.0 || t.h1.back() > t.delta_hidden()) return std::nullopt;
  for (std::size_t k = 0; k < J * K; ++k) {
    if (!(t.a1[k] >= 0.0 && t.a1[k] <= 1.0 && t.a2[k] >= 0.0 && t.a2[k] <= 1.0)) return std::nullopt;
  }
  // The rows' bookkeeping follows from the single level: each row starts at its touchdown
  // and all end at one load, in full contact (the areas are the levels' shares there).
  const double cap = t.xi_star[0] + ipow(t.w_full[0], t.row_power());
  for (int j = 0; j < t.J; ++j) {
    const std::optional<double> star = t.touchdown(t.sample_delta(j));
    const std::size_t end = static_cast<std::size_t>(j) * K + K - 1;
    if (!star || std::abs(*star - t.xi_star[j]) > 1e-12 * (1.0 + *star) ||
        std::abs(t.xi_star[j] + ipow(t.w_full[j], t.row_power()) - cap) > 1e-9 * cap ||
        !(t.share2[j] >= 0.0 && t.share2[j] <= 0.5) ||
        std::abs(t.a2[end] - std::sqrt(t.share2[j] / std::numbers::pi)) > 1e-9 ||
        std::abs(t.a1[end] - std::sqrt((1.0 - t.share2[j]) / std::numbers::pi)) > 1e-9) {
      return std::nullopt;
    }
  }
  return t;
}

std::string PeriodicTable::table_name(int s, int n) {
  return "periodic-s" + std::to_string(s) + "-n" + std::to_string(n);
}

}  // namespace punchsweep::model
