#include "reference/periodic_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
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
  } else if (grid.mirrored_x() && grid.nx % 2 != 0) {
    out << "grid " << grid.nx << " x " << grid.ny << " mirrored in x is outside its range: nx even";
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
  if (std::isinf(f1) || std::isinf(lower2)) return f1 - lower2;  // (one reaches the point, the other not)
  return std::abs(f1 - lower2) <= kProfileTieTolerance * std::max(f1, lower2) ? 0.0 : f1 - lower2;
}

}  // namespace

std::vector<double> punch_profile(const PeriodicGrid& grid, const model::Shape& shape, double cx,
                                  double cy) {
  const auto mirror_point = [](double c, double L) {
    const double d = std::abs(periodic_offset(c, L));
    return d == 0.0 || d == 0.5 * L;
  };
  if ((grid.mirrored_x() && !mirror_point(cx, grid.Lx)) || (grid.mirrored_y() && !mirror_point(cy, grid.Ly))) {
    throw std::invalid_argument("punch_profile: a mirrored grid needs a centre at 0 or half the cell along each mirrored axis");
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

/// The part of the hx x hy square about (x, y) that a level owns, `excess` its surface's
/// margin below the others' (level2_excess: > 0 where it is the lowest, 0 on a tie;
/// `centre_excess` its value at (x, y)): 0 or 1 where the surfaces do not cross within the
/// square (checked at its corners, edge midpoints and centre; ties count half), else the
/// midpoint rule over kRows rows, each cut where the surfaces cross (found by bisection to
/// round-off). Exact where the line of crossing is straight (s = 2), O((h / kRows)^2 /
/// radius of curvature) otherwise; counting points on a lattice instead would err alike
/// along a straight line, adding up to O(h / kRows) over the cell.
template <class Excess>
double level_fraction(const PeriodicGrid& g, const Excess& excess, double x, double y, double centre_excess) {
  constexpr int kRows = 16;
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

/// The node at a site's tip (under a mirror, at its image in the stored part), or
/// std::invalid_argument where the tip is not a node.
std::size_t tip_node(const PeriodicGrid& g, const model::Site& site, std::size_t k) {
  const auto node = [&](double c, double h, int n, int stored) {
    const double L = h * n;
    if (stored < n && c > 0.5 * L) c = L - c;  // (a mirrored axis stores n/2 + 1 of its n)
    const long i = std::lround(c / h);
    if (std::abs(i * h - c) > 1e-9 * h * n || i < 0 || i >= stored) {
      throw std::invalid_argument("make_cell: site " + std::to_string(k) + "'s tip is not a stored node of the grid");
    }
    return static_cast<int>(i);
  };
  return g.index(node(site.x, g.hx(), g.nx, g.stored_nx()), node(site.y, g.hy(), g.ny, g.stored_ny()));
}

std::vector<std::vector<double>> level_surfaces(const model::CellGeometry& geometry, const PeriodicGrid& g,
                                                const model::SurfaceLocator& locator, std::vector<std::size_t>* tips,
                                                std::vector<char>* tip_exposed) {
  const std::vector<model::Site>& sites = geometry.sites;
  const std::size_t levels = static_cast<std::size_t>(geometry.levels());
  // Each level's lowest surface f(r) + drop at the nodes, each site read over its reach
  // alone (never a grid per site: a supercell has thousands).
  std::vector<std::vector<double>> level_low(levels, std::vector<double>(g.size(), std::numeric_limits<double>::infinity()));
  // The nodes i (along one axis of n nodes, `stored` of them kept) within `reach` of c.
  const auto window = [](double c, double reach, double h, int n, int stored, std::vector<int>* out) {
    out->clear();
    const double first = std::ceil((c - reach) / h), last = std::floor((c + reach) / h);
    const bool all = !(last - first + 1.0 < n);
    const long from = all ? 0 : static_cast<long>(first), to = all ? n - 1 : static_cast<long>(last);
    for (long i = from; i <= to; ++i) {
      const int wrapped = static_cast<int>(((i % n) + n) % n);
      if (wrapped < stored) out->push_back(wrapped);
    }
  };
  std::vector<int> rows, columns;
  for (std::size_t k = 0; k < sites.size(); ++k) {
    const model::Site& site = sites[k];
    if (tips) tips->push_back(tip_node(g, site, k));
    if (tip_exposed) tip_exposed->push_back(model::tip_exposed(geometry, locator, k) ? 1 : 0);
    if (locator.reach(k) < 0.0) continue;  // nowhere the lowest
    window(site.x, locator.reach(k), g.hx(), g.nx, g.stored_nx(), &rows);
    window(site.y, locator.reach(k), g.hy(), g.ny, g.stored_ny(), &columns);
    std::vector<double>& low = level_low[static_cast<std::size_t>(site.level)];
    for (const int i : rows) {
      for (const int j : columns) {
        double& v = low[g.index(i, j)];
        v = std::min(v, punch_height(g, site.shape, g.x(i), g.y(j), site.x, site.y) + site.drop);
      }
    }
  }
  return level_low;
}

}  // namespace

Symmetry symmetry_of(const model::CellGeometry& geometry) {
  return model::mirror_symmetric(geometry) ? Symmetry::mirror : model::mirror_symmetric_x(geometry) ? Symmetry::mirror_x : Symmetry::none;
}

Cell make_cell(const model::CellGeometry& geometry, const PeriodicGrid& grid) {
  if (const std::string e = model::geometry_error(geometry); !e.empty()) throw std::invalid_argument("make_cell: " + e);
  if (const std::string e = grid_error(grid); !e.empty()) throw std::invalid_argument("make_cell: " + e);
  if (grid.Lx != geometry.Lx || grid.Ly != geometry.Ly) {
    throw std::invalid_argument("make_cell: the grid's cell is not the geometry's");
  }
  const std::vector<model::Site>& sites = geometry.sites;
  Cell cell;
  cell.grid = grid;
  const PeriodicGrid& g = cell.grid;
  // A mirrored grid needs the sites' set to be even (each site alone need not be: the
  // lowest surface of them all is).
  if (g.mirrored() && !model::mirror_symmetric(geometry)) {
    throw std::invalid_argument("make_cell: a mirrored grid needs a geometry whose sites are even in x and y");
  }
  if (g.mirrored_x() && !model::mirror_symmetric_x(geometry)) {
    throw std::invalid_argument("make_cell: a grid mirrored in x needs a geometry whose sites are even in x");
  }
  const model::SurfaceLocator locator(geometry);
  const std::size_t levels = static_cast<std::size_t>(geometry.levels());
  const std::vector<std::vector<double>> level_low = level_surfaces(geometry, g, locator, &cell.tips, &cell.tip_exposed);
  cell.profile.assign(g.size(), std::numeric_limits<double>::infinity());
  for (const std::vector<double>& low : level_low) {
    for (std::size_t k = 0; k < g.size(); ++k) cell.profile[k] = std::min(cell.profile[k], low[k]);
  }
  // The lowest surface among the sites of `level` (own) or of the others, at a point
  // (+infinity where none of them reaches it: there it lies above the texture's).
  const auto lowest = [&](double px, double py, int level, bool own) {
    return locator.lowest(px, py, [&](std::size_t q) { return (sites[q].level == level) == own; }).first;
  };
  for (int level = 1; level < geometry.levels(); ++level) {
    std::vector<double> weight(g.size());
    std::vector<char> own_node(g.size());
    const auto excess = [&](double px, double py) { return level2_excess(lowest(px, py, level, false), lowest(px, py, level, true)); };
    for (int i = 0; i < g.stored_nx(); ++i) {
      for (int j = 0; j < g.stored_ny(); ++j) {
        const std::size_t k = g.index(i, j);
        double others = std::numeric_limits<double>::infinity();
        for (std::size_t q = 0; q < levels; ++q) {
          if (q != static_cast<std::size_t>(level)) others = std::min(others, level_low[q][k]);
        }
        // The node itself belongs to the level that is lowest there; ties to both.
        const double centre = level2_excess(others, level_low[static_cast<std::size_t>(level)][k]);
        own_node[k] = centre >= 0.0;
        weight[k] = level_fraction(g, excess, g.x(i), g.y(j), centre);
      }
    }
    cell.level_weight.push_back(std::move(weight));
    cell.level_node.push_back(std::move(own_node));
  }
  return cell;
}

std::vector<std::vector<double>> level_surfaces(const model::CellGeometry& geometry, const PeriodicGrid& grid) {
  if (const std::string e = model::geometry_error(geometry); !e.empty()) throw std::invalid_argument("level_surfaces: " + e);
  if (const std::string e = grid_error(grid); !e.empty()) throw std::invalid_argument("level_surfaces: " + e);
  if (grid.Lx != geometry.Lx || grid.Ly != geometry.Ly) {
    throw std::invalid_argument("level_surfaces: the grid's cell is not the geometry's");
  }
  return level_surfaces(geometry, grid, model::SurfaceLocator(geometry), nullptr, nullptr);
}

bool fft_friendly(int n) {
  for (const int p : {2, 3, 5, 7}) {
    while (n > 0 && n % p == 0) n /= p;
  }
  return n == 1 || n == 11 || n == 13;
}

PeriodicGrid lattice_grid(const model::CellGeometry& geometry, model::LatticeKind lattice, int n, int K) {
  if (const std::string e = two_level_grid_error(n); !e.empty()) throw std::invalid_argument(e);
  if (K < 1) throw std::invalid_argument("lattice_grid: K >= 1");
  // A hexagonal cell's ny: a multiple of 6 (its tips on nodes), the FFT-friendly one nearest
  // square nodes within 3% (else the nearest).
  const double square = n * geometry.Ly / geometry.Lx;
  int ny = 6 * std::max(1, static_cast<int>(std::lround(square / 6.0)));
  if (lattice == model::LatticeKind::square) {
    ny = n;
  } else if (!fft_friendly(K * ny)) {
    double best = std::numeric_limits<double>::infinity();
    for (int m = 6 * static_cast<int>(std::ceil(0.97 * square / 6.0)); m <= 1.03 * square; m += 6) {
      if (fft_friendly(K * m) && std::abs(m - square) < best) {
        best = std::abs(m - square);
        ny = m;
      }
    }
  }
  return {K * n, K * ny, geometry.Lx, geometry.Ly, symmetry_of(geometry)};
}

PeriodicGrid cell_grid(const model::CellGeometry& geometry, int n) {
  if (const std::string e = two_level_grid_error(n); !e.empty()) throw std::invalid_argument(e);
  // Among the even ny within 10% of square nodes, the one whose nodes lie nearest the tips
  // (a hexagonal cell's multiple of 6 puts them on nodes), the nearer to square on a tie.
  const double square = n * geometry.Ly / geometry.Lx;
  int best = std::max(2, 2 * static_cast<int>(std::lround(0.5 * square)));
  double best_miss = std::numeric_limits<double>::infinity();
  for (int ny = std::max(2, 2 * static_cast<int>(std::floor(0.45 * square))); ny <= 2 * std::ceil(0.55 * square); ny += 2) {
    const double h = geometry.Ly / ny;
    double miss = 0.0;
    for (const model::Site& site : geometry.sites) miss = std::max(miss, std::abs(site.y / h - std::nearbyint(site.y / h)));
    miss = miss < 1e-9 ? 0.0 : miss;
    if (miss < best_miss || (miss == best_miss && std::abs(ny - square) < std::abs(best - square))) {
      best = ny;
      best_miss = miss;
    }
  }
  return {n, best, geometry.Lx, geometry.Ly, symmetry_of(geometry)};
}

model::CellGeometry snap_tips(const model::CellGeometry& geometry, const PeriodicGrid& grid, double* moved) {
  model::CellGeometry out = geometry;
  double longest = 0.0;
  for (model::Site& site : out.sites) {
    const double x = std::fmod(std::nearbyint(site.x / grid.hx()), grid.nx) * grid.hx();
    const double y = std::fmod(std::nearbyint(site.y / grid.hy()), grid.ny) * grid.hy();
    longest = std::max(longest, std::hypot(periodic_offset(x - site.x, grid.Lx), periodic_offset(y - site.y, grid.Ly)));
    site.x = x;
    site.y = y;
  }
  if (moved != nullptr) *moved = longest;
  return out;
}

TwoLevelCell make_two_level_cell(const model::ContactProblem& problem, int n, Symmetry symmetry) {
  if (const std::string e = two_level_grid_error(n); !e.empty()) throw std::invalid_argument(e);
  Cell cell = make_cell(model::two_level_square(problem), PeriodicGrid::square(n, problem.l, symmetry));
  TwoLevelCell out;
  out.grid = cell.grid;
  out.profile = std::move(cell.profile);
  out.level2_weight = std::move(cell.level_weight[0]);
  out.level2_node = std::move(cell.level_node[0]);
  out.tip1 = cell.tips[0];
  out.tip2 = cell.tips[1];
  return out;
}

double level_share(const PeriodicGrid& grid, const std::vector<double>& weight) {
  double sum = 0.0;
  for (std::size_t k = 0; k < weight.size(); ++k) sum += grid.multiplicity(k) * weight[k];
  return sum / static_cast<double>(grid.nodes());
}

double level2_share(const TwoLevelCell& cell) { return level_share(cell.grid, cell.level2_weight); }

}  // namespace punchsweep::reference
