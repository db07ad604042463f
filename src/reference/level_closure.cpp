#include "reference/level_closure.hpp"

#include "reference/contact_areas.hpp"
#include "reference/touchdown_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace punchsweep::reference {

namespace {

/// How far above the depth where it would be hidden a level's sites are set: a relative
/// 1e-8 keeps their tips on the texture's surface (model::tip_exposed ties within 1e-12).
constexpr double kExposedMargin = 1e-8;

bool in_level(const model::CellGeometry& geometry, int level, std::size_t k) { return geometry.sites[k].level == level; }

}  // namespace

LevelClosure::LevelClosure(const model::CellGeometry& geometry, int level, const PeriodicGrid& grid,
                           ContactSolverOptions solver)
    : geometry_(geometry), solver_(grid, solver), level_(level) {
  if (level < 1 || level >= geometry.levels()) {
    throw std::invalid_argument("level closure: level " + std::to_string(level) + " is not one of the geometry's levels 1 to " +
                                std::to_string(geometry.levels() - 1));
  }
  // The reference tip: a tallest site (the least drop) of another level.
  std::size_t reference = geometry.sites.size();
  for (std::size_t k = 0; k < geometry.sites.size(); ++k) {
    if (!in_level(geometry, level, k) && (reference == geometry.sites.size() || geometry.sites[k].drop < geometry.sites[reference].drop)) {
      reference = k;
    }
  }
  reference_ = reference;
  // The level's caps may lie at different drops (a scattered supercell's, a cell file's):
  // each keeps its offset below the level's tallest, and the level moves as one.
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < geometry.sites.size(); ++k) {
    if (in_level(geometry, level, k)) least = std::min(least, geometry.sites[k].drop);
  }
  offset_.assign(geometry.sites.size(), 0.0);
  for (std::size_t k = 0; k < geometry.sites.size(); ++k) {
    if (in_level(geometry, level, k)) offset_[k] = geometry.sites[k].drop - least;
  }
  // The deepest exposed drop of the level's tallest cap (the level's own sites left out, so
  // a locator's reach, which assumes them, does not apply).
  deepest_ = model::deepest_exposed_drop(geometry, level);
  if (!(deepest_ > geometry.sites[reference_].drop) || !std::isfinite(deepest_)) {
    throw std::invalid_argument("level closure: level " + std::to_string(level) + " has no depth at which it is a punch of its own");
  }
  for (std::size_t k = 0; k < geometry_.sites.size(); ++k) {
    if (in_level(geometry_, level, k)) {
      geometry_.sites[k].drop = deepest_ * (1.0 - kExposedMargin) + offset_[k];
      ++caps_;
    }
  }
  cell_ = make_cell(geometry_, grid);
}

LevelClosed LevelClosure::at(double X) {
  LevelClosed out;
  if (!(X >= 0.0)) throw std::invalid_argument("level closure: the load X = " + std::to_string(X) + " is not >= 0");
  if (X == 0.0) {
    out.status.converged = true;
    return out;
  }
  const PeriodicGrid& g = cell_.grid;
  std::vector<double> p(g.size(), 0.0), u(g.size());
  out.status = solver_.solve(cell_.profile, X, 1.0, p, u);
  out.solves = 1;
  if (!out.status.converged) {
    throw std::runtime_error("level closure: the contact solve at X = " + std::to_string(X) + " E0* missed its tolerance (residual " +
                             std::to_string(out.status.residual) + " after " + std::to_string(out.status.iterations) +
                             " iterations)");
  }
  const double reference_drop = geometry_.sites[reference_].drop;
  const double u_reference = u[cell_.tips[reference_]];
  double closed = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < geometry_.sites.size(); ++k) {
    if (geometry_.sites[k].level != level_) continue;
    if (cell_.touched(k, p)) out.every_drop = true;
    closed = std::max(closed, reference_drop + u_reference - u[cell_.tips[k]] - offset_[k]);
  }
  out.drop = out.every_drop ? deepest_ : std::clamp(closed, 0.0, deepest_);
  return out;
}

void LevelClosure::prepare_moves() {
  if (!others_.empty()) return;
  const std::size_t n = cell_.grid.size();
  model::CellGeometry top = geometry_;
  for (std::size_t k = 0; k < top.sites.size(); ++k) {
    if (in_level(top, level_, k)) top.sites[k].drop = offset_[k];
  }
  level_at_top_ = level_surfaces(top, cell_.grid)[static_cast<std::size_t>(level_)];
  deep_ = level_surfaces(geometry_, cell_.grid);
  others_.assign(n, std::numeric_limits<double>::infinity());
  for (std::size_t q = 0; q < deep_.size(); ++q) {
    if (static_cast<int>(q) == level_) continue;
    for (std::size_t i = 0; i < n; ++i) others_[i] = std::min(others_[i], deep_[q][i]);
  }
}

