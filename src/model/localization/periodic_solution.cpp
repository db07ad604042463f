#include "model/localization/periodic_solution.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>

#include "model/numerics/integer_power.hpp"
#include "model/numerics/root_finding.hpp"
#include "model/problem/shape.hpp"

namespace punchsweep::model {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Samples of the band at which the constructor checks that the blended h increases.
constexpr int kBandChecks = 400;

}  // namespace

PeriodicSolution::PeriodicSolution(std::shared_ptr<const PeriodicTable> tables, std::shared_ptr<const SmallSpotTable> small)
    : tables_(std::move(tables)), small_(std::move(small)) {
  if (!tables_ || !small_) throw std::invalid_argument("the periodic solution needs both of its tables");
  if (tables_->s != small_->s) {
    throw std::invalid_argument("the periodic tables are of s = " + std::to_string(tables_->s) +
                                " and the small-spot table of s = " + std::to_string(small_->s));
  }
  v_gap_hand_ = small_->v_gap_hand;
  v_gap_top_ = small_->v_gap_top;
  v_hand_ = small_->v_hand;
  v_top_ = small_->v_top;
  xi_top_ = small_->xi_top();
  xi_gap_hand_ = small_->xi_gap_hand();
  if (!(v_top_ < tables_->v_full)) throw std::invalid_argument("the small-spot table reaches past full contact");
  // The blends of the two levels read the boundary elements' surface at delta itself, which
  // needs the gap's band below theirs (h is then the boundary elements' alone).
  if (!(v_gap_top_ <= v_hand_)) throw std::invalid_argument("the small-spot table's gap band overlaps its other band");
  h_hand_ = small_->single(small_->xi_gap_hand()).h;
  h_top_ = tables_->gap(small_->xi_gap_top());
  double previous = h_hand_;
  for (int k = 1; k <= kBandChecks; ++k) {
    const double h = single(ipow(v_gap_hand_ + (v_gap_top_ - v_gap_hand_) * k / kBandChecks, s() + 1)).h;
    if (!(h > previous)) {
      throw std::invalid_argument("the blended h of s = " + std::to_string(s()) + " does not increase in its hand-over");
    }
    previous = h;
  }
}

namespace {
/// 1 below the band [from, to], 0 above, the smooth step 1 - u^2 (3 - 2 u) within.
double step_down(double v, double from, double to) {
  if (v <= from) return 1.0;
  if (v >= to) return 0.0;
  const double u = (v - from) / (to - from);
  return 1.0 - u * u * (3.0 - 2.0 * u);
}
}  // namespace

double PeriodicSolution::small_weight(double v) const { return step_down(v, v_hand_, v_top_); }
double PeriodicSolution::small_gap_weight(double v) const { return step_down(v, v_gap_hand_, v_gap_top_); }

PeriodicState PeriodicSolution::single(double xi) const {
  if (!(xi > 0.0) || xi >= xi_top_) return tables_->single(xi);
  const double v = iroot(xi, s() + 1);
  if (v <= v_gap_hand_) return small_->single_at(xi, v);  // below both bands
  PeriodicState out;
  out.Q1 = xi;
  if (v <= v_hand_) {
    // The gap's band, and above it: h blended or the boundary elements', a1 the small spots'.
    out.h = gap(xi, v);
    out.a1 = small_->radius_at(v);
    return out;
  }
  // The radii's band (above the gap's): h the boundary elements'.
  const PeriodicState tables = tables_->single(xi);
  const double w = small_weight(v);
  out.h = tables.h;
  out.a1 = w * small_->radius_at(v) + (1.0 - w) * tables.a1;
  return out;
}

double PeriodicSolution::gap(double xi, double v) const {
  if (v <= v_gap_hand_) return small_->gap_at(v);
  const double tables = xi < xi_top_ ? tables_->gap_at(v) : tables_->gap(xi);
  if (v >= v_gap_top_) return tables;
  const double w = small_gap_weight(v);
  return w * small_->gap_at(v) + (1.0 - w) * tables;
}

double PeriodicSolution::touchdown(double delta) const {
  if (!(delta > 0.0)) return 0.0;
  if (delta >= delta_hidden()) return kInf;
  if (delta >= h_top_) return *tables_->touchdown(delta);  // v_lo = 0: found
  if (delta <= h_hand_) return *small_->touchdown(delta);
  // In the gap's band: the root of the blended h, which increases (the constructor's check),
  // by Newton with its slope from the boundary elements' own root (within about 1e-7 of it),
  // kept inside the bracket the steps find. A step below 1e-9 v leaves an error of its
  // square (Newton's quadratic convergence), below the rounding of v: the second step ends.
  double v = std::clamp(tables_->touchdown_of_gap(delta), v_gap_hand_, v_gap_top_);
  double lo = v_gap_hand_, hi = v_gap_top_;
  for (int k = 0; k < 8; ++k) {
    double slope = 0.0;
    const double value = gap_in_band(v, &slope) - delta;
    if (value == 0.0) return ipow(v, s() + 1);
    (value < 0.0 ? lo : hi) = v;
    const double next = v - value / slope;
    if (!(slope > 0.0) || !(next > lo && next < hi)) break;
    if (std::abs(next - v) <= 1e-9 * v) return ipow(next, s() + 1);
    v = next;
  }
  // Not settled: Brent's method in the bracket found.
  const auto f = [&](double w) {
    double ignored = 0.0;
    return gap_in_band(w, &ignored) - delta;
  };
  const RootResult root = brent(f, lo, hi, f(lo), f(hi), 1e-15 * v_gap_top_);
  return ipow(root.x, s() + 1);
}

