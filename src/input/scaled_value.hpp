#pragma once
/// @file
/// The one rule for what an input number means, the same in every command, config key and
/// Python keyword (docs/cli.md, "Units"):
///   - a bare number is in the quantity's scaled unit: lengths in R, pressures in
///     E0* = E0/(1-nu^2), times in T_eps or the material's time_unit;
///   - a number with a unit (150um, 2kPa, 1min) is physical, and is divided by its scale:
///     R as given (--R, model.R), E0* of the material, one time_unit of the material.
/// A unit without its scale, an unknown unit, a unit of another dimension, or an axis that
/// mixes numbers with and without units is refused with a message naming the text.

#include <optional>
#include <string>

#include "input/axis_parser.hpp"
#include "model/point/parameters.hpp"
#include "model/numerics/units.hpp"

namespace punchsweep::model {
class Material;
}

namespace punchsweep::input {

/// The physical scales an input knows: R (as given, 50 um: outputs use its unit), E0* in Pa
/// and the time unit (from a material).
struct PhysicalScales {
  std::optional<model::Physical> R;
  std::optional<model::Physical> E0_star;
  std::optional<model::Physical> time;  ///< one of the material's time_unit
};

/// E0* and the time unit of `material` (nothing for nullptr), and R when given.
PhysicalScales scales_of(const model::Material* material, std::optional<model::Physical> R = std::nullopt);

/// R from its text: a length > 0 with its unit (50um). Throws std::invalid_argument whose
/// message starts with the text and says what is valid.
model::Physical read_length_scale(const std::string& text);

/// One scaled unit in physical terms: `per_scaled` of `units` (a UDUNITS-2 string).
struct PhysicalUnit {
  double per_scaled;
  std::string units;
};

/// The physical unit of a quantity measured in `scaled_unit`, where `scales` knows it: R in
/// R's unit, E0/(1-nu^2) in Pa, R^2 E0/(1-nu^2) in N, T_eps in the material's time unit;
/// nullopt for a pure number or an unknown scale.
std::optional<PhysicalUnit> physical_unit(std::string_view scaled_unit, const PhysicalScales& scales);
/// The same, or the scaled unit itself (1 of `scaled_unit`) where `scales` does not know it:
/// how a value is printed for people, in um where the run has R and in R otherwise.
PhysicalUnit physical_unit_or_scaled(std::string_view scaled_unit, const PhysicalScales& scales);

/// How a scaled quantity reads a physical value: its dimension, scale, and what gives the
/// scale (for the message when it is missing).
struct Scale {
  model::Dimension dimension;
  std::string_view scaled_unit;          ///< "R", "E0/(1-nu^2)", "T_eps"
  std::optional<model::Physical> value;  ///< the scale, where known
  std::string_view needs;                ///< "--R / model.R (the punch's radius of curvature, e.g. 50um)"
};

/// The scale of a quantity measured in `scaled_unit` ("R", "E0/(1-nu^2)", "T_eps"), or
/// nullopt for a pure number.
std::optional<Scale> scale_of(std::string_view scaled_unit, const PhysicalScales& scales);

/// `text` in the scaled unit: a bare number as it is, a number with a unit divided by the
/// scale. Throws std::invalid_argument (message without the key) for an unknown unit, one
/// of another dimension, or a unit whose scale is unknown.
double read_scaled(const std::string& text, const Scale& scale);

/// A length from its text: a bare number in R, or a number with a length unit where
/// `scales` knows R. Throws UsageError "WHAT = 'TEXT': why" (`what` names the input: an
/// option, or a file's line and key) for a unit without R, another dimension, or no number.
double read_length(const std::string& text, const PhysicalScales& scales, const std::string& what);

/// Whether `text` carries a unit of some dimension ("2um" yes, "0.5" no).
bool has_unit(const std::string& text);

/// An axis (input::parse_axis syntax) whose values may carry units: each value read by
/// read_scaled; with `required`, every value must carry one (a physical-only key such as
/// grid.pressure). Refuses an axis that mixes values with and without a unit.
map::Axis read_scaled_axis(const std::string& text, bool integers, const Scale& scale, bool required = false);

}  // namespace punchsweep::input
