#pragma once
/// @file
/// `punchsweep surface`: a periodic texture (a square or hexagonal lattice of two or three
/// levels, a cell file, a measured map, a scattered supercell) under a material and a load
/// history, from the elastic load curve of its cell (docs/model.md, section 17): each
/// level's touch (immediate, delayed t*, never), the areas and the sites in contact in time.

#include <boost/program_options/options_description.hpp>

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "app/surface_run.hpp"
#include "input/command_options.hpp"

namespace punchsweep::app {

/// The most boundary-element nodes a pitch a texture's curve (or design) is solved on.
inline constexpr int kMaxGridNodes = 2048;

/// --grid TEXT: an even number of nodes a pitch in [4, kMaxGridNodes], or 0 for "auto";
/// UsageError naming the value and the range otherwise.
int read_grid(const std::string& text);

/// The command's options (the point's for `material`'s law, the texture's, the grid's):
/// `surface-map` takes the same.
boost::program_options::options_description surface_options(const input::PointMaterial& material);

/// `punchsweep surface ...`; returns the exit code, throws UsageError for bad input (before
/// printing anything).
int run_surface_command(const std::vector<std::string>& args, std::ostream& out);

/// Each level's touch at more load points than the run's own, read off a curve of the run's
/// texture (surface-map's pressures and law values, one row a point): `--grid auto` holds
/// every one of them to its accuracy, as it holds the run's own.
using MoreLoadPoints = std::function<std::vector<std::vector<model::LevelTouch>>(const SurfaceRun&, const model::LoadCurve&)>;

/// The texture of `punchsweep surface` given as keywords (Python's), evaluated by the
/// command's own options, checks and code; `also_held`: the load points --grid auto holds
/// beside the run's own.
SurfaceRun evaluate_surface(const input::Keywords& keywords, const MoreLoadPoints& also_held = {});

/// Reads `keywords` as evaluate_surface does and throws input::UsageError for what it would
/// refuse before building anything: a bad or missing option, a cell whose scales the
/// boundary elements cannot take, a grid beyond the engine's budget. No curve is built.
void check_surface(const input::Keywords& keywords);

/// The same, as the command's JSON text (what `--format json` prints): Python's surface().
std::string surface_json(const input::Keywords& keywords);

}  // namespace punchsweep::app
