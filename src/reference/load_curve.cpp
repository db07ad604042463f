#include "reference/load_curve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "reference/contact_areas.hpp"
#include "reference/fft_influence.hpp"
#include "reference/touchdown_search.hpp"

namespace punchsweep::reference {

double LoadCurveProgress::fraction() const {
  if (!(X_full > X_start) || !(X_front > X_start)) return 0.0;
  return std::clamp(std::log(X_front / X_start) / std::log(X_full / X_start), 0.0, 1.0);
}

double LoadCurveProgress::range_share() const {
  if (!(X_full_contact > X_start) || !(X_full > X_start)) return 1.0;
  return std::clamp(std::log(X_full / X_start) / std::log(X_full_contact / X_start), 0.0, 1.0);
}

double full_contact_load(const Cell& cell) {
  PeriodicInfluence influence(cell.grid);
  std::vector<double> stiff(cell.profile.size());
  influence.apply_stiffness(cell.profile, stiff);
  return *std::max_element(stiff.begin(), stiff.end());
}

namespace {

/// The march's step in load: samples_per_decade a decade.
double march_step(int samples_per_decade) { return std::pow(10.0, 1.0 / samples_per_decade); }

}  // namespace

double spot_load(const model::CellGeometry& geometry, const PeriodicGrid& grid, int spot_nodes) {
  // The reference tip: a tallest site (the first of the least drop), as the curve's.
  std::size_t reference = 0;
  for (std::size_t k = 0; k < geometry.sites.size(); ++k) {
    if (geometry.sites[k].drop < geometry.sites[reference].drop) reference = k;
  }
  const double a = std::sqrt(spot_nodes * grid.cell_area() / std::numbers::pi);
  const model::Site& tallest = geometry.sites[reference];
  double count = 0.0;
  for (const model::Site& site : geometry.sites) count += site.drop <= tallest.drop ? 1.0 : 0.0;
  return model::load_coefficient(tallest.shape) * std::pow(a, tallest.shape.s + 1) * count / (geometry.Lx * geometry.Ly);
}

double march_end(double X_first, const LoadCurveOptions& options) {
  if (!std::isfinite(options.X_reach)) return options.X_top;
  const double step = march_step(options.samples_per_decade);
  double X = X_first * step;
  while (X < options.X_reach) X *= step;
  return std::min(X, options.X_top);
}

namespace {

/// One solve of the cell and what the curve keeps of it.
struct Solved {
  model::LoadCurveSample sample;
  std::vector<double> p;        ///< the pressure, to start the next solve from
  std::vector<double> h;        ///< per site: u(tallest tip) - u(its tip), in R
  bool full = false;            ///< every node pressed
};

class CurveBuilder {
 public:
  CurveBuilder(const model::CellGeometry& geometry, const Cell& cell, const LoadCurveOptions& options)
      : geometry_(geometry), cell_(cell), options_(options), solver_(cell.grid, options.solver) {
    const PeriodicGrid& g = cell.grid;
    levels_ = geometry.levels();
    // The reference tip: a tallest site (drop 0, or the least drop).
    for (std::size_t k = 0; k < geometry.sites.size(); ++k) {
      if (geometry.sites[k].drop < geometry.sites[reference_].drop) reference_ = k;
    }
    curve_.cell_area = geometry.Lx * geometry.Ly;
    curve_.nx = g.nx;
    curve_.ny = g.ny;
    for (const model::Site& site : geometry.sites) curve_.site_level.push_back(site.level);
    curve_.site_touchdown.assign(geometry.sites.size(), std::numeric_limits<double>::infinity());
    curve_.s_tallest = geometry.sites[reference_].shape.s;
    // Each level's share of the cell (level 0's what the others leave).
    curve_.level_share.assign(static_cast<std::size_t>(levels_), 0.0);
    double rest = 1.0;
    for (int level = 1; level < levels_; ++level) {
      curve_.level_share[static_cast<std::size_t>(level)] = level_share(g, cell.level_weight[static_cast<std::size_t>(level - 1)]);
      rest -= curve_.level_share[static_cast<std::size_t>(level)];
    }
    curve_.level_share[0] = rest;
  }

  model::LoadCurve build(CurveFront* front) {
    const double X_start = start_load(options_.min_spot_nodes);
    const double top = report_range(X_start);
    curve_.X_resolved = start_load(options_.resolved_spot_nodes);
    // The tallest sites touch at any load; any other that has touched by X_start is found
    // below it from the uniform start.
    Solved a = solve(X_start, {});
    for (std::size_t k = 0; k < geometry_.sites.size(); ++k) {
      if (geometry_.sites[k].drop <= geometry_.sites[reference_].drop && cell_.tip_exposed[k] != 0) curve_.site_touchdown[k] = 0.0;
    }
    Solved floor;
    floor.sample.X = X_start * 1e-9;
    floor.h.assign(geometry_.sites.size(), -std::numeric_limits<double>::infinity());
    find_touchdowns(floor, a);
    emit(a);
    // A grid so coarse that the first resolved spot already fills the cell: full there.
    if (a.full) curve_.X_full = a.sample.X;
    return march(std::move(a), top, front);
  }

