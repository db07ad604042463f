#include "model/surface/surface_advisory.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace punchsweep::model {

SurfaceAdvisories advise_surface(const CellGeometry& geometry, const SurfaceHistory& history) {
  if (history.snapshots.empty()) {
    SurfaceAdvisories none;
    none.level.assign(static_cast<std::size_t>(geometry.levels()), Advisories{});
    return none;
  }
  return advise_surface(geometry, history.snapshots.back().state);
}

SurfaceAdvisories advise_surface(const CellGeometry& geometry, const CurveState& last) {
  const std::size_t L = static_cast<std::size_t>(geometry.levels());
  SurfaceAdvisories out;
  out.level.assign(L, Advisories{});
  std::vector<int> sites(L, 0);
  for (const Site& site : geometry.sites) ++sites[static_cast<std::size_t>(site.level)];
  for (std::size_t level = 0; level < L; ++level) {
    const double touching = std::round(last.level_sites_touched[level] * sites[level]);
    const double area = last.level_area[level];
    if (!(touching >= 1.0) || !(area > 0.0)) continue;
    const double radius = std::sqrt(area / (std::numbers::pi * touching));
    // The level's shapes (a lattice's one; a cell file's may differ site by site): the most
    // strained speaks for the level.
    bool first = true;
    for (const Site& site : geometry.sites) {
      if (static_cast<std::size_t>(site.level) != level) continue;
      const Advisories a = advise(site.shape, radius);
      if (first || a.strain > out.level[level].strain) out.level[level] = a;
      first = false;
    }
  }
  for (const Advisories& a : out.level) {
    out.all.a_max = std::max(out.all.a_max, a.a_max);
    out.all.strain = std::max(out.all.strain, a.strain);
    for (const Advisory r : a.raised) {
      if (std::find(out.all.raised.begin(), out.all.raised.end(), r) == out.all.raised.end()) out.all.raised.push_back(r);
    }
  }
  std::sort(out.all.raised.begin(), out.all.raised.end());
  return out;
}

std::size_t SurfaceAdvisories::widest() const {
  std::size_t widest = 0;
  for (std::size_t level = 0; level < this->level.size(); ++level) {
    if (this->level[level].a_max > this->level[widest].a_max) widest = level;
  }
  return widest;
}

}  // namespace punchsweep::model
