#include "reference/measured_cell.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace punchsweep::reference {

MeasuredCell make_measured_cell(const std::vector<double>& z, std::size_t nx, std::size_t ny, double pixel,
                                double summit_radius, double level_gap) {
  if (nx % 2 != 0 || ny % 2 != 0 || nx < 4 || ny < 4 || z.size() != nx * ny) {
    throw std::invalid_argument("make_measured_cell: an even number of pixels each way, at least 4");
  }
  if (!(pixel > 0.0 && std::isfinite(pixel)) || !(summit_radius >= pixel)) {
    throw std::invalid_argument("make_measured_cell: pixel > 0 and a summit radius of at least one pixel");
  }
  const int NX = static_cast<int>(nx), NY = static_cast<int>(ny);
  const auto at = [&](int i, int j) { return z[static_cast<std::size_t>(((j % NY) + NY) % NY) * nx + static_cast<std::size_t>(((i % NX) + NX) % NX)]; };
  const double top = *std::max_element(z.begin(), z.end());
  // Summits: higher than every pixel within the radius (ties: the earlier pixel wins).
  const int reach = static_cast<int>(std::floor(summit_radius / pixel));
  struct Summit {
    int i, j;
    double drop;
  };
  std::vector<Summit> summits;
  for (int j = 0; j < NY; ++j) {
    for (int i = 0; i < NX; ++i) {
      const double h = at(i, j);
      bool highest = true;
      for (int dj = -reach; dj <= reach && highest; ++dj) {
        for (int di = -reach; di <= reach && highest; ++di) {
          if ((di == 0 && dj == 0) || di * di + dj * dj > reach * reach) continue;
          const double other = at(i + di, j + dj);
          // A tie goes to the pixel first in row order (within the periodic cell).
          const int oi = ((i + di) % NX + NX) % NX, oj = ((j + dj) % NY + NY) % NY;
          highest = other < h || (other == h && (oj > j || (oj == j && oi > i)));
        }
      }
      if (highest) summits.push_back({i, j, top - h});
    }
  }
  // Levels by drop: a gap of more than level_gap between consecutive drops starts one.
  std::vector<std::size_t> order(summits.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return summits[a].drop < summits[b].drop; });
  std::vector<int> level(summits.size(), 0);
  for (std::size_t k = 1; k < order.size(); ++k) {
    const bool gap = summits[order[k]].drop - summits[order[k - 1]].drop > level_gap;
    level[order[k]] = level[order[k - 1]] + (gap ? 1 : 0);
  }
  MeasuredCell out;
  model::CellGeometry& g = out.geometry;
  g.Lx = NX * pixel;
  g.Ly = NY * pixel;
  for (std::size_t k = 0; k < summits.size(); ++k) {
    const Summit& s = summits[k];
    const double zxx = (at(s.i + 1, s.j) - 2.0 * at(s.i, s.j) + at(s.i - 1, s.j)) / (pixel * pixel);
    const double zyy = (at(s.i, s.j + 1) - 2.0 * at(s.i, s.j) + at(s.i, s.j - 1)) / (pixel * pixel);
    const double C = std::max(-(zxx + zyy) / 4.0, 1e-12);
    g.sites.push_back(model::Site{s.i * pixel, s.j * pixel, model::Shape{2, C}, s.drop, level[k]});
  }
  // The grid: one node per pixel, node (i, j) at (i pixel, j pixel); the grid's index is
  // i ny + j, the map's j nx + i.
  Cell& cell = out.cell;
  cell.grid = PeriodicGrid{NX, NY, g.Lx, g.Ly, Symmetry::none};
  const PeriodicGrid& grid = cell.grid;
  cell.profile.resize(grid.size());
  for (int i = 0; i < NX; ++i) {
    for (int j = 0; j < NY; ++j) cell.profile[grid.index(i, j)] = top - at(i, j);
  }
  for (const Summit& s : summits) cell.tips.push_back(grid.index(s.i, s.j));
  const int levels = g.levels();
  cell.level_weight.assign(static_cast<std::size_t>(std::max(levels - 1, 0)), std::vector<double>(grid.size(), 0.0));
  cell.level_node.assign(static_cast<std::size_t>(std::max(levels - 1, 0)), std::vector<char>(grid.size(), 0));
  if (levels > 1) {
    for (int i = 0; i < NX; ++i) {
      for (int j = 0; j < NY; ++j) {
        double nearest = std::numeric_limits<double>::infinity();
        int owner = 0;
        for (std::size_t k = 0; k < summits.size(); ++k) {
          const double d = std::hypot(periodic_offset((i - summits[k].i) * pixel, g.Lx), periodic_offset((j - summits[k].j) * pixel, g.Ly));
          if (d < nearest) {
            nearest = d;
            owner = level[k];
          }
        }
        if (owner > 0) {
          cell.level_weight[static_cast<std::size_t>(owner - 1)][grid.index(i, j)] = 1.0;
          cell.level_node[static_cast<std::size_t>(owner - 1)][grid.index(i, j)] = 1;
        }
      }
    }
  }
  return out;
}

}  // namespace punchsweep::reference