  /// `curve` (this builder's, stopped at its top short of full contact) continued from
  /// `from`, the state at its last sample, as if the march had not stopped.
  model::LoadCurve extend(model::LoadCurve curve, const CurveFront& from, CurveFront* front) {
    if (std::isfinite(curve.X_full) || curve.nx != cell_.grid.nx || curve.ny != cell_.grid.ny ||
        curve.sites() != geometry_.sites.size() || from.p.size() != cell_.grid.size() || from.h.size() != geometry_.sites.size()) {
      throw std::invalid_argument("extend_load_curve: the curve and its front are not this cell's, stopped short of full contact");
    }
    curve.level_small_spot.clear();
    curve.site_small_spot.clear();
    curve.X_small_spot = 0.0;
    curve_ = std::move(curve);
    const double top = report_range(curve_.X_first());
    Solved a;
    a.sample = curve_.samples.back();
    a.p = from.p;
    a.h = from.h;
    last_p_ = from.p;
    return march(std::move(a), top, front);
  }

 private:
  /// The march's end for a march from X_start (the stated top, or its first sample past the
  /// question's reach), told to the progress.
  double report_range(double X_start) {
    const double top = march_end(X_start, options_);
    if (options_.progress) {
      report_.X_start = X_start;
      report_.X_full_contact = full_contact_load(cell_);
      report_.X_full = std::min(report_.X_full_contact, top);
    }
    return top;
  }

  /// The march in load from sample a (emitted) to `top` or full contact; `front` (where
  /// given) receives the state at the last sample where it stops short of full contact.
  model::LoadCurve march(Solved a, double top, CurveFront* front) {
    const double step = march_step(options_.samples_per_decade);
    while (!a.full && a.sample.X < top) {
      options_.stop.throw_if_requested();
      Solved b = solve(std::min(a.sample.X * step, top), a.p);
      if (b.full) {
        b = first_full(a, b);
        curve_.X_full = b.sample.X;
      }
      // The sites that touch within (a, b], each a knot of the curve: the state at its
      // touchdown, the bisection's last touched solve.
      std::vector<Solved> knots = find_touchdowns(a, b);
      for (Solved& knot : knots) {
        if (knot.sample.X >= b.sample.X * (1.0 - 1e-12)) continue;
        refine(a, knot, 0);
        a = std::move(knot);
      }
      refine(a, b, 0);
      a = std::move(b);
    }
    if (front != nullptr) *front = a.full ? CurveFront{} : CurveFront{a.p, a.h};
    curve_.level_touchdown = level_touchdowns_found();
    return std::move(curve_);
  }

  /// The load at which each tallest site's spot, as an isolated punch's, covers
  /// `spot_nodes` nodes: P = K_P a^(s+1) per site.
  double start_load(int spot_nodes) const { return spot_load(geometry_, cell_.grid, spot_nodes); }

  /// The cell at X from `start` (empty: the uniform field), retried from the uniform field
  /// where the warm start misses.
  Solved solve(double X, const std::vector<double>& start) {
    const PeriodicGrid& g = cell_.grid;
    Solved s;
    s.sample.X = X;
    std::vector<double> u(g.size());
    s.p = start.empty() ? std::vector<double>(g.size(), 0.0) : start;
    ContactStatus status = solver_.solve(cell_.profile, X, 1.0, s.p, u);
    ++solves_;
    if (!status.converged && !start.empty()) {
      std::fill(s.p.begin(), s.p.end(), 0.0);
      status = solver_.solve(cell_.profile, X, 1.0, s.p, u);
      ++solves_;
    }
    if (!status.converged) {
      throw std::runtime_error("load curve: the contact solve at X = " + std::to_string(X) + " E0* missed its tolerance (residual " +
                               std::to_string(status.residual) + " after " + std::to_string(status.iterations) + " iterations)");
    }
    if (options_.progress) {
      report_.solves = solves_;
      report_.X = X;
      report_.X_front = std::max(report_.X_front, X);
      options_.progress(report_);
    }
    s.sample.level_load = level_loads(g, cell_.level_weight, s.p);
    s.full = std::all_of(s.p.begin(), s.p.end(), [](double v) { return v > 0.0; });
    // The areas from the rims of the pressure (an elastic solve's falls as the square root).
    s.sample.level_area = level_contact_areas(g, cell_.level_weight, s.p, s.p);
    s.h.resize(geometry_.sites.size());
    for (std::size_t k = 0; k < geometry_.sites.size(); ++k) s.h[k] = u[cell_.tips[reference_]] - u[cell_.tips[k]];
    return s;
  }

