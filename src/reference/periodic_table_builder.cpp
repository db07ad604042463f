#include "reference/periodic_table_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "reference/periodic_grid.hpp"
#include "reference/reference_point.hpp"

namespace punchsweep::reference {
namespace {

/// The two-level rows end at this multiple of the single level's full-contact load.
constexpr double kCapShare = 1.05;

/// One cell's solves along increasing loads, each from the last one's pressure.
class Path {
 public:
  Path(int s, double delta, int n, const PeriodicTableOptions& options, int* done, int planned)
      : cell_(scaled_cell(s, delta, n)),
        solver_(cell_.grid, options.solver),
        p_(cell_.grid.size(), 0.0),
        u_(cell_.grid.size(), 0.0),
        options_(options),
        done_(done),
        planned_(planned) {}

  /// The state at load xi (from the last pressure; `keep` false leaves it as it was).
  ReferenceSnapshot solve(double xi, bool keep = true) {
    std::vector<double> p, u;
    solve_fields(xi, &p, &u);
    const ReferenceSnapshot state = measure_state(cell_, p, p, u, 0.0);
    if (keep) {
      monotone_ = true;
      double top = 0.0;
      for (const double x : p) top = std::max(top, x);
      for (std::size_t k = 0; k < p.size(); ++k) {
        if (p[k] < p_[k] - 1e-9 * top) monotone_ = false;
      }
      p_ = std::move(p);
      u_ = std::move(u);
    }
    last_full_ = std::all_of(p_.begin(), p_.end(), [](double x) { return x > 0.0; });
    return state;
  }
  /// Whether every node is in contact at load xi (the last pressure is kept as it was).
  bool full(double xi) {
    std::vector<double> p, u;
    solve_fields(xi, &p, &u);
    return std::all_of(p.begin(), p.end(), [](double x) { return x > 0.0; });
  }
  /// Whether no node's pressure fell in the last kept solve.
  bool monotone() const { return monotone_; }
  /// Whether every node is in contact in the last kept solve.
  bool last_full() const { return last_full_; }
  /// The level-2 share of the cell's area.
  double share2() const { return level2_share(cell_); }
  void reset() { std::fill(p_.begin(), p_.end(), 0.0); }

 private:
  /// The pressure and displacement at load xi, from the last kept pressure: a start from a
  /// contact of a node or two can stall the iteration (small loads on a coarse grid), so
  /// once more from the uniform pressure before giving up.
  void solve_fields(double xi, std::vector<double>* p, std::vector<double>* u) {
    options_.stop.throw_if_requested();
    *p = p_;
    u->assign(u_.size(), 0.0);
    ContactStatus status = solver_.solve(cell_.profile, xi, 1.0, *p, *u);
    if (!status.converged) {
      std::fill(p->begin(), p->end(), 0.0);
      status = solver_.solve(cell_.profile, xi, 1.0, *p, *u);
    }
    if (!status.converged) {
      throw std::runtime_error("a contact solve of the periodic tables missed its tolerance at xi = " +
                               std::to_string(xi) + " (residual " + std::to_string(status.residual) + ")");
    }
    ++*done_;
    if (options_.progress) options_.progress(*done_, planned_);
  }

