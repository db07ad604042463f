#pragma once
/// @file
/// A texture's evaluation, as `punchsweep surface`, `design`, a texture's map and Python's
/// surface() and surface_classify() share it: a periodic texture (a square or hexagonal
/// lattice of two or three levels, a cell file, a measured map, a scattered supercell) read
/// from its options, its cell's elastic load curve built (or read from the cache or off the
/// periodic tables), and each level's touch, the areas and the sites in contact in time
/// under the material and the load history (docs/model.md, section 17).

#include <boost/program_options/options_description.hpp>
#include <boost/program_options/variables_map.hpp>

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "input/command_options.hpp"
#include "model/surface/geometry_parts.hpp"
#include "reference/periodic_grid.hpp"
#include "engine/surface_run.hpp"

namespace punchsweep::engine {

/// The most boundary-element nodes a pitch a texture's curve (or design) is solved on.
inline constexpr int kMaxGridNodes = 2048;

/// --grid TEXT: an even number of nodes a pitch in [4, kMaxGridNodes], or 0 for "auto";
/// UsageError naming the value and the range otherwise.
int read_grid(const std::string& text);

/// Seconds as progress lines say them: "4.1 s", "105 s" (two or three digits).
std::string seconds_text(double s);

/// This machine's memory, in bytes (0 where the system does not say): a curve's budget and a
/// texture map's dry run hold to it.
double machine_bytes();

/// The texture's options (the point's for `material`'s law, the texture's, the grid's):
/// `surface`, `design`, a texture's sweep and Python's surface() take the same.
boost::program_options::options_description surface_options(const input::PointMaterial& material);

/// More load points than the run's own that read the run's curve (a texture map's pressures
/// and law values, Python's arrays, a design's window): how far they reach, and each
/// level's touch at each of them.
struct MoreLoadPoints {
  /// The largest creep-weighted load they read, X(inf) at the most (E0*), given the run as
  /// read (its point fills what the points do not set): the curve reaches it as well as the
  /// run's own (SurfaceRun::X_reach); +infinity for the whole curve. Empty: none beyond the
  /// run's own.
  std::function<double(const SurfaceRun&)> X_reach;
  /// Each level's touch at each point off a curve of the run's texture (one row a point):
  /// `--grid auto` holds every one of them to its accuracy, as it holds the run's own.
  /// Empty: none held.
  std::function<std::vector<std::vector<model::LevelTouch>>(const SurfaceRun&, const model::LoadCurve&)> touches;

