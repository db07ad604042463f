#pragma once
/// @file
/// Every quantity of a texture's map, declared once: its name (the map's variable), what
/// it runs over after the geometry's axes (the load's axes and the levels, the levels, the
/// load's axes and the times, or the geometry alone), its flag set or scale, and its long
/// name. A texture map's storage, the order its values travel between ranks and into the
/// journal, and the netCDF writer all iterate this list (app/surface_map_command.cpp);
/// adding a texture output is one row here and the line that computes it.

#include <array>
#include <cstddef>
#include <string_view>

namespace punchsweep::map {

/// What a texture quantity runs over, after the geometry's axes.
enum class TextureExtent {
  load_level,      ///< the load's axes, then `level`
  geometry_level,  ///< `level` (a geometry's own, whatever the load)
  load_time,       ///< the load's axes, then `t`
  load_time_level, ///< the load's axes, then `t`, then `level`
  geometry,        ///< nothing more: one value a geometry
};

/// The codes a texture flag takes (int8 with flag_values; flag_meanings where named).
enum class TextureFlags {
  none,                    ///< a real (float64)
  regime,                  ///< immediate delayed never (model::Regime)
  regime_or_not_computed,  ///< not_computed, then the regimes (-1 to 2)
  surface_validity,        ///< valid below_resolution above_top unloading (model::SurfaceValidity)
  yes_no,                  ///< 0 or 1
};

/// When a texture quantity is stored: always, in a map of full quantities only (what each
/// snapshot time reads: caps and areas in contact, each level's load; `quantities = regime`
/// leaves them out, and their cost), with a box of
/// tolerances, or with a sample of load points checked by time stepping (`surface --check`
/// at each).
enum class TextureStored { always, full, tolerance, check };

struct TextureQuantitySpec {
  std::string_view name;
  TextureExtent extent;
  TextureFlags flags;
  /// A real's scale: "T_eps" (written in the law's time unit where it has one),
  /// "E0/(1-nu^2)" (units "1" with scaled_by), or "1"; empty for a flag.
  std::string_view scale;
  std::string_view long_name;
  /// When it is stored (with a box of tolerances, its long name ends with the box).
  TextureStored stored = TextureStored::always;
};

/// In the order the map creates its variables.
inline constexpr std::array<TextureQuantitySpec, 22> kTextureQuantities{{
    {"t_star", TextureExtent::load_level, TextureFlags::none, "T_eps", "each level's touch time (0 at once, +inf never)"},
    {"regime", TextureExtent::load_level, TextureFlags::regime, "", "each level's regime"},
    {"t_star_low", TextureExtent::load_level, TextureFlags::none, "T_eps", "each level's least touch time", TextureStored::tolerance},
    {"t_star_high", TextureExtent::load_level, TextureFlags::none, "T_eps", "each level's greatest touch time", TextureStored::tolerance},
    {"regime_low", TextureExtent::load_level, TextureFlags::regime_or_not_computed, "",
     "each level's regime at the corner of least t*", TextureStored::tolerance},
    {"regime_high", TextureExtent::load_level, TextureFlags::regime_or_not_computed, "",
     "each level's regime at the corner of greatest t*", TextureStored::tolerance},
    {"X_star", TextureExtent::geometry_level, TextureFlags::none, "E0/(1-nu^2)",
     "each level's touchdown load (creep-weighted; +inf past the curve's end, which no load point reaches)"},
    {"resolved", TextureExtent::geometry_level, TextureFlags::yes_no, "",
     "whether the curve resolves the level's touchdown (1) or it lies below its resolution (0)"},
    {"touched", TextureExtent::load_time, TextureFlags::none, "1", "share of the caps whose tip has touched", TextureStored::full},
    {"area_fraction", TextureExtent::load_time, TextureFlags::none, "1", "contact area over the cell's", TextureStored::full},
    {"valid", TextureExtent::load_time, TextureFlags::surface_validity, "",
     "whether touched and area_fraction may be trusted at the time", TextureStored::full},
    {"level_touched", TextureExtent::load_time_level, TextureFlags::none, "1",
     "share of each level's caps whose tip has touched", TextureStored::full},
    {"level_area", TextureExtent::load_time_level, TextureFlags::none, "R^2", "each level's contact area in the cell", TextureStored::full},
    {"level_load", TextureExtent::load_time_level, TextureFlags::none, "R^2 E0/(1-nu^2)",
     "the load each level carries in the cell, P_L(t); NaN where its history integral would cost too much", TextureStored::full},
    {"contact_radius", TextureExtent::load_level, TextureFlags::none, "R",
     "each level's contact radius by the last time: sqrt(area / (pi caps in contact)), 0 where none touches"},
    {"advised", TextureExtent::load_level, TextureFlags::yes_no, "",
     "whether the level's caps pass the paraboloid's bound (a > 0.3 R on a sphere) or the strain's (0.2 f'(a) > 0.1) "
     "by the last time (surface's advisories: the answer stands for less than it seems)"},
    {"check_regime", TextureExtent::load_level, TextureFlags::regime_or_not_computed, "",
     "each level's regime by time stepping the same cell (surface --check) at the sampled load points; not_computed "
     "elsewhere", TextureStored::check},
    {"check_t_star", TextureExtent::load_level, TextureFlags::none, "T_eps",
     "each level's touch time by time stepping the same cell at the sampled load points (the middle of an interval "
     "check_t_star_resolution wide); NaN elsewhere", TextureStored::check},
    {"check_t_star_resolution", TextureExtent::load_level, TextureFlags::none, "T_eps",
     "the width of the time stepping's touch-time intervals at the sampled load points; NaN elsewhere",
     TextureStored::check},
    {"check_area_fraction", TextureExtent::load_time, TextureFlags::none, "1",
     "contact area over the cell's by time stepping at the sampled load points; NaN elsewhere", TextureStored::check},
    {"grid", TextureExtent::geometry, TextureFlags::none, "1", "boundary-element nodes along x of the curve"},
    {"from_tables", TextureExtent::geometry, TextureFlags::yes_no, "",
     "the curve came from the periodic model's tables (1) or the cell's boundary elements (0)"},
}};
inline constexpr std::size_t kTextureQuantityCount = kTextureQuantities.size();

/// The position of the texture quantity called `name` in kTextureQuantities (a name not
/// there is a compile error where it is a constant expression).
consteval std::size_t texture_quantity(std::string_view name) {
  for (std::size_t q = 0; q < kTextureQuantityCount; ++q) {
    if (kTextureQuantities[q].name == name) return q;
  }
  throw "no such texture quantity";
}

}  // namespace punchsweep::map
