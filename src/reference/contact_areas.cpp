#include "reference/contact_areas.hpp"

#include <algorithm>

namespace punchsweep::reference {

namespace {

/// How far past a node in contact, in grid spacings along one axis, the contact's edge lies
/// when the next node on is free: where p^2, extrapolated linearly from that node (p_edge)
/// and the one behind it (p_inner), reaches zero (a smooth contact's pressure falls as the
/// square root of the distance to its edge), within [0, 1]; 1/2, the node's own half
/// square, where the pressure does not fall towards the edge.
double edge_offset(double p_edge, double p_inner) {
  if (!(p_inner > p_edge)) return 0.5;
  return std::clamp(p_edge * p_edge / (p_inner * p_inner - p_edge * p_edge), 0.0, 1.0);
}

/// The node's neighbour index along one axis on a grid of `n` nodes: periodic, or under
/// mirror symmetry (stored 0 .. n/2) reflected at both ends.
int neighbour(int i, int step, int n, bool mirrored) {
  const int k = i + step;
  if (!mirrored) return (k % n + n) % n;
  if (k < 0) return -k;
  if (2 * k > n) return n - k;
  return k;
}

}  // namespace

std::vector<double> level_contact_areas(const PeriodicGrid& g, const std::vector<std::vector<double>>& level_weight,
                                        std::span<const double> p, std::span<const double> rims) {
  const bool mirrored_x = g.mirrored_x(), mirrored_y = g.mirrored_y();
  std::vector<double> area(level_weight.size() + 1, 0.0);
  for (int i = 0; i < g.stored_nx(); ++i) {
    for (int j = 0; j < g.stored_ny(); ++j) {
      const std::size_t k = g.index(i, j);
      if (!(p[k] > 0.0)) continue;
      // The node's square, moved at each free neighbour to where the edge lies, half from
      // the rows' estimate and half from the columns'.
      double nodes = 1.0;
      for (const int step : {-1, 1}) {
        if (!(p[g.index(neighbour(i, step, g.nx, mirrored_x), j)] > 0.0)) {
          nodes += 0.5 * (edge_offset(rims[k], rims[g.index(neighbour(i, -step, g.nx, mirrored_x), j)]) - 0.5);
        }
        if (!(p[g.index(i, neighbour(j, step, g.ny, mirrored_y))] > 0.0)) {
          nodes += 0.5 * (edge_offset(rims[k], rims[g.index(i, neighbour(j, -step, g.ny, mirrored_y))]) - 0.5);
        }
      }
      const double m = g.multiplicity(k) * nodes;
      double others = 0.0;
      for (std::size_t level = 0; level < level_weight.size(); ++level) {
        area[level + 1] += m * level_weight[level][k];
        others += level_weight[level][k];
      }
      area[0] += m * (1.0 - others);
    }
  }
  for (double& a : area) a *= g.cell_area();
  return area;
}

std::vector<double> level_loads(const PeriodicGrid& g, const std::vector<std::vector<double>>& level_weight,
                                std::span<const double> p) {
  std::vector<double> load(level_weight.size() + 1, 0.0);
  for (std::size_t k = 0; k < g.size(); ++k) {
    const double m = g.multiplicity(k);  // 1 on a whole grid: the plain sums
    double others = 0.0;
    for (std::size_t level = 0; level < level_weight.size(); ++level) {
      load[level + 1] += m * (level_weight[level][k] * p[k]);
      others += level_weight[level][k];
    }
    load[0] += m * ((1.0 - others) * p[k]);
  }
  for (double& q : load) q *= g.cell_area();
  return load;
}

}  // namespace punchsweep::reference
