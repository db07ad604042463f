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

/// What a measured map gives: the geometry (its cell, its summits as sites) and the cell.
struct MeasuredCell {
  model::CellGeometry geometry;
  Cell cell;
};

/// The cell of heights `z` (row-major, nx x ny pixels of size `pixel`, in R; nx and ny
/// even), the initial separation max z - z at each node. A summit is a pixel higher than
/// every other within `summit_radius` (periodic; ties to the first); each is a site whose
/// drop is max z - its height and whose shape is the paraboloid of its mean curvature
/// there (s = 2, C = -(z_xx + z_yy) / 4 by central differences; only the curve's first
/// sample and the areas below it use it). Levels: sorted by drop, a gap between drops of
/// more than `level_gap` starts a new level (+infinity: one level); each node belongs to
/// the level of the summit it climbs to (the cap whose surface is highest there). A radius
/// of a period or more leaves the highest pixel the one summit. Throws std::invalid_argument for odd sizes or a radius under
/// one pixel.
MeasuredCell make_measured_cell(const std::vector<double>& z, std::size_t nx, std::size_t ny, double pixel,
                                double summit_radius, double level_gap);

}  // namespace punchsweep::reference
