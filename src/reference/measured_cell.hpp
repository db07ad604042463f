#pragma once
/// @file
/// A measured texture: the height map of one period (input::HeightMap's grid, one node per
/// pixel) as a cell of the boundary elements, its summits as the sites whose touch is
/// followed (docs/model.md, section 17.1). Units: lengths in R.

#include <cstddef>
#include <vector>

#include "model/problem/cell_geometry.hpp"
#include "reference/periodic_grid.hpp"

namespace punchsweep::reference {

/// What a measured map gives: the geometry (its cell, its summits as sites) and the cell,
/// and how its summits were told from the land's roughness.
struct MeasuredCell {
  model::CellGeometry geometry;
  Cell cell;
  /// Each site's topographic prominence (in R): how far its summit rises above the highest
  /// saddle on any path to higher ground (+infinity for the highest).
  std::vector<double> prominence;
  double height_range = 0.0;      ///< max z - min z, in R
  double least_prominence = 0.0;  ///< the prominence a summit needed, in R
  std::size_t summits_below = 0;  ///< summits that rose less, taken as part of higher ground
};

/// The share of the map's height range (max z - min z) a summit must rise above its saddle
/// to higher ground by default: land roughness a fiftieth of the relief or less is no cap.
inline constexpr double kDefaultProminenceShare = 0.02;

/// The cell of heights `z` (row-major, nx x ny pixels of size `pixel`, in R; nx and ny
/// even), the initial separation max z - z at each node. A summit is a pixel higher than
/// every other within `summit_radius` (periodic; ties to the first) that rises at least
/// `least_prominence` above the highest saddle on any path to higher ground (its
/// topographic prominence, 8-connected, periodic; 0 keeps every summit; a flat top is one
/// summit); a summit that rises less is part of the higher ground it joins at that saddle.
/// Each is a site whose drop is max z - its height and whose shape is the paraboloid of its
/// mean curvature there (s = 2, C = -(z_xx + z_yy) / 4 by central differences; only the
/// curve's first sample and the areas below it use it). Levels: sorted by drop, a gap
/// between drops of more than `level_gap` starts a new level (+infinity: one level); each
/// node belongs to the level of the summit it climbs to (the cap whose surface is highest
/// there). A radius of a period or more leaves the highest pixel the one summit. Throws
/// std::invalid_argument for odd sizes, a radius under one pixel or a negative prominence.
MeasuredCell make_measured_cell(const std::vector<double>& z, std::size_t nx, std::size_t ny, double pixel,
                                double summit_radius, double level_gap, double least_prominence = 0.0);

}  // namespace punchsweep::reference
