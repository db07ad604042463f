#pragma once
/// @file
/// The load curves of textures (docs/model.md, section 17) kept in the table cache
/// (table_cache.hpp) under the same rules as the periodic model's tables: signed files in a
/// private folder, built once per geometry, grid and numerical options.

#include <functional>

#include "model/problem/cell_geometry.hpp"
#include "model/surface/load_curve.hpp"
#include "reference/load_curve.hpp"
#include "reference/periodic_grid.hpp"

namespace punchsweep::engine {

/// Where a curve came from.
/// (extended: a saved curve that stopped short, continued from where it stopped.)
enum class CurveOrigin { cache, built, extended };

/// The load curve of `geometry` on `grid` with `options`: read from the table cache where
/// this engine saved one for the same geometry, grid, options and cell (they are hashed
/// into the file's name and checked inside it: a measured map's cell by its fields, a cell
/// made from the geometry by how cells are made), else built on `cell()` and saved there
/// (under a lock, so that processes asking at once build it once). `cell` is called only
/// to build: a cached curve is read in milliseconds, without its cell. `measured`: a
/// measured map's cell (its heights are data), else null. Without a usable cache it is
/// built.
///
/// The key leaves out options.X_reach: a saved curve that reaches as far (to full contact,
/// or a march that stopped at or past this one's end) is read and cut where the march for
/// this reach stops (model::LoadCurve::up_to at reference::march_end), which gives the curve
/// built for it, bit for bit; one that stops short is continued to this reach from where it
/// stopped (its front, saved beside it: the pressure and the sites' closures at its last
/// sample), which gives the curve built for the new reach, bit for bit, at the cost of the
/// part past the old end (from the start where no front is saved), and saved in its place.
model::LoadCurve load_curve_for(const model::CellGeometry& geometry, const reference::PeriodicGrid& grid,
                                const reference::LoadCurveOptions& options, const reference::Cell* measured,
                                const std::function<const reference::Cell&()>& cell, CurveOrigin* origin = nullptr);

/// What the cache holds of a curve: nothing load_curve_for would use, the curve as far as
/// `options` reach (read, not built), or its beginning with its front (continued from
/// X_last: only the rest is built).
struct CachedCurve {
  enum class Holds { nothing, whole, beginning } holds = Holds::nothing;
  double X_first = 0.0, X_last = 0.0;  ///< the saved curve's extent (E0*), where one is saved
};

/// What load_curve_for would find in the cache for this curve (a dry run's question; it
/// builds nothing, makes no cell and takes no lock).
CachedCurve cached_curve(const model::CellGeometry& geometry, const reference::PeriodicGrid& grid,
                         const reference::LoadCurveOptions& options, const reference::Cell* measured);

}  // namespace punchsweep::engine
