#include "reference/periodic_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "model/numerics/integer_power.hpp"

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

namespace {

/// f(r) of the punch centred at (cx, cy), at (x, y): r the distance to its nearest
/// periodic image.
double punch_height(const PeriodicGrid& grid, const model::Shape& shape, double x, double y, double cx, double cy) {
  return shape.C * model::ipow(std::hypot(periodic_offset(x - cx, grid.Lx), periodic_offset(y - cy, grid.Ly)), shape.s);
}

/// f1 - (f2 + dh), level 1's surface above level 2's: > 0 where level 2 is the lower one,
/// 0 where they tie (within kProfileTieTolerance).
double level2_excess(double f1, double lower2) {
  return std::abs(f1 - lower2) <= kProfileTieTolerance * std::max(f1, lower2) ? 0.0 : f1 - lower2;
}

}  // namespace

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
    for (int j = 0; j < grid.stored_ny(); ++j) f[grid.index(i, j)] = punch_height(grid, shape, grid.x(i), grid.y(j), cx, cy);
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

namespace {

/// The part of the hx x hy square about (x, y) where the level-2 surface is the lower one
/// (`centre_excess` is level2_excess at (x, y)): 0 or 1 where the two surfaces do not cross
/// within the square (checked at its corners, edge midpoints and centre; ties count half),
/// else the midpoint rule over kRows rows, each cut where the surfaces cross (found by
/// bisection to round-off). Exact where the line of crossing is straight (s = 2),
/// O((h / kRows)^2 / radius of curvature) otherwise; counting points on a lattice instead
/// would err alike along a straight line, adding up to O(h / kRows) over the cell.
double level2_fraction(const PeriodicGrid& g, const model::ContactProblem& problem, double x, double y,
                       double centre_excess) {
  constexpr int kRows = 16;
  const double half = 0.5 * problem.l;
  const auto excess = [&](double px, double py) {
    return level2_excess(punch_height(g, problem.shape, px, py, 0.0, 0.0),
                         punch_height(g, problem.shape, px, py, half, half) + problem.dh);
  };
  const auto owner = [](double e) { return e > 0.0 ? 1.0 : e < 0.0 ? 0.0 : 0.5; };
  const double centre = owner(centre_excess);
  bool uniform = centre != 0.5;
  for (int a = -1; a <= 1 && uniform; ++a) {
    for (int b = -1; b <= 1 && uniform; ++b) uniform = owner(excess(x + 0.5 * a * g.hx(), y + 0.5 * b * g.hy())) == centre;
  }
  if (uniform) return centre;
  double sum = 0.0;
  const double left = x - 0.5 * g.hx(), right = x + 0.5 * g.hx();
  for (int b = 0; b < kRows; ++b) {
    const double row = y + ((b + 0.5) / kRows - 0.5) * g.hy();
    const double e_left = excess(left, row), e_right = excess(right, row);
    if ((e_left > 0.0) == (e_right > 0.0) && (e_left < 0.0) == (e_right < 0.0)) {
      sum += owner(e_left);
      continue;
    }
    double lo = left, hi = right;  // keeps the sign of e_left at lo
    for (int k = 0; k < 60 && hi - lo > 1e-15 * g.Lx; ++k) {
      const double mid = 0.5 * (lo + hi);
      ((excess(mid, row) > 0.0) == (e_left > 0.0) ? lo : hi) = mid;
    }
    const double cut = (0.5 * (lo + hi) - left) / g.hx();
    sum += e_left > 0.0 ? cut : e_right > 0.0 ? 1.0 - cut : 0.5;
  }
  return sum / kRows;
}

}  // namespace

TwoLevelCell make_two_level_cell(const model::ContactProblem& problem, int n, Symmetry symmetry) {
  if (const std::string e = two_level_grid_error(n); !e.empty()) throw std::invalid_argument(e);
  TwoLevelCell cell;
  cell.grid = PeriodicGrid::square(n, problem.l, symmetry);
  const PeriodicGrid& g = cell.grid;
  const double half = 0.5 * problem.l;
  const std::vector<double> f1 = punch_profile(g, problem.shape, 0.0, 0.0);
  const std::vector<double> f2 = punch_profile(g, problem.shape, half, half);
  cell.profile.resize(g.size());
  cell.level2_node.resize(g.size());
  cell.level2_weight.resize(g.size());
  for (int i = 0; i < g.stored_nx(); ++i) {
    for (int j = 0; j < g.stored_ny(); ++j) {
      const std::size_t k = g.index(i, j);
      const double lower2 = f2[k] + problem.dh;
      cell.profile[k] = std::min(f1[k], lower2);
      // The node itself belongs to the punch that is lower there; ties (dh = 0 on the
      // bisector) to both.
      const double excess = level2_excess(f1[k], lower2);
      cell.level2_node[k] = excess >= 0.0;
      cell.level2_weight[k] = level2_fraction(g, problem, g.x(i), g.y(j), excess);
    }
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