  /// Points at any load: the whole curve, to full contact (a design's window, a reader that
  /// does not say how far it reads).
  static MoreLoadPoints any_load() {
    return {[](const SurfaceRun&) { return std::numeric_limits<double>::infinity(); }, {}};
  }
};

/// --grid auto's top (nodes a pitch), and the accuracy it holds each level's t* to: the
/// share of itself t* may move from the grid of half the nodes to the one taken.
inline constexpr int kAutoMaxNodes = 512;
inline constexpr double kAutoTStarAccuracy = 1e-3;

/// The texture of `given` (parsed by surface_options(material)) read and checked, not yet
/// evaluated: its inputs, geometry, times, grid and switches. `material` must outlive it
/// (the run's law points into it). Throws input::UsageError for a bad or missing option.
SurfaceRun read_surface(const boost::program_options::variables_map& given, const input::PointMaterial& material);

/// Evaluates `run` (read_surface's): its load curve (built on the cell's boundary elements,
/// read from the table cache or off the periodic tables), under --grid auto held to its
/// accuracy, then the history at its times and the checks asked. `progress`: the curve's
/// solves said on stderr.
void evaluate(SurfaceRun& run, bool progress, const MoreLoadPoints& also_held = {});

/// The texture of `punchsweep surface` given as keywords (Python's), evaluated by the
/// command's own options, checks and code; `also_held`: the load points --grid auto holds
/// beside the run's own.
SurfaceRun evaluate_surface(const input::Keywords& keywords, const MoreLoadPoints& also_held = {});

/// The ensemble of `run` (read_surface's, run.seeds > 1): the run evaluated as it is (the
/// first draw) and again with each later seed, re-read from `given` with the seed changed.
/// The first stays in `run`.
SurfaceEnsemble evaluate_ensemble(SurfaceRun& run, const boost::program_options::variables_map& given,
                                  const input::PointMaterial& material, bool progress);

/// The ensemble of `punchsweep surface`'s keywords (Python's surface(seeds=N)): its first
/// draw's run and the ensemble (empty for one seed).
std::pair<SurfaceRun, std::optional<SurfaceEnsemble>> evaluate_surface_ensemble(const input::Keywords& keywords);

/// A texture's parts (model::GeometryParts) and the run they come from.
struct TextureParts {
  SurfaceRun run;  ///< read_surface's (evaluated where the parts are a curve, which is moved into them)
  std::unique_ptr<model::GeometryParts> parts;
};

/// The parts of the texture of `keywords`: the one choice between a localization model and
/// a load curve. The paper's two-level square lattice, where the periodic model's tables
/// reach its dh (--curve auto or tables), by the periodic localization (model::touchdown: no
/// curve is made); any other texture by its cell's load curve (evaluate's: built, cached, or
/// held under --grid auto to the run's load and to `also_held`'s). Throws
/// input::UsageError as evaluate_surface does.
TextureParts texture_parts(const input::Keywords& keywords, const MoreLoadPoints& also_held = {});

/// The cell the boundary elements solve for the texture of `keywords` (its grid fixed by
/// their `grid`; a cell file's tips snapped to it, a measured map's own): what --check
/// steps in time, made once for a map's sampled load points.
reference::Cell surface_cell(const input::Keywords& keywords);

/// A texture as its boundary elements solve it: its geometry (a cell file's tips snapped to
/// the grid) and the grid.
struct TextureGeometry {
  model::CellGeometry geometry;
  reference::PeriodicGrid grid;
  int supercell = 1;      ///< K of a K x K supercell
  std::string cell_file;  ///< a cell file's path; empty for a lattice
};

/// The texture of `keywords` on the grid their `grid` fixes (a number of nodes a pitch, not
/// auto), refused as surface refuses it (its scales, the budget): what design's closure of
/// a level (reference::LevelClosure) solves. Throws input::UsageError for a measured height
/// map, whose cell is its heights rather than caps at drops.
TextureGeometry texture_geometry(const input::Keywords& keywords);

/// --check alone: the texture of `keywords` (with `check`) stepped in time on `cell`
/// (surface_cell's, of the same texture and grid) at their load: run.stepped and
/// check_t_star_resolution, the same bits as evaluate_surface's, without its curve.
SurfaceRun step_surface(const input::Keywords& keywords, const reference::Cell& cell);

/// Reads `keywords` as evaluate_surface does and throws input::UsageError for what it would
/// refuse before building anything: a bad or missing option, a cell whose scales the
/// boundary elements cannot take, a grid beyond the engine's budget. No curve is built, no
/// cell made. Returns the estimated seconds of its curve(s) on one core
/// (estimated_curve_seconds; 0 off the periodic tables; a cached curve not known here) and
/// its snapshot times.
struct SurfaceCheck {
  double seconds = 0.0;
  std::size_t times = 0;
};
SurfaceCheck check_surface(const input::Keywords& keywords);

/// The seconds a cell's load curve on `grid` takes to build on one core of this machine,
/// estimated from the grid's nodes and the cell's caps: a power law fitted to measured
/// curves (docs/performance.md, "A curve's cost"), within a factor of kCurveSecondsSpread
/// of every one of them.
double estimated_curve_seconds(const reference::PeriodicGrid& grid, double caps);
inline constexpr double kCurveSecondsSpread = 2.0;

/// What one texture's load curve asks, found before it is built (a dry run's answer):
/// where it comes from, the grids it is built on (--grid auto: the grid it picks and the
/// one of half its nodes, at least: it doubles where t* still moves), each grid's memory,
/// whether the table cache holds its curve, and the seconds to build it on one core of
/// this machine (estimated_curve_seconds), 0 where cached.
struct CurveCost {
  std::string source;  ///< "periodic tables" (no grid: read off the tables) or "cell"
  bool auto_grid = false;
  struct Grid {
    int nodes_per_pitch = 0;  ///< 0: a measured map's pixels
    int nx = 0, ny = 0;
    double bytes = 0.0;       ///< the solve's memory
    bool cached = false;      ///< read from the cache, not built
    /// Where the cache holds the curve's beginning (and its front): its last load (E0*),
    /// from which it is continued; 0 otherwise.
    double continued_from = 0.0;
    double seconds = 0.0;     ///< to build (a continued curve's: the whole's, at most)
    double built_seconds = 0.0;  ///< to build it whole, cached or not (another draw's, --seeds)
  };
  std::vector<Grid> grids;
  std::size_t caps = 0;
  int levels = 0;
  /// How far the curve is read (SurfaceRun::X_reach, E0*): it stops at its first sample past
  /// it; the seconds are the whole curve's (the cost model's fit), so an upper bound there.
  double X_reach = std::numeric_limits<double>::infinity();
};
/// What `run`'s curve asks (read_surface's run; its grid is changed and put back), read at
/// its own load and `also_held`'s.
CurveCost curve_cost(SurfaceRun& run, const MoreLoadPoints& also_held = {});
/// Throws input::UsageError for what evaluate_surface would refuse (check_surface).
CurveCost curve_cost(const input::Keywords& keywords, const MoreLoadPoints& also_held = {});

}  // namespace punchsweep::engine