  TwoLevelCell cell_;
  ContactSolver solver_;
  std::vector<double> p_, u_;
  const PeriodicTableOptions& options_;
  int* done_;
  int planned_;
  bool monotone_ = true;
  bool last_full_ = false;
};

/// The smallest load at which every node is in contact, to a relative 1e-6, above `from`
/// (not in full contact).
double full_contact_load(Path& path, double from) {
  double lo = from, hi = std::max(2.0 * from, 0.05);
  while (!path.full(hi)) {
    lo = hi;
    hi *= 2.0;
    if (hi > 1e6) throw std::runtime_error("the periodic tables found no full contact below xi = 1e6");
  }
  while (hi - lo > 1e-6 * hi) {
    const double mid = 0.5 * (lo + hi);
    (path.full(mid) ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace

TwoLevelCell scaled_cell(int s, double delta, int n) {
  model::ContactProblem problem;
  problem.l = 1.0;
  problem.dh = delta;
  problem.pbar0 = 1.0;
  problem.shape = model::Shape{s, 1.0};
  return make_two_level_cell(problem, n, Symmetry::mirror);
}

model::PeriodicState solve_scaled(int s, double xi, double delta, int n, const ContactSolverOptions& solver) {
  const TwoLevelCell cell = scaled_cell(s, std::isfinite(delta) ? delta : 2.0, n);
  ContactSolver contact(cell.grid, solver);
  std::vector<double> p(cell.grid.size(), 0.0), u(cell.grid.size());
  contact.solve(cell.profile, xi, 1.0, p, u);
  const ReferenceSnapshot state = measure_state(cell, p, p, u, 0.0);
  return {state.h, state.a1, state.a2, state.P1, state.P2, true};
}

model::PeriodicTable build_periodic_table(int s, const PeriodicTableOptions& options) {
  if (s < model::Shape::kMinExponent || s > model::Shape::kMaxExponent) {
    throw std::invalid_argument("s = " + std::to_string(s) + " is outside 1 .. 32");
  }
  model::PeriodicTable t;
  t.s = s;
  t.n = options.n;
  t.J = options.deltas;
  t.K = options.r_samples;
  const int K1 = options.single_samples;
  // Planned: ~24 bisection solves for each full contact, then the samples.
  const int planned = 24 + K1 + t.J * t.K;
  int done = 0;

  // The single level: full contact, then the samples from the unloaded state.
  Path single(s, 2.0, options.n, options, &done, planned);
  const double xi_full = full_contact_load(single, 0.0);
  single.reset();
  t.v_lo = 0.0;
  t.v_full = std::pow(xi_full, 1.0 / (s + 1));
  t.h1.assign(K1, 0.0);
  t.a11.assign(K1, 0.0);
  t.monotone1.assign(K1 - 1, 1);
  for (int k = 1; k < K1; ++k) {
    const double v = t.sample_v(k);
    const ReferenceSnapshot state = single.solve(std::pow(v, s + 1));
    t.h1[k] = k == K1 - 1 ? t.delta_hidden() : state.h;
    t.a11[k] = k == K1 - 1 ? 1.0 / std::sqrt(std::numbers::pi) : state.a1;
    t.monotone1[k - 1] = single.monotone();
  }

  // The two levels, one delta at a time.
  t.delta_top = options.delta_top_share * t.delta_hidden();
  const double cap = kCapShare * xi_full;
  t.xi_star.assign(t.J, 0.0);
  t.w_full.assign(t.J, 0.0);
  t.share2.assign(t.J, 0.0);
  const std::size_t JK = static_cast<std::size_t>(t.J) * t.K;
  t.a1.assign(JK, 0.0);
  t.a2.assign(JK, 0.0);
  t.Q2.assign(JK, 0.0);
  t.monotone2.assign(static_cast<std::size_t>(t.J) * (t.K - 1), 1);
  t.set_grids();
  for (int j = 0; j < t.J; ++j) {
    const double delta = t.sample_delta(j);
    const double star = *t.touchdown(delta);
    t.xi_star[j] = star;
    Path path(s, delta, options.n, options, &done, planned);
    t.share2[j] = path.share2();
    // Every row runs to the same load, past the single level's full contact (the two levels
    // fill the cell sooner). The load at which a row's last node closes jumps by a few
    // percent from one delta to the next (which node is last is a matter of the grid), so
    // rows normalised by their own full contact do not line up across delta (measured:
    // twice the error of this common end).
    const double w_full = std::pow(cap - star, 1.0 / t.row_power());
    t.w_full[j] = w_full;
    const std::size_t row = static_cast<std::size_t>(j) * t.K;
    // r = 0: the touchdown, the single-level state (a2 = 0, Q2 = 0).
    t.a1[row] = t.single(star).a1;
    if (star > 0.0) path.solve(star);  // the pressure to start from
    for (int k = 1; k < t.K; ++k) {
      const ReferenceSnapshot state = path.solve(star + t.sample_excess(j, k));
      t.a1[row + k] = state.a1;
      t.a2[row + k] = state.a2;
      t.Q2[row + k] = state.P2;
      t.monotone2[static_cast<std::size_t>(j) * (t.K - 1) + (k - 1)] = path.monotone();
    }
    if (!path.last_full()) {
      throw std::runtime_error("the periodic tables' row delta = " + std::to_string(delta) +
                               " is not in full contact at its end, xi = " + std::to_string(cap));
    }
  }
  t.finish();
  return t;
}

}  // namespace punchsweep::reference
