#pragma once
/// @file
/// The design, the inverse question (`punchsweep design`, Python's design()). Which height
/// difference dh meets every requirement ("touch within 1s at 30kPa", "never at 5kPa") at
/// every temperature of a range and every corner of a tolerance box? Each requirement bounds dh on one side at
/// each temperature and corner, exactly: until the second level touches, the first carries
/// the load alone, so the gap it closes by time t, model::dh_touching_at, is the dh whose t*
/// is t (docs/design.md). Or, for a given dh, which pitch (--find l) or which nominal
/// pressure (--find pressure): the gap grows with each, so each requirement's bound is the
/// value whose gap is dh, found by bisection. A texture (a lattice of two or three levels,
/// a cell file, a height map, a scattered supercell) is solved by its cell's boundary
/// elements or read off its load curve (docs/design.md, "Any texture").

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "input/command_options.hpp"
#include "model/point/advisory.hpp"

namespace punchsweep::engine {

/// Temperatures a range is checked at (evenly spaced, both ends included).
inline constexpr int kTemperatureSamples = 9;

/// The forms a requirement takes (the usage text and every message about one quote it).
inline constexpr const char* kRequirementForms =
    "valid: 'touch within TIME at PRESSURE', 'touch at once at PRESSURE', 'touch at PRESSURE' (at any time), "
    "'never at PRESSURE', 'no touch within TIME at PRESSURE' (with --find pressure, without 'at PRESSURE'); "
    "on a scattered supercell, a cell file or a height map also 'N% of level L within TIME', "
    "'at most N% of caps within TIME' (of level L, or of caps: every one; without a time, ever; a drop or pitch "
    "window: of its level or of every cap, 'at PRESSURE' added); TIME with a unit (1s, 5min) where a material file "
    "gives one (else in T_eps), PRESSURE with one (30kPa) where it gives a modulus (else in E0/(1-nu^2))";

/// One requirement as the user states it.
struct Requirement {
  std::string text;  ///< as given
  /// touch_by: t* <= time (dh at most the gap closed by then); no_touch_by: t* > time (dh
  /// above it). time 0: at once; +inf: ever.
  enum class Kind { touch_by, no_touch_by } kind = Kind::touch_by;
  double time = 0.0;  ///< in the law's time unit
  double pbar = 0.0;  ///< nominal pressure, in E0* (NaN with --find pressure: the one searched)
  /// A share of caps ("90% of level 1 within 1min": touch_by, 0.9; "at most 5% of caps within
  /// 1s": no_touch_by, 0.05), where heights scatter: touch_by holds where at least this share
  /// of the caps has touched by `time`, no_touch_by where at most it has. NaN: the level's
  /// first cap (touch_by: one at least; no_touch_by: none).
  double share = std::numeric_limits<double>::quiet_NaN();
  /// Whose caps a share counts: -1 every cap of the cell, 0 the design's level, else that level.
  int share_level = 0;
  bool is_share() const { return share == share; }
};

/// Where one requirement bounds the design's quantity at one temperature and corner of the
/// box.
struct DesignBound {
  double temperature = 0.0;  ///< degC (NaN for a law without temperature)
  double pbar = 0.0;         ///< the corner's pressure, in E0* (the search's start for --find pressure)
  double l = 0.0, C = 0.0;   ///< the corner's pitch (R; the search's start for --find l) and shape factor
  double dh = 0.0;           ///< the corner's dh (R; for --find l)
  /// The bound before the quantity's own tolerance, in R: for dh, the gap closed by the
  /// requirement's time (the dh whose t* it is); for l (the pressure), the pitch (pressure)
  /// at which that gap is the corner's dh (inf or the search's end where none within it).
  double value = 0.0;
  double edge = 0.0;  ///< the edge it sets: `value` less the quantity's own tolerance, in R
};

/// The tolerance box as the design reads it (--tolerance).
struct DesignTolerance {
  double dh = 0.0;                ///< R
  double pressure = 0.0;          ///< relative (10% -> 0.1), or absolute in E0* when pressure_absolute
  bool pressure_absolute = false;
  double l = 0.0;                 ///< relative, or absolute in R when l_absolute
  bool l_absolute = false;
  double C = 0.0;                 ///< relative
  double temperature = 0.0;       ///< K: the range is widened by it on each side
};

/// A requirement's bound on dh: its binding temperature and corner, and every one it met.
struct RequirementBound {
  Requirement requirement;
  /// The window's edge it sets (R): the bound less the quantity's tolerance, the tightest
  /// over every temperature and corner; for dh an upper edge for touch_by and a lower one
  /// for no_touch_by, for l and the pressure (the gap grows with each) the other way round.
  double edge = 0.0;
  bool upper = true;  ///< which edge it sets
  DesignBound binding;
  /// The bound is the same at every temperature checked (h_0 and h_inf are: the glassy and
  /// the relaxed compliance do not shift), so `binding.temperature` is only the first.
  bool every_temperature = false;
  std::vector<DesignBound> bounds;  ///< temperature-major, then corner
  /// `point`'s advisories at the edge (docs/model.md, section 16): at the binding corner with
  /// the searched quantity at its edge, the caps' contact radius in the long term (X(inf):
  /// radii only grow while the contact does) against the paraboloid's and the strain's
  /// bounds; nothing raised where the edge is not finite or the law creeps without end.
  model::Advisories advice;
  /// The level of the widest caps there (a texture's); -1 on the paper's lattice by its
  /// model (its tall caps).
  int advice_level = -1;
};

/// A texture's design (docs/design.md, "Any texture"): a lattice of two or three levels,
/// solved by its cell's boundary elements.
struct DesignTexture {
  std::string lattice = "square";  ///< square or hexagonal
  int levels = 2;                  ///< 2, or 3 with a third level (--dh2)
  int level = 1;                   ///< the level the requirements are on (whose drop --find dh or dh2 finds)
  std::vector<double> drops;       ///< per level from 1, in R (the searched level's 0: found)
  int nodes = 0;                   ///< nodes per pitch of the answer's grid
  /// --grid auto: the grid of half the nodes the answer was held to (0 where not held), and
  /// the largest relative move of an edge between the two.
  int coarser = 0;
  double grid_move = 0.0;
  bool every_drop = false;  ///< some load pressed the level at any drop it can have (its bound is its deepest)
  int solves = 0;           ///< contact solves of the answer's grid
  /// Closures answered by the small-spot limit (no grid; docs/model.md 17.6), on both grids.
  int small_spot = 0;
  /// A scattered supercell (--supercell K, --scatter): K, the scatter as given and the seed;
  /// its design reads the load curve's touchdown of every cap (K 1 and empty otherwise).
  int supercell = 1;
  std::string scatter;
  std::string seed;
  int caps = 0;  ///< caps in the cell (a supercell's: every one)
  std::string file;  ///< a cell file's or height map's path (lattice then "cell" or "height map")
};

/// The answer: the window, each requirement's bound, and what the user should know.
struct DesignResult {
  std::string quantity = "dh";  ///< what the window is of: dh, dh2 (--find dh2), l (--find l) or pbar (--find pressure)
  std::optional<DesignTexture> texture;  ///< a lattice texture's design; none for the paper's lattice by the model
  double search_lo = 0.0, search_hi = 0.0;  ///< --find l or pressure: the range searched (R or E0*)
  input::PointInputs inputs;  ///< the geometry and material (at the first requirement's pressure)
  std::vector<double> temperatures;
  DesignTolerance tolerance;
  std::vector<RequirementBound> bounds;
  /// R or E0*; lower > upper, or lower +infinity (a requirement no value meets): no value
  /// meets every requirement.
  double lower = 0.0, upper = 0.0;
  std::vector<std::string> notes;
  bool empty() const { return !(lower <= upper) || lower == std::numeric_limits<double>::infinity(); }
};

/// The design of `keywords` (the command's options as keywords: --require repeats; the
/// point's options, a texture's, --find, --temperature, --tolerance; --format and --help
/// are read and left to the caller): the window, each requirement's bound and binding
/// corner, and the notes. Every corner is evaluated (the paper's lattice by the model, a
/// texture by its cell's boundary elements or its load curve). Throws input::UsageError,
/// naming the bad input, before any result.
DesignResult design(const input::Keywords& keywords);

/// A scaled unit in a physical one: `per` of `unit` make one scaled unit.
struct Unit {
  double per = 1.0;
  std::string unit;
};

/// Lengths in R's physical unit where --R is given, else in R.
Unit length_unit(const input::PointInputs& in);

/// Pressures in Pa, kPa or MPa (whichever `typical`, in E0*, reads in as 1 to 1000) where the
/// material gives a modulus, else in E0*.
Unit pressure_unit(const input::PointInputs& in, double typical);

/// `pbar` (E0*) in pressure_unit's unit, four digits, with the unit.
std::string pressure_text(double pbar, const input::PointInputs& in);

/// The tolerance of the quantity a window is of (dh, l or pbar): its width (in the
/// quantity's scaled unit, or a fraction where relative).
struct OwnTolerance {
  double width = 0.0;
  bool relative = false;
};
OwnTolerance own_tolerance(const DesignTolerance& box, std::string_view quantity);

}  // namespace punchsweep::engine
