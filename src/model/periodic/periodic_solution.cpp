#include "model/periodic/periodic_solution.hpp"

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
/// Samples of the solution's curve past the small-spot table's last.
constexpr int kPast = 2;

/// 1 below the band [from, to], 0 above, the smooth step 1 - u^2 (3 - 2 u) within.
double step_down(double v, double from, double to) {
  if (v <= from) return 1.0;
  if (v >= to) return 0.0;
  const double u = (v - from) / (to - from);
  return 1.0 - u * u * (3.0 - 2.0 * u);
}

}  // namespace

PeriodicSolution::PeriodicSolution(std::shared_ptr<const PeriodicTable> tables, std::shared_ptr<const SmallSpotTable> small)
    : tables_(std::move(tables)), small_(std::move(small)) {
  if (!tables_ || !small_) throw std::invalid_argument("the periodic solution needs both of its tables");
  if (tables_->s != small_->s) {
    throw std::invalid_argument("the periodic tables are of s = " + std::to_string(tables_->s) +
                                " and the small-spot table of s = " + std::to_string(small_->s));
  }
  const SmallSpotTable& t = *small_;
  v_hand_ = t.v_hand;
  v_top_ = t.v_top;
  xi_top_ = t.xi_top();
  xi_gap_hand_ = t.xi_gap_hand();
  if (!(v_top_ < tables_->v_full)) throw std::invalid_argument("the small-spot table reaches past full contact");
  // The blends of the two levels read the boundary elements' surface at delta itself, which
  // needs the gap's band below theirs (h is then the boundary elements' alone).
  if (!(t.v_gap_top <= v_hand_)) throw std::invalid_argument("the small-spot table's gap band overlaps its other band");
  // The single level below v_top: at the small-spot table's samples (and two more past v_top,
  // so that the cubic there is centred as the boundary elements' is), the small spots' ratios
  // below the bands, the blends within, the boundary elements' above; read by the same cubic
  // as the small-spot table's own (equal to it wherever its four samples lie below the gap's
  // band), and equal to the boundary elements' curve at v_top.
  const RatioCurve& own = t.curve();
  std::vector<double> a1(own.a1_ratio()), h(own.h_ratio());
  const double step = own.grid().step;
  const int sampled = static_cast<int>(h.size());
  a1.resize(static_cast<std::size_t>(sampled + kPast), 0.0);
  h.resize(static_cast<std::size_t>(sampled + kPast), 0.0);
  for (int k = 1; k < sampled + kPast; ++k) {
    const double v = k < sampled ? t.sample_v(k) : step * k;
    const double w_gap = step_down(v, t.v_gap_hand, t.v_gap_top), w = step_down(v, v_hand_, v_top_);
    if (w_gap == 1.0 && w == 1.0) continue;
    const PeriodicState tables = tables_->single(ipow(v, s() + 1));
    h[k] = w_gap * h[k] + (1.0 - w_gap) * tables.h / (own.h_per_v() * ipow(v, s()));
    a1[k] = w * a1[k] + (1.0 - w) * tables.a1 / (own.a_per_v() * v);
  }
  if (!(step * (static_cast<double>(h.size()) - 1.0) < tables_->v_full)) {
    throw std::invalid_argument("the small-spot table reaches past full contact");
  }
  const int count = static_cast<int>(h.size());
  curve_ = RatioCurve(s(), step * (count - 1), std::move(a1), std::move(h));
  const std::vector<double>& samples = curve_.h_samples();
  for (std::size_t k = 1; k < samples.size(); ++k) {
    if (!(samples[k] > samples[k - 1])) {
      throw std::invalid_argument("the blended h of s = " + std::to_string(s()) + " does not increase in its hand-over");
    }
  }
  h_top_ = curve_.gap(v_top_);
}

double PeriodicSolution::small_weight(double v) const { return step_down(v, v_hand_, v_top_); }

PeriodicState PeriodicSolution::single(double xi) const {
  if (!(xi > 0.0) || xi >= xi_top_) return tables_->single(xi);
  return curve_.at(xi, iroot(xi, s() + 1));
}

double PeriodicSolution::touchdown(double delta) const {
  if (!(delta > 0.0)) return 0.0;
  if (delta >= delta_hidden()) return kInf;
  if (delta < h_top_) return *curve_.touchdown(delta);
  return *tables_->touchdown(delta);  // v_lo = 0: found; at or above v_top (h_top_ is theirs there)
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
    // The small-spot table at eta = delta / h(xi), h the solution's own gap (one placing of v
    // serves both: the solution's curve has the small-spot table's samples), so that it
    // touches down where that h says. Its blend with the boundary elements' surface lies
    // above the gap's band, where h is the boundary elements' own: their surface is read at
    // delta, from the touchdown said here (row()).
    const GridPosition at = curve_.grid().at(v);  // the same grid, kPast samples longer
    const Stencil on_curve(at, curve_.grid().count);
    // The small-spot table's stencil: the same nodes and weights but in its last intervals.
    const int small_count = small_->curve().grid().count;
    const Stencil on_small = on_curve.first <= small_count - 4 ? on_curve : Stencil(at, small_count);
    const double h = curve_.gap(v, on_curve);
    out = small_->two_level_with(xi, v, h > 0.0 ? std::clamp(row.delta / h, 0.0, 1.0) : 0.0, on_small);
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