  /// Whether site k has touched in state s: its tip's node carries pressure (the discrete
  /// contact's own test, as the time stepping's; a test on h reaching the drop within a
  /// fixed share of it fails once the displacements grow, the solve's tolerance being
  /// relative to their range: at 512 nodes a level was found 3,000 times late).
  bool touched(const Solved& s, std::size_t k) const {
    // (The floor below the first sample has no pressure: nothing but the tallest touches.)
    if (cell_.tip_exposed[k] == 0) return false;  // under a taller cap: never a punch of its own
    return geometry_.sites[k].drop <= geometry_.sites[reference_].drop || (!s.p.empty() && cell_.touched(k, s.p));
  }
  /// Site k's remaining gap in state s: its drop below the reference tip less h.
  double gap(const Solved& s, std::size_t k) const {
    return geometry_.sites[k].drop - geometry_.sites[reference_].drop - s.h[k];
  }

  /// The pressure to start a solve at X in [a.X, b.X] from: the two states' pressures
  /// mixed as X lies between them in log X (within an interval whose contact set does not
  /// change the solution is affine in X; a quarter fewer iterations than from a's alone,
  /// measured); none (the uniform field) where a is the floor below the first sample.
  static std::vector<double> between(const Solved& a, const Solved& b, double X) {
    if (a.p.empty()) return {};
    const double w = std::clamp(std::log(X / a.sample.X) / std::log(b.sample.X / a.sample.X), 0.0, 1.0);
    std::vector<double> p(a.p.size());
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = (1.0 - w) * a.p[i] + w * b.p[i];
    return p;
  }

  /// The sites untouched in a and touched in b: each one's touchdown by bisection in log X
  /// (sites of the same level, drop and shape whose h agree in a and b to 1e-12 share it,
  /// as symmetric images do), each trial started between the bracket's solves. Returns the
  /// state at each distinct touchdown (the bisection's last touched solve: b where the
  /// bracket never closed from above), increasing in X.
  std::vector<Solved> find_touchdowns(const Solved& a, const Solved& b) {
    std::vector<Solved> found;
    std::vector<std::size_t> done;
    for (std::size_t k = 0; k < geometry_.sites.size(); ++k) {
      if (touched(a, k)) continue;
      if (!touched(b, k) || curve_.site_touchdown[k] == 0.0) continue;
      const model::Site& site = geometry_.sites[k];
      bool shared = false;
      for (std::size_t q : done) {
        const model::Site& other = geometry_.sites[q];
        const auto close = [](double x, double y) { return std::abs(x - y) <= 1e-12 * std::max(std::abs(x), std::abs(y)); };
        if (other.level == site.level && other.drop == site.drop && other.shape.s == site.shape.s &&
            other.shape.C == site.shape.C && close(a.h[k], a.h[q]) && close(b.h[k], b.h[q])) {
          curve_.site_touchdown[k] = curve_.site_touchdown[q];
          shared = true;
          break;
        }
      }
      if (shared) continue;
      // Bisection in log X, aimed by the secant of the site's gap (drop - h, > 0 while
      // untouched; reference/touchdown_search.hpp), each trial started between the
      // bracket's solves.
      const Solved* below = &a;  // the bracket's solves: untouched, touched
      const Solved* above = &b;
      Solved last_below, last_above;
      TouchdownSearch search(std::log(a.sample.X), std::log(b.sample.X), std::log(a.sample.X), gap(a, k),
                             options_.touchdown_tolerance);
      while (search.open()) {
        options_.stop.throw_if_requested();
        const double trial = search.trial();
        Solved m = solve(std::exp(trial), between(*below, *above, std::exp(trial)));
        if (touched(m, k)) {
          search.touched(trial);
          last_above = std::move(m);
          above = &last_above;
        } else {
          search.untouched(trial, gap(m, k));
          last_below = std::move(m);
          below = &last_below;
        }
      }
      const double hi = search.hi();
      curve_.site_touchdown[k] = std::exp(hi);
      found.push_back(above == &b ? b : std::move(last_above));
      done.push_back(k);
    }
    std::sort(found.begin(), found.end(), [](const Solved& x, const Solved& y) { return x.sample.X < y.sample.X; });
    found.erase(std::unique(found.begin(), found.end(), [](const Solved& x, const Solved& y) { return x.sample.X == y.sample.X; }),
                found.end());
    return found;
  }

