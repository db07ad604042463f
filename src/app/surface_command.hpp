#pragma once
/// @file
/// `punchsweep surface`: a periodic texture (a square or hexagonal lattice of two or three
/// levels) under a material and a load history, from the elastic load curve of its cell
/// (docs/model.md, section 17): each level's touch (immediate, delayed t*, never), the areas
/// and the sites in contact in time.

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "input/command_options.hpp"
#include "model/problem/cell_geometry.hpp"
#include "model/surface/load_curve.hpp"
#include "model/surface/surface_history.hpp"
#include "model/point/sensitivity.hpp"
#include "reference/cell_stepping.hpp"
#include "reference/measured_cell.hpp"

namespace punchsweep::app {

/// One texture evaluated: its inputs, geometry, curve and history.
struct SurfaceRun {
  input::PointInputs inputs;
  model::LatticeKind lattice = model::LatticeKind::square;
  std::string cell_file;  ///< --cell FILE or --height-map FILE, or empty for a lattice
  std::optional<reference::MeasuredCell> measured;  ///< --height-map: the map's cell and summits
  model::CellGeometry geometry;
  std::vector<double> times;
  int supercell = 1;   ///< K: the cell is K x K lattice cells
  model::HeightScatter scatter;
  int grid_nodes = 0;  ///< nodes per pitch (0: --grid auto, until evaluated)
  model::LoadCurve curve;
  model::SurfaceHistory history;
  double curve_seconds = 0.0;
  bool curve_cached = false;  ///< read from the table cache (app/curve_cache.hpp)
  bool check = false;         ///< --check: step the same cell in time too
  std::vector<model::Tolerance> tolerances;  ///< --tolerance: on the pressure and the law's parameters
  /// Per level: d t*/dx along pbar and the law's parameters (empty for level 0), and the
  /// range of t* over the tolerances (none without).
  std::vector<std::vector<model::TStarDerivative>> derivatives;
  std::vector<std::optional<model::TStarRange>> ranges;
  std::optional<reference::CellReference> stepped;
  double check_seconds = 0.0;
};

/// `punchsweep surface ...`; returns the exit code, throws UsageError for bad input (before
/// printing anything).
int run_surface_command(const std::vector<std::string>& args, std::ostream& out);

/// The texture of `punchsweep surface` given as keywords (Python's), evaluated by the
/// command's own options, checks and code.
SurfaceRun evaluate_surface(const input::Keywords& keywords);

/// The same, as the command's JSON text (what `--format json` prints): Python's surface().
std::string surface_json(const input::Keywords& keywords);

}  // namespace punchsweep::app
