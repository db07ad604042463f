#pragma once
/// @file
/// Units of the whole physics layer (docs/model.md, section 1). Stated here once:
///   lengths      in R, the characteristic punch size;
///   pressures    in E0* = E0 / (1 - nu^2), the instantaneous plane-strain modulus;
///   point loads  in R^2 E0*;
///   time         in T_eps, the creep (retardation) time;
///   creep J(t)   in 1/E0*, relaxation E(t) in E0*.
/// Poisson's ratio never appears: it is folded into E0*. Every double in src/model is in
/// these units; nothing in the physics converts.
///
/// And the physical units an input may carry, declared once: the material files' modulus
/// and time units, `--pressure`, and the scaled options (--l, --dh, --pbar) given with a
/// unit all read them from here, and are divided by their scale (R, E0*) on the way in.
/// Factors are exact SI multiples (checked against UDUNITS-2's `udunits2` by
/// tests/model/units_test.cpp).

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace punchsweep::model {

/// The kinds of physical quantity an input may be given in.
enum class Dimension { length, pressure, time };

/// A unit of one dimension: its symbol (as UDUNITS-2 spells it) and its size in the
/// dimension's SI unit (m, Pa, s).
struct Unit {
  std::string_view name;
  double si;
};

/// The units a dimension is accepted in, its SI unit first: m, mm, um, nm; Pa, kPa, MPa,
/// GPa; s, ms, min, h.
std::span<const Unit> units_of(Dimension dimension);

/// The unit of `dimension` named `name` (exact spelling; "µm" is um), or nullptr.
const Unit* find_unit(Dimension dimension, std::string_view name);

/// "m, mm, um or nm": the dimension's units for messages.
std::string unit_names(Dimension dimension);

/// "length", "pressure" or "time".
std::string_view dimension_name(Dimension dimension);

/// A number in a unit.
struct Physical {
  double number = 0.0;
  const Unit* unit = nullptr;
  double si() const { return number * unit->si; }
};

/// A number followed by a unit of `dimension` ("150um", "150 um", "2.5e-3 mm");
/// std::nullopt when `text` is a bare number (the caller's scaled unit). Throws
/// std::invalid_argument naming the text and the valid units when the unit is not one of
/// the dimension's, or the number is not one.
std::optional<Physical> parse_physical(std::string_view text, Dimension dimension);

/// x in unit `from` expressed in unit `to` (of one dimension). Between declared units the
/// ratio is an integer (1000, 60) or its reciprocal, and is applied as that integer, so
/// 0.15 mm is 150 um exactly where 0.15 x (1e-3 / 1e-6) is not.
double convert(double x, const Unit& from, const Unit& to);

/// `value` in units of `scale` (both of one dimension): value / scale, both in the smaller
/// of their units first (150 um over 0.05 mm is 150 / 50; 0.15 mm over 50 um is 150 / 50).
double in_units_of(const Physical& value, const Physical& scale);

}  // namespace punchsweep::model
