#include "model/problem/cell_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace punchsweep::model {

int CellGeometry::levels() const {
  int top = -1;
  for (const Site& site : sites) top = std::max(top, site.level);
  return top + 1;
}

std::string geometry_error(const CellGeometry& g) {
  std::ostringstream out;
  out.precision(17);
  if (!(std::isfinite(g.Lx) && g.Lx > 0.0 && std::isfinite(g.Ly) && g.Ly > 0.0)) {
    out << "cell " << g.Lx << " x " << g.Ly << " R is outside its range: Lx, Ly finite and > 0";
    return out.str();
  }
  if (g.sites.empty()) return "the cell has no site: it needs at least one punch";
  std::vector<bool> seen(static_cast<std::size_t>(std::max(g.levels(), 0)), false);
  for (std::size_t k = 0; k < g.sites.size(); ++k) {
    const Site& site = g.sites[k];
    out << "site " << k << ": ";
    if (!(site.x >= 0.0 && site.x < g.Lx && site.y >= 0.0 && site.y < g.Ly)) {
      out << "(" << site.x << ", " << site.y << ") R is outside the cell: 0 <= x < " << g.Lx << ", 0 <= y < " << g.Ly;
      return out.str();
    }
    if (site.shape.s < Shape::kMinExponent || site.shape.s > Shape::kMaxExponent) {
      out << "s = " << site.shape.s << " is outside its range: an integer in [" << Shape::kMinExponent << ", "
          << Shape::kMaxExponent << "]";
      return out.str();
    }
    if (!(std::isfinite(site.shape.C) && site.shape.C > 0.0)) {
      out << "C = " << site.shape.C << " is outside its range: C > 0";
      return out.str();
    }
    if (!(std::isfinite(site.drop) && site.drop >= 0.0)) {
      out << "drop = " << site.drop << " R is outside its range: finite and >= 0";
      return out.str();
    }
    if (site.level < 0) {
      out << "level = " << site.level << " is outside its range: >= 0";
      return out.str();
    }
    seen[static_cast<std::size_t>(site.level)] = true;
    out.str("");
  }
  for (std::size_t level = 0; level < seen.size(); ++level) {
    if (!seen[level]) {
      out << "level " << level << " has no site: the levels are numbered 0 .. " << seen.size() - 1 << " without gaps";
      return out.str();
    }
  }
  return {};
}

CellGeometry two_level_square(const ContactProblem& problem) {
  const double half = 0.5 * problem.l;
  return {problem.l, problem.l, {Site{0.0, 0.0, problem.shape, 0.0, 0}, Site{half, half, problem.shape, problem.dh, 1}}};
}

}  // namespace punchsweep::model