LevelClosed LevelClosure::at(double X, std::size_t caps, bool every_level) {
  return counting(X, caps, every_level ? kEveryLevel : level_);
}

LevelClosed LevelClosure::counting(double X, std::size_t caps, int level) {
  const bool every_level = level == kEveryLevel;
  // Another level's caps: more of them touch the deeper this level lies (it carries less).
  const bool rising = !every_level && level != level_;
  std::size_t counted = 0;
  for (std::size_t k = 0; k < geometry_.sites.size(); ++k) counted += every_level || in_level(geometry_, level, k) ? 1 : 0;
  if (rising && (level < 1 || level >= geometry_.levels())) {
    throw std::invalid_argument("level closure: level " + std::to_string(level) + " is not one of the geometry's levels 1 to " +
                                std::to_string(geometry_.levels() - 1) + " (level 0, the tallest, is the reference)");
  }
  if (caps < 1 || caps > counted) {
    throw std::invalid_argument("level closure: " + std::to_string(caps) + " caps of " +
                                (every_level ? std::string("the cell") : "level " + std::to_string(level)) + ", which has " +
                                std::to_string(counted));
  }
  if (!(X >= 0.0)) throw std::invalid_argument("level closure: the load X = " + std::to_string(X) + " is not >= 0");
  if (rising && X == 0.0) {  // (nothing but the tallest tips touches at no load)
    LevelClosed out;
    out.status.converged = true;
    out.rising = true;
    out.drop = std::numeric_limits<double>::infinity();
    return out;
  }
  if ((caps == 1 && level == level_) || X == 0.0) return at(X);
  LevelClosed out;
  out.status.converged = true;
  const std::size_t n = cell_.grid.size();
  prepare_moves();
  // The level's caps in contact at load X with its tallest cap at `drop` (the others at
  // their offsets below it), and where fewer than `caps` are, the gap of the cap that would
  // be the caps-th (the (caps - count)-th least tip gap of the untouched: it falls to 0 as
  // the drop nears the answer from below, continuously as caps touch before it). The
  // level's tips stay on the surface at any drop to its deepest, so the closure's cell says
  // which are pressed.
  const double deepest = deepest_ * (1.0 - kExposedMargin);
  std::vector<double> profile(n), u(n), gaps;
  std::vector<std::pair<double, std::size_t>> tried;
  if (pressure_.size() != n) pressure_.assign(n, 0.0);
  struct Trial {
    std::size_t count = 0;
    double gap = 0.0;  ///< the deciding cap's, where count < caps
  };
  const auto trial_at = [&](double drop) {
    for (std::size_t i = 0; i < n; ++i) profile[i] = std::min(others_[i], level_at_top_[i] + drop);
    const ContactStatus status = solver_.solve(profile, X, 1.0, pressure_, u);
    ++out.solves;
    if (!status.converged) {
      throw std::runtime_error("level closure: the contact solve at X = " + std::to_string(X) + " E0* with level " +
                               std::to_string(level_) + " at drop " + std::to_string(drop) +
                               " R missed its tolerance (residual " + std::to_string(status.residual) + ")");
    }
    out.status.iterations += status.iterations;
    out.status.residual = std::max(out.status.residual, status.residual);
    Trial t;
    gaps.clear();
    for (std::size_t k = 0; k < geometry_.sites.size(); ++k) {
      if (!every_level && !in_level(geometry_, level, k)) continue;
      if (cell_.touched(k, pressure_)) {
        ++t.count;
      } else {
        const std::size_t tip = cell_.tips[k];
        gaps.push_back(profile[tip] + u[tip] - status.approach);
      }
    }
    if (t.count < caps) {
      const auto nth = gaps.begin() + static_cast<std::ptrdiff_t>(caps - t.count - 1);
      std::nth_element(gaps.begin(), nth, gaps.end());
      t.gap = *nth;
    }
    tried.emplace_back(drop, t.count);
    return t;
  };
  // Every trial's drop and count: whether the count fell (rose, for another level's caps)
  // steadily with the drop.
  const auto steady = [&tried, rising] {
    std::sort(tried.begin(), tried.end());
    for (std::size_t k = 1; k < tried.size(); ++k) {
      if (rising ? tried[k].second < tried[k - 1].second : tried[k].second > tried[k - 1].second) return false;
    }
    return true;
  };
  // Aimed bisection over the drop, as the load curve's touchdowns are
  // (reference/touchdown_search.hpp), in x = sign x drop (touched at the greater x): the
  // bracket from an untouched drop to a touched one, the secant's first point a drop whose
  // deciding cap's gap is known (at or beyond the untouched end); the bracket's middle.
  const auto bisect = [&](double sign, double untouched, double touched, double known, double gap) {
    TouchdownSearch search(sign * untouched, sign * touched, sign * known, gap, kDropTolerance * deepest_);
    while (search.open()) {
      const double drop = sign * search.trial();
      const Trial t = trial_at(drop);
      if (t.count >= caps) {
        search.touched(sign * drop);
      } else {
        search.untouched(sign * drop, t.gap);
      }
    }
    return sign * (0.5 * (search.lo() + search.hi()));
  };
  if (rising) {
    // The least drop at which `caps` of the other level's caps have touched: -infinity where
    // they have with this level at the top (at every drop it can have), +infinity where not
    // even at its deepest; between, the bisection in x = drop (the deciding cap's gap smooth
    // on the shallower side).
    out.rising = true;
    const Trial at_top = trial_at(0.0);
    if (at_top.count >= caps) {
      out.drop = -std::numeric_limits<double>::infinity();
      out.steady = steady();
      return out;
    }
    if (trial_at(deepest).count < caps) {
      out.drop = std::numeric_limits<double>::infinity();
      out.steady = steady();
      return out;
    }
    out.drop = bisect(1.0, 0.0, deepest, 0.0, at_top.gap);
    out.steady = steady();
    return out;
  }
  const Trial at_deepest = trial_at(deepest);
  if (at_deepest.count >= caps) {
    out.every_drop = true;
    out.drop = deepest_;
    return out;
  }
  // The level's first cap closes at at(X).drop: its caps-th no deeper.
  double low = 0.0, high = deepest;
  if (!every_level) {
    const LevelClosed first = at(X);
    out.solves += first.solves;
    high = std::min(first.drop, deepest);
  }
  if (trial_at(low).count < caps) {
    out.drop = -std::numeric_limits<double>::infinity();
    out.steady = steady();
    return out;
  }
  // The bisection in x = -drop: the deciding cap's gap is smooth on the untouched (deeper)
  // side.
  out.drop = bisect(-1.0, high, low, deepest, at_deepest.gap);
  out.steady = steady();
  return out;
}

