#pragma once
/// @file
/// Every input parameter of the model, declared once: its name (the command-line option,
/// the config key and the map's coordinate), its unit, its valid range with the check
/// that enforces it, and the values a sweep takes by default. The command line, the config
/// validation, `--help`, the map's coordinate attributes and the option table of docs/cli.md follow
/// from these declarations (tests/model/parameters_test.cpp holds docs/cli.md to them).

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace punchsweep::model {

/// One input parameter of the model.
struct Parameter {
  std::string_view name;       ///< option `--NAME`, config key, map coordinate: "l"
  /// The scale the value is measured in (units.hpp): "R", "E0/(1-nu^2)", or "1" for a pure
  /// number. The map stores it as `scaled_by` beside `units = "1"` (UDUNITS reads "R" as
  /// the roentgen, so a scale is never a `units` string).
  std::string_view scale;
  std::string_view long_name;  ///< the map's `long_name` attribute: "lattice pitch"
  std::string_view meaning;    ///< one phrase for help texts, unit included
  std::string_view range;      ///< the valid range as messages print it: "l > 0 (in R)"
  bool (*in_range)(double);    ///< the check `range` describes (called on finite values)
  bool integer = false;        ///< whole numbers only
  /// The point commands' default value; empty when the option is required.
  std::string_view point_default = {};
  /// The values a sweep takes when a config leaves the axis out; empty when the parameter
  /// is not an axis but one value per sweep (a [model] key).
  std::string_view sweep_default = {};
  /// How help texts state the default where the input decides it (temperature: the
  /// material's T_ref); empty: sweep_default as written.
  std::string_view default_meaning = {};

  /// Whether `value` is admissible: finite, whole if `integer`, and in range.
  bool admits(double value) const;
  /// Empty when `value` is admissible, else "LONG_NAME NAME = VALUE is outside its range: RANGE".
  std::string error(double value) const;
  /// Whether a sweep may take it as an axis.
  bool sweepable() const { return !sweep_default.empty(); }
};

/// The parameters of the contact problem (model/problem/contact_problem.hpp): geometry and load.
inline constexpr std::string_view kPitch = "l";
inline constexpr std::string_view kHeightDifference = "dh";
inline constexpr std::string_view kPressure = "pbar";
inline constexpr std::string_view kExponent = "s";
inline constexpr std::string_view kShapeConstant = "C";

/// The contact problem's parameters, in the order of a map's axes around the material's
/// (l, dh first; pbar, s after), then C, which is one value per sweep.
std::span<const Parameter> problem_parameters();

/// The contact problem's parameter called `name` (l, dh, pbar, s, C); nullptr if none.
const Parameter* problem_parameter(std::string_view name);

/// A texture's lengths beyond the two-level problem's (docs/model.md, section 17): the third
/// level's drop (`--dh2`) and the caps' height scatter's width (a surface map's axis).
inline constexpr std::string_view kThirdLevelDrop = "dh2";
inline constexpr std::string_view kScatterWidth = "scatter_width";
/// The seed of the scatter's draws (`--seed`): an axis of a texture's map, one supercell
/// drawn per value.
inline constexpr std::string_view kScatterSeed = "seed";
/// The texture's parameter called `name`; nullptr if none.
const Parameter* texture_parameter(std::string_view name);

struct Shape;
/// Empty when the shape is usable, else a sentence naming the bad field and its range (its
/// parameters' declarations, s and C, above).
std::string shape_error(const Shape& shape);

}  // namespace punchsweep::model