  /// The first load of full contact in (a, b], b full: by bisection in log X.
  Solved first_full(const Solved& a, Solved b) {
    double lo = std::log(a.sample.X), hi = std::log(b.sample.X);
    while (hi - lo > options_.touchdown_tolerance) {
      const double mid = 0.5 * (lo + hi);
      Solved m = solve(std::exp(mid), between(a, b, std::exp(mid)));
      if (m.full) {
        hi = mid;
        b = std::move(m);
      } else {
        lo = mid;
      }
    }
    return b;
  }

  /// Each level's touchdown: the least of its sites' found so far (+infinity for none).
  std::vector<double> level_touchdowns_found() const { return curve_.least_site_touchdowns(levels_); }

  /// Whether the curve's reading between a and b (LoadCurve::at) meets the solve m.
  bool interpolation_holds(const Solved& a, const Solved& m, const Solved& b) const {
    model::LoadCurve pair;
    pair.cell_area = curve_.cell_area;
    pair.samples = {a.sample, b.sample};
    // The touchdowns found so far (the interval's reading depends on whether it starts at one).
    pair.level_touchdown = level_touchdowns_found();
    pair.level_share = curve_.level_share;
    pair.X_full = std::numeric_limits<double>::infinity();
    const model::CurveState s = pair.at(m.sample.X);
    const double node_area = cell_.grid.cell_area();
    const double X_area = m.sample.X * curve_.cell_area;
    for (std::size_t level = 0; level < static_cast<std::size_t>(levels_); ++level) {
      const double area = m.sample.level_area[level];
      if (std::abs(s.level_area[level] - area) > options_.area_tolerance * area + 0.5 * node_area) return false;
      if (std::abs(s.level_load[level] - m.sample.level_load[level]) > options_.load_tolerance * X_area) return false;
    }
    return true;
  }

  /// Adds the samples of (a, b] to the curve: b, after as many midpoints (in log X) as the
  /// interpolation needs.
  void refine(const Solved& a, const Solved& b, int depth) {
    if (depth < options_.max_refinements) {
      const double X = std::sqrt(a.sample.X * b.sample.X);
      Solved m = solve(X, between(a, b, X));
      if (!interpolation_holds(a, m, b)) {
        refine(a, m, depth + 1);
        refine(m, b, depth + 1);
        return;
      }
    }
    emit(b);
  }

  /// Appends a sample, recording whether the pressure grew at every node since the last.
  void emit(const Solved& s) {
    if (!curve_.samples.empty()) {
      double top = 0.0;
      for (double v : s.p) top = std::max(top, v);
      bool grew = true;
      for (std::size_t k = 0; k < s.p.size() && grew; ++k) grew = s.p[k] >= last_p_[k] - 1e-9 * top;
      curve_.pressure_monotone.push_back(grew ? 1 : 0);
    }
    curve_.samples.push_back(s.sample);
    last_p_ = s.p;
  }

  const model::CellGeometry& geometry_;
  const Cell& cell_;
  LoadCurveOptions options_;
  ContactSolver solver_;
  int levels_ = 0;
  std::size_t reference_ = 0;
  int solves_ = 0;
  LoadCurveProgress report_;  ///< what options_.progress is told
  std::vector<double> last_p_;
  model::LoadCurve curve_;
};

}  // namespace

namespace {

void check_options(const LoadCurveOptions& options) {
  if (!(options.X_top > 0.0) || !(options.X_reach > 0.0) || options.min_spot_nodes < 1 || options.resolved_spot_nodes < options.min_spot_nodes || options.samples_per_decade < 1 ||
      !(options.area_tolerance > 0.0) || !(options.load_tolerance > 0.0) || options.max_refinements < 0 ||
      !(options.touchdown_tolerance > 0.0)) {
    throw std::invalid_argument("build_load_curve: X_top, X_reach > 0, min_spot_nodes, samples_per_decade >= 1, tolerances > 0");
  }
}

}  // namespace

model::LoadCurve build_load_curve(const model::CellGeometry& geometry, const Cell& cell, const LoadCurveOptions& options,
                                  CurveFront* front) {
  check_options(options);
  if (cell.tips.size() != geometry.sites.size()) throw std::invalid_argument("build_load_curve: the cell is not the geometry's");
  return CurveBuilder(geometry, cell, options).build(front);
}

model::LoadCurve extend_load_curve(const model::CellGeometry& geometry, const Cell& cell, model::LoadCurve curve,
                                   const CurveFront& from, const LoadCurveOptions& options, CurveFront* front) {
  check_options(options);
  if (cell.tips.size() != geometry.sites.size()) throw std::invalid_argument("extend_load_curve: the cell is not the geometry's");
  return CurveBuilder(geometry, cell, options).extend(std::move(curve), from, front);
}

}  // namespace punchsweep::reference
