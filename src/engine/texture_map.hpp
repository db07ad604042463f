#pragma once
/// @file
/// A texture's map over geometry and load axes (`punchsweep sweep` with a [texture]
/// section, `surface-map`, Python's surface_map; docs/cli.md, docs/model.md section 17.5).
/// Each geometry value (a pitch l, a level's drop dh or dh2, a scatter's width) is one load
/// curve; the pressure and the creep law's parameters are then read off each curve: every
/// level's regime and t*, and at each time the share of caps in contact, the area fraction
/// and their validity, in tiles of a geometry's load points (rows of the pressure axis). The
/// run (app/texture_map_run.hpp) deals the tiles to the MPI ranks and journals them; rank 0
/// writes the map, a netCDF-4 file, a tile at a time.

#include <boost/program_options/options_description.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/surface_evaluation.hpp"
#include "input/command_options.hpp"
#include "map/layout_version.hpp"
#include "map/texture_quantities.hpp"
#include "sweep/reference_sample.hpp"

namespace punchsweep::engine {

/// One axis of the map: its name (an option of `surface`), values and how they are measured.
struct SurfaceMapAxis {
  std::string name;
  std::vector<double> values;
  std::string scale;      ///< "R", "E0/(1-nu^2)", "1", "degC", ...
  std::string long_name;
};

/// The map: its axes and arrays, row-major over the geometry axes, then the load's (pbar,
/// then the law's given parameters), then level or time.
struct SurfaceMap {
  std::vector<SurfaceMapAxis> geometry;  ///< l, dh, dh2, scatter_width where given
  std::vector<SurfaceMapAxis> load;      ///< pbar, then the creep law's parameters given
  std::vector<double> times;
  std::string time_unit = "T_eps";
  int levels = 0;
  std::size_t caps = 0;                 ///< per cell (per supercell)
  /// With a box of tolerances: `tolerance` as stated (map::kTextureQuantities' tolerance
  /// quantities are stored then); empty without one.
  std::string tolerance;
  /// Each quantity of map::kTextureQuantities, row-major over the geometry's axes, then its
  /// extent's (the load's, then level or time); flags as their codes; empty where not
  /// stored. t* in time_unit (+inf never), X* in E0*.
  using Values = std::vector<double>;
  std::array<Values, map::kTextureQuantityCount> values;
  std::vector<double>& operator[](std::size_t q) { return values[q]; }
  const std::vector<double>& operator[](std::size_t q) const { return values[q]; }
  /// Whether the map stores what the snapshot times read (`quantities = full`, the
  /// default) or each level's touch alone (`regime`).
  bool full = true;
  /// Whether quantity q is stored (a tolerance's only with one).
  bool stores(std::size_t q) const {
    switch (map::kTextureQuantities[q].stored) {
      case map::TextureStored::always: return true;
      case map::TextureStored::full: return full;
      case map::TextureStored::tolerance: return !tolerance.empty();
      case map::TextureStored::check: return check_sample > 0;
    }
    return false;
  }
  /// With a sample checked by time stepping: its size (load points of the whole map, drawn
  /// by sweep::ReferenceSample with check_seed); 0 without one.
  std::uint64_t check_sample = 0;
  std::uint64_t check_seed = 1;
  /// The values quantity q has over `points` load points of a geometry (a tile's, or all).
  std::size_t per_points(std::size_t q, std::size_t points) const;
  double E0_star_Pa = 0.0;              ///< with a material: pbar in Pa; else 0
  std::string texture;                  ///< the texture's keywords, as JSON
  std::string material;                 ///< the material file, or empty
  /// --R as a regime map states it ("60 um": the number and the unit's name), and in m;
  /// empty and 0 without one.
  std::string R;
  double R_m = 0.0;
  /// The unit lengths are said in: R's own ("60 um": a length of 1 R is 60 um), else R.
  struct LengthUnit {
    double per_R = 1.0;
    std::string name = "R";
  };
  LengthUnit length_unit() const;
  std::string scatter_kind;             ///< normal or uniform where the scatter's width is an axis
  /// The lines that define the map (texture_map_identity), compared by --resume; and the
  /// layout's version (2: written through the journal; 1 before).
  std::string identity;
  int layout_version = 0;

