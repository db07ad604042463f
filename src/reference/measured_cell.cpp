#include "reference/measured_cell.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace punchsweep::reference {

MeasuredCell make_measured_cell(const std::vector<double>& z, std::size_t nx, std::size_t ny, double pixel,
                                double summit_radius, double level_gap, double least_prominence) {
  if (nx % 2 != 0 || ny % 2 != 0 || nx < 4 || ny < 4 || z.size() != nx * ny) {
    throw std::invalid_argument("make_measured_cell: an even number of pixels each way, at least 4");
  }
  if (!(pixel > 0.0 && std::isfinite(pixel)) || !(summit_radius >= pixel)) {
    throw std::invalid_argument("make_measured_cell: pixel > 0 and a summit radius of at least one pixel");
  }
  if (!(least_prominence >= 0.0)) throw std::invalid_argument("make_measured_cell: a prominence >= 0");
  const int NX = static_cast<int>(nx), NY = static_cast<int>(ny);
  const auto index = [&](int i, int j) {
    return static_cast<std::size_t>(((j % NY) + NY) % NY) * nx + static_cast<std::size_t>(((i % NX) + NX) % NX);
  };
  const auto at = [&](int i, int j) { return z[index(i, j)]; };
  const double top = *std::max_element(z.begin(), z.end());
  // Pixels in one total order: the higher first, a tie to the pixel first in row order.
  const auto beats = [&](std::size_t a, std::size_t b) { return z[a] > z[b] || (z[a] == z[b] && a < b); };
  // The disc of the summit radius as offsets, nearest first (a pixel that is no summit
  // meets one that beats it early); each other pixel once: offsets within half the cell.
  const int reach = static_cast<int>(std::min(std::floor(summit_radius / pixel), static_cast<double>(NX + NY)));
  const int rx = std::min(reach, NX / 2), ry = std::min(reach, NY / 2);
  std::vector<std::pair<int, int>> disc;
  for (int dj = -ry; dj <= ry; ++dj) {
    for (int di = -rx; di <= rx; ++di) {
      const bool twice = 2 * di == -NX || 2 * dj == -NY;  // the same pixel as +NX/2 (+NY/2)
      if ((di != 0 || dj != 0) && !twice && static_cast<long>(di) * di + static_cast<long>(dj) * dj <= static_cast<long>(reach) * reach) {
        disc.emplace_back(di, dj);
      }
    }
  }
  std::stable_sort(disc.begin(), disc.end(),
                   [](const auto& a, const auto& b) { return a.first * a.first + a.second * a.second < b.first * b.first + b.second * b.second; });
  // Each pixel climbs to a summit (the watershed of the heights turned over): to its best
  // neighbour (the disc's nearest ring) while one beats it, from a local top to the first
  // pixel of its disc that beats it. A pixel is thus the summit's whose cap is highest
  // there, the surface lowest, as the lattice's cells assign their nodes (for caps, the
  // climb stays on one cap's surface), not its nearest summit's, which a tall cap's
  // contact crosses.
  std::vector<std::size_t> up(z.size());
  for (int j = 0; j < NY; ++j) {
    for (int i = 0; i < NX; ++i) {
      const std::size_t k = index(i, j);
      std::size_t best = k;
      for (const auto& [di, dj] : disc) {
        if (std::abs(di) > 1 || std::abs(dj) > 1) break;  // (nearest first: the ring is done)
        if (const std::size_t q = index(i + di, j + dj); beats(q, best)) best = q;
      }
      up[k] = best;
    }
  }
  // Each pixel's prominence, by joining the pixels from the highest down (8-connected,
  // periodic) into grounds, each named by its peak: a pixel none of whose neighbours came
  // before it is a peak of its own; where grounds meet at pixel p, each but the one of the
  // highest peak ends there, its peak rising z(peak) - z(p) above the highest saddle on any
  // path to higher ground, which `higher` names (a pixel that is no peak rises 0, next to
  // higher ground). The highest peak rises +infinity.
  std::vector<std::size_t> by_height(z.size());
  std::iota(by_height.begin(), by_height.end(), 0);
  std::sort(by_height.begin(), by_height.end(), beats);
  constexpr double kHighest = std::numeric_limits<double>::infinity();
  std::vector<std::size_t> ground(z.size(), z.size());  // union-find: z.size() not yet reached
  std::vector<std::size_t> higher(z.size(), z.size());
  std::vector<double> prominence(z.size(), 0.0);
  const auto find = [&](std::size_t a) {
    while (ground[a] != a) a = ground[a] = ground[ground[a]];
    return a;
  };
  for (const std::size_t p : by_height) {
    const int i = static_cast<int>(p % nx), j = static_cast<int>(p / nx);
    std::array<std::size_t, 8> met{};
    std::size_t count = 0;
    for (int dj = -1; dj <= 1; ++dj) {
      for (int di = -1; di <= 1; ++di) {
        const std::size_t q = index(i + di, j + dj);
        if ((di == 0 && dj == 0) || ground[q] == z.size()) continue;
        const std::size_t g = find(q);
        if (std::find(met.begin(), met.begin() + count, g) == met.begin() + count) met[count++] = g;
      }
    }
    if (count == 0) {
      ground[p] = p;
      prominence[p] = kHighest;
      continue;
    }
    const std::size_t best = *std::min_element(met.begin(), met.begin() + count, beats);
    ground[p] = best;
    higher[p] = best;
    for (std::size_t m = 0; m < count; ++m) {
      if (met[m] == best) continue;
      prominence[met[m]] = z[met[m]] - z[p];
      higher[met[m]] = best;
      ground[met[m]] = best;
    }
  }
  struct Summit {
    int i, j;
    double drop, prominence;
  };
  std::vector<Summit> summits;
  std::vector<std::size_t> summit_of(z.size(), z.size());
  std::vector<std::size_t> tops;  // pixels no pixel of their disc beats, in row order
  for (int j = 0; j < NY; ++j) {
    for (int i = 0; i < NX; ++i) {
      const std::size_t k = index(i, j);
      if (up[k] != k) continue;  // not even a local top
      for (const auto& [di, dj] : disc) {
        if (const std::size_t q = index(i + di, j + dj); beats(q, k)) {
          up[k] = q;
          break;
        }
      }
      if (up[k] == k) tops.push_back(k);
    }
  }
  // A flat top (8-connected pixels of exactly one height) is one summit however wide: the
  // row order's tie rule would make a second where the top wraps round the cell's edge (a
  // flat cap at a corner gave two). Its other tops climb to its first in row order (which
  // beats them: the same height, earlier). Its prominence is its first pixel's (the first
  // joined); a top that rises less than least_prominence climbs on to the higher ground.
  std::vector<char> on_top(z.size(), 0);
  for (const std::size_t k : tops) on_top[k] = 1;
  std::vector<char> filled(z.size(), 0);
  std::vector<std::size_t> front;
  std::size_t below = 0;
  for (const std::size_t k : tops) {
    if (up[k] != k) continue;  // merged into an earlier top
    const int i = static_cast<int>(k % nx), j = static_cast<int>(k / nx);
    std::size_t first = k;
    front.assign(1, k);
    filled[k] = 1;
    while (!front.empty()) {
      const std::size_t q = front.back();
      front.pop_back();
      first = std::min(first, q);
      if (on_top[q] && q != k) up[q] = k;
      const int qi = static_cast<int>(q % nx), qj = static_cast<int>(q / nx);
      for (int dj = -1; dj <= 1; ++dj) {
        for (int di = -1; di <= 1; ++di) {
          const std::size_t r = index(qi + di, qj + dj);
          if (!filled[r] && z[r] == z[k]) {
            filled[r] = 1;
            front.push_back(r);
          }
        }
      }
    }
    if (prominence[first] < least_prominence) {
      up[k] = higher[first];  // strictly higher: a flat top's first pixel ends only below it
      ++below;
      continue;
    }
    summit_of[k] = summits.size();
    summits.push_back({i, j, top - z[k], prominence[first]});
  }
  // Each pixel's summit: follow the climb (every step beats the last, so it ends), then
  // give the path its end.
  std::vector<std::size_t> path;
  for (std::size_t k = 0; k < z.size(); ++k) {
    std::size_t q = k;
    path.clear();
    while (summit_of[q] == z.size()) {
      path.push_back(q);
      q = up[q];
    }
    for (const std::size_t p : path) summit_of[p] = summit_of[q];
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
  out.height_range = top - *std::min_element(z.begin(), z.end());
  out.least_prominence = least_prominence;
  out.summits_below = below;
  for (const Summit& summit : summits) out.prominence.push_back(summit.prominence);
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
  cell.tip_exposed.assign(summits.size(), 1);  // a summit is the highest pixel about it
  const int levels = g.levels();
  cell.level_weight.assign(static_cast<std::size_t>(std::max(levels - 1, 0)), std::vector<double>(grid.size(), 0.0));
  cell.level_node.assign(static_cast<std::size_t>(std::max(levels - 1, 0)), std::vector<char>(grid.size(), 0));
  if (levels > 1) {
    for (int i = 0; i < NX; ++i) {
      for (int j = 0; j < NY; ++j) {
        const int owner = level[summit_of[index(i, j)]];
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
