#include "reference/level_closure.hpp"

#include "reference/contact_areas.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

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
  // The deepest exposed drop of the level's tallest cap: at each of the level's tips, the
  // lowest of the other sites' surfaces there (every other site, each to its nearest image:
  // the level's own sites are left out, so a locator's reach, which assumes them, does not
  // apply), less the tip's offset.
  const model::SurfaceLocator surface(geometry);
  deepest_ = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < geometry.sites.size(); ++k) {
    if (!in_level(geometry, level, k)) continue;
    for (std::size_t j = 0; j < geometry.sites.size(); ++j) {
      if (in_level(geometry, level, j)) continue;
      deepest_ = std::min(deepest_, surface.surface(j, surface.distance(geometry.sites[k].x, geometry.sites[k].y, j)) - offset_[k]);
    }
  }
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

LevelClosed LevelClosure::at(double X, std::size_t caps) {
  if (caps < 1 || caps > caps_) {
    throw std::invalid_argument("level closure: " + std::to_string(caps) + " caps of level " + std::to_string(level_) +
                                ", which has " + std::to_string(caps_));
  }
  if (caps == 1 || X == 0.0) return at(X);
  if (!(X > 0.0)) throw std::invalid_argument("level closure: the load X = " + std::to_string(X) + " is not >= 0");
  LevelClosed out;
  out.status.converged = true;
  const std::size_t n = cell_.grid.size();
  if (others_.empty()) {
    model::CellGeometry top = geometry_;
    for (std::size_t k = 0; k < top.sites.size(); ++k) {
      if (in_level(top, level_, k)) top.sites[k].drop = offset_[k];
    }
    level_at_top_ = level_surfaces(top, cell_.grid)[static_cast<std::size_t>(level_)];
    const std::vector<std::vector<double>> deep = level_surfaces(geometry_, cell_.grid);
    others_.assign(n, std::numeric_limits<double>::infinity());
    for (std::size_t q = 0; q < deep.size(); ++q) {
      if (static_cast<int>(q) == level_) continue;
      for (std::size_t i = 0; i < n; ++i) others_[i] = std::min(others_[i], deep[q][i]);
    }
  }
  // The level's caps in contact at load X with its tallest cap at `drop` (the others at
  // their offsets below it). The level's tips stay on the surface at any drop to its
  // deepest, so the closure's cell says which are pressed.
  const double deepest = deepest_ * (1.0 - kExposedMargin);
  std::vector<double> profile(n), u(n);
  if (pressure_.size() != n) pressure_.assign(n, 0.0);
  const auto touched = [&](double drop) {
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
    std::size_t count = 0;
    for (std::size_t k = 0; k < geometry_.sites.size(); ++k) {
      if (in_level(geometry_, level_, k) && cell_.touched(k, pressure_)) ++count;
    }
    return count;
  };
  if (touched(deepest) >= caps) {
    out.every_drop = true;
    out.drop = deepest_;
    return out;
  }
  // The first cap closes at at(X).drop: the caps-th no deeper.
  const LevelClosed first = at(X);
  out.solves += first.solves;
  double low = 0.0, high = std::min(first.drop, deepest);
  if (touched(low) < caps) {
    out.drop = -std::numeric_limits<double>::infinity();
    return out;
  }
  while (high - low > kDropTolerance * deepest_) {
    const double mid = 0.5 * (low + high);
    (touched(mid) >= caps ? low : high) = mid;
  }
  out.drop = 0.5 * (low + high);
  return out;
}

model::CurveState LevelClosure::state(double X, double drop) {
  if (!(drop >= 0.0 && drop <= deepest_)) {
    throw std::invalid_argument("level closure: the drop " + std::to_string(drop) + " R is outside 0 to the level's deepest, " +
                                std::to_string(deepest_) + " R");
  }
  if (!(X >= 0.0) || std::isinf(X)) throw std::invalid_argument("level closure: the load X = " + std::to_string(X) + " is not finite and >= 0");
  model::CellGeometry at = geometry_;
  for (std::size_t k = 0; k < at.sites.size(); ++k) {
    if (in_level(at, level_, k)) at.sites[k].drop = std::min(drop, deepest_ * (1.0 - kExposedMargin)) + offset_[k];
  }
  const Cell cell = make_cell(at, cell_.grid);
  const std::size_t n = cell.grid.size();
  const std::size_t L = static_cast<std::size_t>(at.levels());
  model::CurveState out;
  out.X = X;
  out.level_area.assign(L, 0.0);
  out.level_load.assign(L, 0.0);
  out.level_sites_touched.assign(L, 0.0);
  if (X == 0.0) return out;
  std::vector<double> p(n, 0.0), u(n);
  const ContactStatus status = solver_.solve(cell.profile, X, 1.0, p, u);
  if (!status.converged) {
    throw std::runtime_error("level closure: the contact solve at X = " + std::to_string(X) + " E0* missed its tolerance (residual " +
                             std::to_string(status.residual) + ")");
  }
  out.level_area = level_contact_areas(cell.grid, cell.level_weight, p, p);
  out.level_load = level_loads(cell.grid, cell.level_weight, p);
  std::vector<double> sites(L, 0.0);
  double touched = 0.0;
  for (std::size_t k = 0; k < at.sites.size(); ++k) {
    const auto level = static_cast<std::size_t>(at.sites[k].level);
    sites[level] += 1.0;
    if (cell.touched(k, p)) {
      out.level_sites_touched[level] += 1.0;
      touched += 1.0;
    }
  }
  double area = 0.0;
  for (std::size_t level = 0; level < L; ++level) {
    if (sites[level] > 0.0) out.level_sites_touched[level] /= sites[level];
    area += out.level_area[level];
  }
  out.sites_touched = touched / static_cast<double>(at.sites.size());
  out.area_fraction = area / (at.Lx * at.Ly);
  return out;
}

}  // namespace punchsweep::reference