  std::size_t geometries() const;
  std::size_t load_points() const;

  /// A map's unit of work and of its journal: geometry g's load points [first, first +
  /// count), whole rows of the first load axis (the pressure), each every value of the
  /// load's other axes.
  struct Tile {
    std::size_t geometry, first, count;
  };
  /// Rows of the first load axis a tile holds (TextureMapPlan sizes them from `chunk`): at
  /// least 1, at most the axis's length.
  std::size_t tile_rows = 1;
  std::size_t tiles_per_geometry() const;
  std::size_t tiles() const { return geometries() * tiles_per_geometry(); }
  /// Tile u (0 to tiles() - 1; a geometry's tiles one after another, in its rows' order).
  Tile tile(std::size_t u) const;
  /// The load points of a row of the first load axis (every value of the others).
  std::size_t points_per_row() const;
};

/// A texture map's inputs, read once (the texture's keywords, the geometry's axes, the
/// load's axes, a box of tolerances), and each geometry's block computed from them: one
/// load curve, every load point read off it. `sweep` with a [texture] section, `surface-map`
/// and Python's surface_map all go through it.
class TextureMapPlan {
 public:
  /// `keywords` are surface's, with axes where they take several values (and `output`,
  /// `overwrite`, which it passes over). Throws input::UsageError for bad input or a map
  /// beyond its limits (geometries, points held in memory).
  explicit TextureMapPlan(const input::Keywords& keywords);
  ~TextureMapPlan();
  TextureMapPlan(const TextureMapPlan&) = delete;
  TextureMapPlan& operator=(const TextureMapPlan&) = delete;

  /// The map's axes and attributes, no geometry computed yet (its arrays empty).
  const SurfaceMap& header() const { return header_; }
  std::size_t geometries() const { return header_.geometries(); }
  /// Geometry g's coordinates as "l = 1 R, dh = 0.02 R".
  std::string describe(std::size_t g) const;
  /// The map's tiles (SurfaceMap::tile): a geometry's rows of the first load axis.
  std::size_t tiles() const { return header_.tiles(); }
  /// The snapshot times each load point is read at.
  std::size_t times() const { return times_; }
  /// Tile u computed: its geometry's curve (built, from the cache or the tables; held from
  /// the tile before where that was of the same geometry) and each of its load points read
  /// off it, as the values that travel between ranks and into a journal
  /// (TextureMapWriter::write reads them). A pure function of u and the keywords.
  std::vector<double> evaluate(std::size_t u) const;
  /// Geometry g's texture as `surface`'s keywords (at the least pressure, the law's first
  /// values).
  input::Keywords keywords_of(std::size_t g) const;
  /// The map's load points, as more than the run of keywords_of(g) holds (its least
  /// pressure): how far any of them reads a geometry's curve (X(inf) at the most) and each
  /// level's touch at each. The plan must outlive it.
  MoreLoadPoints load_points() const;
  /// Geometry g's estimated seconds on one core (check_surface's; a cached curve not known).
  double estimated_seconds(std::size_t g) const { return seconds_[g]; }
  /// The order the tiles are dealt in to `ranks` ranks: the geometries the costliest first
  /// (by estimated_seconds, ties in index order), so that no long curve starts last while
  /// the other ranks idle; in waves of `ranks` geometries, their first tiles (a curve each)
  /// before the rest of their tiles, so that the ranks build curves side by side.
  std::vector<std::size_t> dealing_order(int ranks) const;

