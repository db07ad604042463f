#pragma once
/// @file
/// The contact area of a pressure field on a periodic grid, split between the levels of a
/// cell (docs/model.md, section 13.1). Units: lengths in R.

#include <span>
#include <vector>

#include "reference/periodic_grid.hpp"

namespace punchsweep::reference {

/// The contact areas of the contact set {p > 0} per level, in R^2: each node in contact
/// counts its square, split between the levels by `level_weight` (for each level from 1 on,
/// each node's share in it, Cell::level_weight; level 0 has what the others leave), with the
/// square's sides moved, where the next node is free, to the edge that rims^2 extrapolated
/// linearly from the last two nodes places between them, averaged over the rows' and the
/// columns' estimates. `rims` is a field that falls as the square root of the distance to a
/// smooth contact's edge: the pressure of an elastic solve, and under creep the
/// creep-scaled pressure w = int J dp (the elastic pressure at the creep-weighted load,
/// while the contact grows), not p, whose rim is a history of such falls. Against Hertz on
/// spots of radius a = 4 to 32 grid spacings h (tests/reference), counting the pressed
/// nodes is off by 0.11-0.27 h/a and jumps as the rim crosses nodes; this estimate by
/// 0.03-0.13 h/a (the grid's pressure itself departs from the square root at the last node
/// or two), and moves smoothly with the load, which is what curves and tables interpolated
/// between loads need. Returns one area per level (level_weight.size() + 1).
std::vector<double> level_contact_areas(const PeriodicGrid& grid, const std::vector<std::vector<double>>& level_weight,
                                        std::span<const double> p, std::span<const double> rims);

/// The load each level carries under the pressure p, in R^2 E0*: the sum over the nodes of
/// the pressure times each level's share of the node's square (`level_weight` as for
/// level_contact_areas; level 0 what the others leave), times the square's area. One load
/// per level (level_weight.size() + 1); they sum to the mean pressure times the cell.
std::vector<double> level_loads(const PeriodicGrid& grid, const std::vector<std::vector<double>>& level_weight,
                                std::span<const double> p);

}  // namespace punchsweep::reference
