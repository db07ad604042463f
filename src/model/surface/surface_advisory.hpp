#pragma once
/// @file
/// The physical advisories of a texture's answer (docs/model.md, section 16), as `point`
/// gives them for the paper's lattice: where a valid answer stands for less than it seems
/// because a cap's contact has grown past the paraboloid that stands for a sphere, or the
/// strain past linear viscoelasticity.

#include <vector>

#include "model/point/advisory.hpp"
#include "model/problem/cell_geometry.hpp"
#include "model/surface/surface_history.hpp"

namespace punchsweep::model {

/// Per level, the contact radius of its caps at the last snapshot (radii only grow while the
/// contact does: the answer holds no later), and the advisories over all levels.
struct SurfaceAdvisories {
  /// Per level, the advisories of its caps (model::advise on the level's shape, the most
  /// strained of its shapes where its caps differ). Their a_max is the level's contact
  /// radius, in R: its contact area over pi times its caps in contact, sqrt(A / (pi n)) (each
  /// cap's radius on a lattice, whose caps of a level are equal; their root-mean-square where
  /// heights scatter); 0 where none touches.
  std::vector<Advisories> level;
  /// Over all levels: a_max and strain the largest, `raised` every advisory any level raises.
  Advisories all;
  /// The level of the widest caps (the least such level; 0 where none touches).
  std::size_t widest() const;
};

/// The advisories of `history` on `geometry` (no snapshots: none).
SurfaceAdvisories advise_surface(const CellGeometry& geometry, const SurfaceHistory& history);
/// The same from the cell's state at the last time alone (what a map reads per load point).
SurfaceAdvisories advise_surface(const CellGeometry& geometry, const CurveState& last);

}  // namespace punchsweep::model
