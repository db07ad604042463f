#pragma once

#include <boost/program_options.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/problem/contact_problem.hpp"
#include "model/laws/material.hpp"
#include "model/laws/creep_laws.hpp"
#include "model/point/sensitivity.hpp"
#include "model/point/parameters.hpp"
#include "model/problem/shape.hpp"
#include "model/numerics/units.hpp"
#include "input/scaled_value.hpp"

namespace punchsweep::input {

/// Parses a one-shot command's arguments (long options only, so "--l -0.5" reads -0.5 as
/// a value; no positional arguments). Throws UsageError naming `command` for help.
boost::program_options::variables_map parse_command(const std::vector<std::string>& args,
                                                    const boost::program_options::options_description& opts,
                                                    const std::string& command);

/// Keywords and their values as text, in the order given: Python's keywords, each the name
/// of an option without its dashes (`l`, `load-table`).
using Keywords = std::vector<std::pair<std::string, std::string>>;

/// The same options read from keywords instead of a command line: each keyword is stored as
/// its option with the value, through the same declarations (defaults, notify), so every
/// later check is the command's. Throws UsageError for a keyword that is no option
/// ("unknown option --NAME", as the command line says it).
boost::program_options::variables_map parse_keywords(const Keywords& keywords,
                                                     const boost::program_options::options_description& opts,
                                                     const std::string& command);

/// A required (or defaulted) real option, range-checked. Throws UsageError naming the
/// option, its value and its valid range `range`.
double read_real(const boost::program_options::variables_map& vm, const char* name, const char* meaning,
                 const char* range, const std::function<bool(double)>& in_range);

/// Declares --NAME for `parameter` with its meaning, unit, range and default (or
/// "required"), as model/point/parameters.hpp declares them.
/// `requirement` replaces "required" / "default X" in the help when given.
void add_parameter_option(boost::program_options::options_description& opts, const model::Parameter& parameter,
                          const std::string& requirement = {});

/// "--NAME = TEXT is outside its range: RANGE": the message for `parameter` given as `text`.
std::string out_of_range(const model::Parameter& parameter, const std::string& text);

/// The value of --NAME for `parameter`. A length (in R) or a pressure (in E0*) may carry a
/// unit (150um, 20kPa) where `scales` holds its scale. Throws UsageError naming the option,
/// its value and its valid range (or "missing required option", or the scale a unit needs)
/// when it is not admissible.
double read_parameter(const boost::program_options::variables_map& vm, const model::Parameter& parameter,
                      const PhysicalScales* scales = nullptr);

/// --s and --C as a Shape.
model::Shape read_shape(const boost::program_options::variables_map& vm);

/// The options of one parameter point of `law` (the default creep law unless said): --help,
/// one per model::sweep_axes parameter (for the standard linear solid --l, --dh, --T,
/// --pbar, --s), --C and --times.
void add_point_options(boost::program_options::options_description& opts,
                       const model::CreepLawSpec& law = model::creep_laws().front());

/// --l, --dh, --pbar, --s and --C as a ContactProblem, each range-checked.
model::ContactProblem read_problem(const boost::program_options::variables_map& vm);

/// --localization L: any spelling of model::localization_spellings() (docs/model.md,
/// sections 11, 14), default `fallback`: model::kDefaultLocalization where the answers are
/// (point, sweep), paper for the commands that draw the paper's curves and table
/// (single-level, elastic).
void add_localization_option(boost::program_options::options_description& opts, const std::string& fallback);
/// --localization as read, refused as a usage error (exit 2) naming its valid forms.
model::Localization read_localization(const boost::program_options::variables_map& vm);

/// The material file `path` read and parsed. Throws UsageError with the file's message
/// (file, key, value, valid range) when it cannot be read or is refused.
/// `option` ("--material") starts the message of a file that cannot be opened; empty where
/// the caller names the key itself.
std::shared_ptr<const model::Material> read_material_file(const std::string& path,
                                                          const std::string& option = "--material");

/// A point command's material: the file given as --material in `args` (nullptr without it)
/// and the creep law it defines, else the default creep law. The options the command
/// declares depend on it (--temperature for a material with a shift, --T for the default).
struct PointMaterial {
  std::shared_ptr<const model::Material> material;
  model::CreepLawSpec spec;  ///< material->spec(), or the default creep law
  /// The unit of every time: the file's time_unit, or "T_eps".
  std::string time_unit() const { return material ? material->time_unit() : "T_eps"; }
};
PointMaterial find_point_material(const std::vector<std::string>& args);
/// The same for keywords (the `material` keyword).
PointMaterial find_point_material(const Keywords& keywords);

/// A load table "t:phi, t:phi, ..." (times in the law's unit, phi the fraction of pbar; from
/// t = 0 to phi = 1, non-decreasing) as a LoadShape. Throws UsageError naming `key`, the
/// text and the rule it breaks.
model::LoadShape parse_load_table(const std::string& text, const std::string& key);

/// --pressure VALUE[UNIT] (Pa, kPa, MPa, GPa) as pbar = p / E0* of `material`; empty
/// without it. Throws UsageError without a unit, beside --pbar or without a material.
std::optional<double> read_physical_pressure(const boost::program_options::variables_map& vm,
                                             const model::Material* material);

/// --ramp and --load-table as the load's shape (a step without either); the ramp time and
/// the table's text as given come back too. Throws UsageError for both or a bad value.
/// --ramp may carry a time unit (30s) where `scales` has the material's time unit.
model::LoadShape read_loading(const boost::program_options::variables_map& vm, double* ramp_time,
                              std::string* table_text, const PhysicalScales& scales = {});

/// --material FILE, --ramp TR and --load-table, declared for a point command.
void add_material_options(boost::program_options::options_description& opts);

/// The inputs of one parameter point: the contact problem and the creep law with its
/// parameter values.
struct PointInputs {
  /// Every parameter given, with its value, in add_point_options' order.
  std::vector<std::pair<const model::Parameter*, double>> values;
  model::ContactProblem problem;
  const model::CreepLawSpec* law = nullptr;
  std::vector<double> law_values;  ///< in law->parameters order
  std::unique_ptr<model::CreepLaw> creep;
  std::shared_ptr<const model::Material> material;  ///< the --material file, or nullptr
  std::string time_unit = "T_eps";                   ///< of every time in and out
  std::string load_text;                             ///< --load-table as given, or empty
  PhysicalScales scales;                             ///< what physical units the inputs could carry
  /// What the reading changed and says so, in the user's words (a tolerance box clipped at
  /// dh = 0): printed with the result ("note:"; JSON "notes").
  std::vector<std::string> notes;