model::CurveState LevelClosure::state(double X, double drop) {
  if (!(drop >= 0.0 && drop <= deepest_)) {
    throw std::invalid_argument("level closure: the drop " + std::to_string(drop) + " R is outside 0 to the level's deepest, " +
                                std::to_string(deepest_) + " R");
  }
  if (!(X >= 0.0) || std::isinf(X)) throw std::invalid_argument("level closure: the load X = " + std::to_string(X) + " is not finite and >= 0");
  const std::size_t L = static_cast<std::size_t>(geometry_.levels());
  model::CurveState out;
  out.X = X;
  out.level_area.assign(L, 0.0);
  out.level_load.assign(L, 0.0);
  out.level_sites_touched.assign(L, 0.0);
  if (X == 0.0) return out;
  prepare_moves();
  const PeriodicGrid& g = cell_.grid;
  const std::size_t n = g.size();
  const double at = std::min(drop, deepest_ * (1.0 - kExposedMargin));
  // The profile with the level at `at`, and each node counted to the level whose surface is
  // the lowest at its centre (level_weight's shares, which make_cell samples within each
  // node's square at many times the cost, differ only where two levels' surfaces meet, away
  // from the spots until the contact nearly fills the cell).
  std::vector<double> profile(n);
  std::vector<std::vector<double>> weight(L - 1, std::vector<double>(n, 0.0));
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t lowest = 0;
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t q = 0; q < L; ++q) {
      const double v = static_cast<int>(q) == level_ ? level_at_top_[i] + at : deep_[q][i];
      if (v < least) {
        least = v;
        lowest = q;
      }
    }
    profile[i] = least;
    if (lowest > 0) weight[lowest - 1][i] = 1.0;
  }
  std::vector<double> p(n, 0.0), u(n);
  const ContactStatus status = solver_.solve(profile, X, 1.0, p, u);
  if (!status.converged) {
    throw std::runtime_error("level closure: the contact solve at X = " + std::to_string(X) + " E0* missed its tolerance (residual " +
                             std::to_string(status.residual) + ")");
  }
  out.level_area = level_contact_areas(g, weight, p, p);
  out.level_load = level_loads(g, weight, p);
  std::vector<double> sites(L, 0.0);
  double touched = 0.0;
  for (std::size_t k = 0; k < geometry_.sites.size(); ++k) {
    const auto level = static_cast<std::size_t>(geometry_.sites[k].level);
    sites[level] += 1.0;
    if (cell_.touched(k, p)) {
      out.level_sites_touched[level] += 1.0;
      touched += 1.0;
    }
  }
  double area = 0.0;
  for (std::size_t level = 0; level < L; ++level) {
    if (sites[level] > 0.0) out.level_sites_touched[level] /= sites[level];
    area += out.level_area[level];
  }
  out.sites_touched = touched / static_cast<double>(geometry_.sites.size());
  out.area_fraction = area / (geometry_.Lx * geometry_.Ly);
  return out;
}

}  // namespace punchsweep::reference