 private:
  std::vector<double> seconds_;
  std::size_t times_ = 0;
  struct Inputs;
  std::unique_ptr<const Inputs> in_;
  SurfaceMap header_;
  std::optional<sweep::ReferenceSample> check_;  ///< the load points checked by time stepping
  mutable std::optional<double> reach_;          ///< the load points' largest X(inf), found once
  /// The last geometry a tile read, kept for the next tile of the same geometry.
  struct Opened;
  mutable std::unique_ptr<Opened> last_;
  const Opened& open(std::size_t g, bool* held) const;
};

/// The seconds `points` load points of a geometry of `levels` levels take to read off its
/// curve at `times` snapshot times on one core of this machine: with full quantities
/// (each level's touch, areas and load by its history) levels x (19 + 16 times) us a load
/// point, fitted to maps of 20,000 load points of two and three levels at 1, 3 and 10 times
/// (each within 25%); each level's touch and advisories alone (`full` false) 5 + levels us,
/// fitted to maps of 100,000 load points of two and three levels (0.74-0.86 s a run, within
/// 10%).
double estimated_reading_seconds(std::size_t points, int levels, std::size_t times, bool full);

/// What a tile's curve cost: seconds, and "built", "from the cache", "from the periodic
/// tables" or held from the rank's tile before (`held`: it cost nothing).
struct GeometryCost {
  double seconds;
  const char* source;
  bool held = false;
};
GeometryCost geometry_cost(std::span<const double> block);

/// Writes a texture's map a tile at a time (TextureMapPlan::evaluate's blocks, in any
/// order), never holding it whole: into FILE.partial, one slab (and one HDF5 chunk) a tile
/// in every variable over the load (a geometry's slab in the others), renamed to FILE by
/// finish(). The levels and the times come with the first block; the .partial is removed
/// when the writer goes unfinished.
class TextureMapWriter {
 public:
  /// Checks `path` as every output is (io::output_file_problem for it and its .partial;
  /// none of the files `keywords` reads: material, cell, height-map; an existing file only
  /// with `overwrite`). Throws input::UsageError naming the problem.
  TextureMapWriter(std::string path, SurfaceMap header, bool overwrite, const input::Keywords& keywords);
  ~TextureMapWriter();
  TextureMapWriter(const TextureMapWriter&) = delete;
  TextureMapWriter& operator=(const TextureMapWriter&) = delete;

  /// Tile u's block. Throws input::UsageError where its levels differ from the first
  /// block's, std::invalid_argument where it does not fit the map.
  void write(std::size_t u, std::span<const double> block);
  /// The map's levels and snapshot times (0 before the first block).
  int levels() const { return header_.levels; }
  std::size_t times() const { return header_.times.size(); }
  /// Closes the file and gives it its name. Throws std::logic_error when a tile is missing.
  void finish();

 private:
  void create(std::span<const double> first);
  struct File;
  std::string path_;
  SurfaceMap header_;
  std::vector<bool> written_;
  std::unique_ptr<File> file_;
};

/// The map of `keywords` computed on this process alone and written to `path`, with a line
/// on stderr per curve when `progress` (Python's surface_map).
void write_texture_map(const input::Keywords& keywords, const std::string& path, bool overwrite, bool progress);

/// The options a texture's map takes: its own (output, overwrite, resume, quiet, the
/// time-stepping sample) and surface's.
boost::program_options::options_description texture_map_options(const input::PointMaterial& material);

/// Whether `key` is one of the run's own keywords (where and how to write), not the map's.
bool is_map_run_keyword(const std::string& key);

/// The files a map's keywords read: its material, cell file or height map.
std::vector<std::string> texture_input_files(const input::Keywords& keywords);

/// Throws input::UsageError naming the first keyword no texture map takes (by its
/// `origins` entry: "texture.foo"), with the ones it does.
void check_texture_keywords(const input::Keywords& keywords, const std::vector<std::string>& origins);

/// The lines that define a map (its keywords, sorted, and the layout): the journal's
/// header and the map's `identity` attribute, compared on --resume.
std::vector<std::string> texture_map_identity(const input::Keywords& keywords);

/// Python's surface_map: the map of `keywords` on this process alone, written to their
/// `output`; returns that path.
std::string surface_map_file(const input::Keywords& keywords);

}  // namespace punchsweep::engine
