#include "reference/periodic_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "model/integer_power.hpp"

namespace punchsweep::reference {

std::string grid_error(const PeriodicGrid& grid) {
  std::ostringstream out;
  if (grid.nx < 1 || grid.ny < 1) {
    out << "grid " << grid.nx << " x " << grid.ny << " is outside its range: nx, ny >= 1";
  } else if (grid.mirrored() && (grid.nx % 2 != 0 || grid.ny % 2 != 0)) {
    out << "mirrored grid " << grid.nx << " x " << grid.ny << " is outside its range: nx, ny even";
  } else if (!(std::isfinite(grid.Lx) && grid.Lx > 0.0 && std::isfinite(grid.Ly) &&
               grid.Ly > 0.0)) {
    out << "cell " << grid.Lx << " x " << grid.Ly << " is outside its range: Lx, Ly > 0";
  }
  return out.str();
}

double periodic_offset(double d, double L) { return d - L * std::nearbyint(d / L); }

std::vector<double> punch_profile(const PeriodicGrid& grid, const model::Shape& shape, double cx,
                                  double cy) {
  if (grid.mirrored()) {
    const auto mirror_point = [](double c, double L) {
      const double d = std::abs(periodic_offset(c, L));
      return d == 0.0 || d == 0.5 * L;
    };
    if (!mirror_point(cx, grid.Lx) || !mirror_point(cy, grid.Ly)) {
      throw std::invalid_argument("punch_profile: a mirrored grid needs a centre at 0 or half the cell");
    }
  }
  std::vector<double> f(grid.size());
  for (int i = 0; i < grid.stored_nx(); ++i) {
    const double dx = periodic_offset(grid.x(i) - cx, grid.Lx);
    for (int j = 0; j < grid.stored_ny(); ++j) {
      const double dy = periodic_offset(grid.y(j) - cy, grid.Ly);
      f[grid.index(i, j)] = shape.C * model::ipow(std::hypot(dx, dy), shape.s);
    }
  }
  return f;
}

std::string two_level_grid_error(int n) {
  if (n >= kMinTwoLevelNodes && n % 2 == 0) return {};
  std::ostringstream out;
  out << "grid size n = " << n << " is outside its range: an even n >= " << kMinTwoLevelNodes
      << " (both punch tips must be nodes)";
  return out.str();
}

TwoLevelCell make_two_level_cell(const model::ContactProblem& problem, int n, Symmetry symmetry) {
  if (const std::string e = two_level_grid_error(n); !e.empty()) throw std::invalid_argument(e);
  TwoLevelCell cell;
  cell.grid = PeriodicGrid::square(n, problem.l, symmetry);
  const PeriodicGrid& g = cell.grid;
  const double half = 0.5 * problem.l;
  const std::vector<double> f1 = punch_profile(g, problem.shape, 0.0, 0.0);
  const std::vector<double> f2 = punch_profile(g, problem.shape, half, half);
  cell.profile.resize(g.size());
  cell.level2_weight.resize(g.size());
  for (std::size_t k = 0; k < g.size(); ++k) {
    const double lower2 = f2[k] + problem.dh;
    cell.profile[k] = std::min(f1[k], lower2);
    // The surface belongs to the punch that is lower there; ties (dh = 0 on the bisector) split.
    const double tie = kProfileTieTolerance * std::max(f1[k], lower2);
    cell.level2_weight[k] = std::abs(f1[k] - lower2) <= tie ? 0.5 : (lower2 < f1[k] ? 1.0 : 0.0);
  }
  const int m = n / 2;
  cell.tip1 = g.index(0, 0);
  cell.tip2 = g.index(m, m);
  return cell;
}

double level2_share(const TwoLevelCell& cell) {
  double sum = 0.0;
  for (std::size_t k = 0; k < cell.level2_weight.size(); ++k) sum += cell.grid.multiplicity(k) * cell.level2_weight[k];
  return sum / static_cast<double>(cell.grid.nodes());
}

}  // namespace punchsweep::reference