  /// "l = 0.75 R, dh = 0.075 R, T = 2.5, pbar = 0.06 E0/(1-nu^2), s = 2, C = 0.5": every
  /// parameter in add_point_options' order, with its unit.
  std::string describe() const;
};

/// The point's options (add_point_options) read and range-checked, for creep law `law`.
PointInputs read_point_inputs(const boost::program_options::variables_map& vm,
                              const model::CreepLawSpec& law = model::creep_laws().front());

/// The same with pbar given (from --pressure) instead of read from --pbar.
PointInputs read_point_inputs(const boost::program_options::variables_map& vm, const model::CreepLawSpec& law,
                              std::optional<double> pbar, const PhysicalScales& scales);

/// --R (a length with its unit) and a material's E0* (plane_strain_modulus), the scales of
/// add_material_options' point. Throws UsageError for an R without a unit, not > 0, or not a length.
PhysicalScales read_physical_scales(const boost::program_options::variables_map& vm, const model::Material* material);

/// The same for the material found by find_point_material, with --ramp, --load-table and
/// --pressure (add_material_options).
PointInputs read_point_inputs(const boost::program_options::variables_map& vm, const PointMaterial& material);

/// The valid range of snapshot times, as --times and [time] times state it.
inline constexpr const char* kTimesRange = "each t >= 0 and finite, strictly increasing (in T_eps)";

/// Declares --times (default 0,0.5,1,2,5) with its syntax and range.
void add_times_option(boost::program_options::options_description& opts);

/// --times: snapshot times in T_eps, in the axis syntax of a sweep (a list, linspace() or
/// logspace()), each >= 0, strictly increasing. Throws UsageError naming --times, the
/// problem and kTimesRange.
/// With a material's time unit in `scales`, the times may carry time units (30s, 1min, 2h).
std::vector<double> read_times(const boost::program_options::variables_map& vm, const PhysicalScales& scales = {});

/// A list option whose values must each satisfy `in_range` (described by `range`).
std::vector<double> read_real_list(const boost::program_options::variables_map& vm, const char* name,
                                   const char* range, const std::function<bool(double)>& in_range);

/// --tolerance "NAME=VALUE, ...": symmetric tolerances on real-valued parameters of the
/// point (l, dh, pbar or pressure, C, T, temperature), each VALUE a percentage of the
/// parameter's value (5%), a number in its scale, or a number with a unit where the scale
/// is known (0.05um, 200Pa; a temperature in K or degC, a difference). Empty without the
/// option. Throws UsageError naming the entry and what is valid.
void add_tolerance_option(boost::program_options::options_description& opts);
/// The entries of a tolerance text "NAME=VALUE, ..." (`key` names it in messages: the
/// option or config key), each on a real-valued parameter `known` admits (pressure stands
/// for pbar), VALUE a percentage (relative), a number in the parameter's scale or one with
/// a unit where `scales` knows it (a temperature's in K or degC, a difference). Throws
/// UsageError naming the entry and what is valid (`names`: the valid NAMEs, for it; `unknown`
/// what a NAME `known` does not give is; `refuse`, where given, a command's own rule: why it
/// refuses a tolerance read, or empty).
std::vector<model::StatedTolerance> parse_tolerances(
    const std::string& text, const std::string& key,
    const std::function<const model::Parameter*(std::string_view)>& known, const PhysicalScales& scales,
    const std::string& names, const std::string& unknown = "is no real-valued input of this point",
    const std::function<std::string(const model::StatedTolerance&)>& refuse = {});
/// A box that reaches below 0 on a parameter whose range starts at 0 (dh: the two levels at
/// one height) is clipped there, with a note in `inputs.notes`.
std::vector<model::Tolerance> read_tolerances(const boost::program_options::variables_map& vm, PointInputs& inputs);

/// --cap-radius B or --cap-height H: the base radius of the spherical caps the punches are
/// (a length in R, or with a unit where R is given; from the height, B = sqrt(H (2 - H)) in
/// R, for s = 2, C = 0.5 only). nullopt without either. Throws UsageError naming the option.
void add_cap_options(boost::program_options::options_description& opts);
std::optional<double> read_cap_radius(const boost::program_options::variables_map& vm, const PointInputs& inputs);

/// --format, one of `allowed`.
std::string read_choice(const boost::program_options::variables_map& vm, const char* name,
                        const std::vector<std::string>& allowed);

/// Shortest text that reads back to the same double; "null" for NaN or infinity (JSON).
std::string json_number(double value);

/// `text` as a JSON string: quoted, with '"' and '\\' escaped and control characters as \\u00XX.
std::string json_string(const std::string& text);

/// `values` as a JSON array of json_number()s: "[0, 0.5, null]".
std::string json_array(const std::vector<double>& values);

/// The options of `punchsweep point` for `material` (the design command reads its points
/// through them too).
boost::program_options::options_description point_options(const input::PointMaterial& material);


}  // namespace punchsweep::input
