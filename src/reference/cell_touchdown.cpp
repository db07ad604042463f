#include "reference/cell_touchdown.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "reference/contact_areas.hpp"

namespace punchsweep::reference {

namespace {

/// The first site of each level (the one whose tip h_L is measured at).
std::vector<std::size_t> first_sites(const model::CellGeometry& geometry) {
  std::vector<std::size_t> first(static_cast<std::size_t>(geometry.levels()), geometry.sites.size());
  for (std::size_t k = geometry.sites.size(); k-- > 0;) first[static_cast<std::size_t>(geometry.sites[k].level)] = k;
  return first;
}

}  // namespace

CellState cell_state(const model::CellGeometry& geometry, const Cell& cell, ContactSolver& solver, double X) {
  const PeriodicGrid& g = cell.grid;
  std::vector<double> p(g.size(), 0.0), u(g.size());  // p = 0: the solve starts from the uniform field
  CellState s;
  s.X = X;
  s.status = solver.solve(cell.profile, X, 1.0, p, u);
  const int levels = geometry.levels();
  s.level_load = level_loads(g, cell.level_weight, p);
  const std::vector<std::size_t> first = first_sites(geometry);
  s.h.assign(static_cast<std::size_t>(levels), 0.0);
  for (int level = 1; level < levels; ++level) {
    s.h[static_cast<std::size_t>(level)] = u[cell.tips[first[0]]] - u[cell.tips[first[static_cast<std::size_t>(level)]]];
  }
  return s;
}

std::vector<double> level_touchdowns(const model::CellGeometry& geometry, const Cell& cell, double X_max,
                                     double tolerance) {
  if (!(X_max > 0.0 && std::isfinite(X_max) && tolerance > 0.0)) {
    throw std::invalid_argument("level_touchdowns: X_max finite > 0 and tolerance > 0");
  }
  ContactSolver solver(cell.grid);
  const std::vector<std::size_t> first = first_sites(geometry);
  const int levels = geometry.levels();
  std::vector<double> out(static_cast<std::size_t>(levels), 0.0);
  for (int level = 1; level < levels; ++level) {
    const double drop = geometry.sites[first[static_cast<std::size_t>(level)]].drop;
    // Once touched, h_L stays at the drop (to the solve's tolerance, 1e-10 of the
    // displacements): reaching it within 1e-9 counts.
    const auto reached = [&](double X) {
      const CellState s = cell_state(geometry, cell, solver, X);
      if (!s.status.converged) {
        throw std::runtime_error("level_touchdowns: the contact solve at X = " + std::to_string(X) +
                                 " did not converge");
      }
      return s.h[static_cast<std::size_t>(level)] >= drop * (1.0 - 1e-9);
    };
    if (!reached(X_max)) {
      out[static_cast<std::size_t>(level)] = std::numeric_limits<double>::infinity();
      continue;
    }
    double lo = std::log(1e-12), hi = std::log(X_max);
    while (hi - lo > tolerance) {
      const double mid = 0.5 * (lo + hi);
      (reached(std::exp(mid)) ? hi : lo) = mid;
    }
    out[static_cast<std::size_t>(level)] = std::exp(0.5 * (lo + hi));
  }
  return out;
}

}  // namespace punchsweep::reference
