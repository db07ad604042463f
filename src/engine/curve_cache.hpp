#pragma once
/// @file
/// The load curves of textures (docs/model.md, section 17) kept in the table cache
/// (table_cache.hpp) under the same rules as the periodic model's tables: signed files in a
/// private folder, built once per geometry, grid and numerical options.

#include "model/problem/cell_geometry.hpp"
#include "model/surface/load_curve.hpp"
#include "reference/load_curve.hpp"
#include "reference/periodic_grid.hpp"

namespace punchsweep::engine {

/// Where a curve came from.
enum class CurveOrigin { cache, built };

/// The load curve of `geometry` on `cell`'s grid with `options`: read from the table cache
/// where this engine saved one for the same geometry, grid, cell fields (profile, level
/// shares, tips) and options (they are hashed into the file's name and checked inside it), else built and saved there (under a lock,
/// so that processes asking at once build it once). Without a usable cache it is built.
model::LoadCurve load_curve_for(const model::CellGeometry& geometry, const reference::Cell& cell,
                                const reference::LoadCurveOptions& options, CurveOrigin* origin = nullptr);

/// Whether load_curve_for would read this curve from the cache (a dry run's question; it
/// builds nothing and takes no lock).
bool curve_is_cached(const model::CellGeometry& geometry, const reference::Cell& cell, const reference::LoadCurveOptions& options);

}  // namespace punchsweep::engine