double PeriodicSolution::gap_in_band(double v, double* slope) const {
  const double u = (v - v_gap_hand_) / (v_gap_top_ - v_gap_hand_);
  const double w = 1.0 - u * u * (3.0 - 2.0 * u), dw = -6.0 * u * (1.0 - u) / (v_gap_top_ - v_gap_hand_);
  double small_slope = 0.0, tables_slope = 0.0;
  const double small = small_->gap_at(v, &small_slope), tables = tables_->gap_at(v, &tables_slope);
  *slope = dw * (small - tables) + w * small_slope + (1.0 - w) * tables_slope;
  return w * small + (1.0 - w) * tables;
}

PeriodicSolution::Row PeriodicSolution::row(double delta, double xi_star) const {
  Row out;
  out.delta = delta;
  const double d = std::clamp(delta, 0.0, delta_top());
  out.xi_star = xi_star;
  out.in_range = delta >= 0.0 && delta <= delta_top() && std::isfinite(out.xi_star);
  // The boundary elements' row: their surface is read from the radii's band up, at the
  // touchdown said here (their own where it lies above the gap's band; below, theirs differs
  // by about 1e-5 of it, a shift of their r that leaves their states within 1e-6 from the
  // radii's band up, where xi - xi* exceeds xi*).
  out.table = tables_->row(d, std::isfinite(out.xi_star) ? out.xi_star : *tables_->touchdown(d));
  return out;
}

PeriodicState PeriodicSolution::two_level(double xi, const Row& row) const {
  PeriodicState out;
  out.in_range = row.in_range;
  if (!std::isfinite(row.xi_star)) return out;
  if (xi >= xi_top_) {
    out = tables_->two_level(xi, row.table);
  } else {
    const double v = iroot(std::max(xi, 0.0), s() + 1);
    // The small-spot table at eta = delta / h(xi), h the blended gap, so that it touches down
    // where that h says. Its blend with the boundary elements' surface lies above the gap's
    // band, where h is theirs: their surface is read at delta, as it is alone.
    out = v <= v_gap_hand_ ? small_->two_level_below(xi, v, row.delta)
                           : small_->two_level_at(xi, v, std::clamp(row.delta / gap(xi, v), 0.0, 1.0));
    if (v > v_hand_) {
      const double w = small_weight(v);
      const PeriodicState tables = tables_->two_level(xi, row.table);
      out.a1 = w * out.a1 + (1.0 - w) * tables.a1;
      out.a2 = w * out.a2 + (1.0 - w) * tables.a2;
      out.Q2 = w * out.Q2 + (1.0 - w) * tables.Q2;
    }
    out.in_range = row.in_range;
  }
  if (row.delta == 0.0 && std::isfinite(xi)) {
    // One height: one lattice of pitch l / sqrt(2), its two sublattices alike.
    const double a = 0.5 * (out.a1 + out.a2);
    out.a1 = out.a2 = a;
    out.Q2 = 0.5 * xi;
  }
  out.a2 = std::min(out.a2, out.a1);  // level 2 is the lower level: its spot is never the larger
  out.Q1 = xi - out.Q2;
  out.h = row.delta;
  return out;
}

bool PeriodicSolution::pressure_monotone(double xi_a, double xi_b, const Row& row) const {
  // Below the band the spots are small, each an isolated punch's under a growing load,
  // whose pressure grows at every point; the boundary elements' record from where they
  // are read.
  const double from = std::max(xi_a, xi_gap_hand_);
  return xi_b <= from || tables_->pressure_monotone(from, xi_b, row.table);
}

namespace {
std::mutex& source_mutex() {
  static std::mutex m;
  return m;
}
PeriodicSolutionSource& source() {
  static PeriodicSolutionSource f;
  return f;
}
std::map<int, std::shared_ptr<const PeriodicSolution>>& loaded() {
  static std::map<int, std::shared_ptr<const PeriodicSolution>> solutions;
  return solutions;
}
// The loaded solutions by s, read without the lock: a point looks its solution up several
// times (the touchdown, the branch, each single-level state), and the lock cost 0.1-0.2 us
// of the 1.8 us a scattered point took (issue 23). Set under the lock, after it is whole.
constexpr int kFastExponents = Shape::kMaxExponent + 1;  // s in [0, kMaxExponent]
std::array<std::atomic<const PeriodicSolution*>, kFastExponents>& ready() {
  static std::array<std::atomic<const PeriodicSolution*>, kFastExponents> solutions{};
  return solutions;
}
}  // namespace

void set_periodic_solution_source(PeriodicSolutionSource f) {
  const std::lock_guard lock(source_mutex());
  source() = std::move(f);
  for (auto& solution : ready()) solution.store(nullptr, std::memory_order_release);
  loaded().clear();
}

const PeriodicSolution& periodic_solution(int s) {
  const bool fast = s >= 0 && s < kFastExponents;
  if (fast) {
    if (const PeriodicSolution* solution = ready()[static_cast<std::size_t>(s)].load(std::memory_order_acquire)) {
      return *solution;
    }
  }
  const std::lock_guard lock(source_mutex());
  auto& entry = loaded()[s];
  if (!entry) {
    if (!source()) {
      throw std::runtime_error("the periodic model needs its tables, and this program has no source for them "
                               "(the punchsweep command and the Python module set one)");
    }
    entry = source()(s);
    if (!entry) throw std::runtime_error("no periodic tables for s = " + std::to_string(s));
  }
  if (fast) ready()[static_cast<std::size_t>(s)].store(entry.get(), std::memory_order_release);
  return *entry;
}

}  // namespace punchsweep::model
