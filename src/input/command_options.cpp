#include "input/command_options.hpp"

#include "model/point/advisory.hpp"
#include "input/material_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include "input/text_file.hpp"
#include "input/usage_error.hpp"
#include "input/value_parsing.hpp"
#include "input/axis_parser.hpp"
#include "model/point/parameters.hpp"
#include "model/point/point_axes.hpp"

namespace po = boost::program_options;

namespace punchsweep::input {

namespace {

/// Why an option that names a creep law's parameter is not one here: a law's parameter
/// (--T of the standard linear solid) beside --material, whose law is the file's, or a
/// material's --temperature without one (issue 24: "unknown option --T" alone left the user
/// to guess). Empty for any other option.
std::string law_hint(const std::string& option, const std::vector<std::string>& args) {
  const bool material = std::find(args.begin(), args.end(), "--material") != args.end() ||
                        std::any_of(args.begin(), args.end(), [](const std::string& a) { return a.rfind("--material=", 0) == 0; });
  for (const model::CreepLawSpec& law : model::creep_laws()) {
    for (const model::Parameter& p : law.parameters) {
      if (option != "--" + std::string(p.name)) continue;
      return " (" + std::string(p.long_name) + ") of the " + std::string(law.name) + " law" +
             (material ? "; with --material the law is the file's, which takes --temperature where the file has a "
                         "[shift] and no other parameter"
                       : "");
    }
  }
  if (option == "--" + std::string(model::temperature_parameter().name)) {
    return material ? " (this material file has no [shift], so its law takes no temperature; add a [shift] "
                      "section, docs/materials.md)"
                    : " (a material's temperature: give --material FILE, a material file with a [shift])";
  }
  return {};
}

}  // namespace

po::variables_map parse_command(const std::vector<std::string>& args, const po::options_description& opts,
                                const std::string& command) {
  po::variables_map vm;
  // Stray arguments are collected under a hidden name, so the message can quote them.
  constexpr const char* kStray = "stray-argument";
  po::options_description all;
  all.add(opts);
  all.add_options()(kStray, po::value<std::vector<std::string>>());
  po::positional_options_description stray;
  stray.add(kStray, -1);
  const std::string see = "see punchsweep " + command + " --help";
  try {
    const auto style = po::command_line_style::unix_style ^ po::command_line_style::allow_short;
    po::store(po::command_line_parser(args).options(all).style(style).positional(stray).run(), vm);
    po::notify(vm);
  } catch (const po::unknown_option& e) {
    throw UsageError("unknown option " + e.get_option_name() + law_hint(e.get_option_name(), args) + " (" + see + ")");
  } catch (const po::error& e) {
    throw UsageError(std::string(e.what()) + " (" + see + ")");
  }
  if (vm.count(kStray)) {
    throw UsageError("unexpected argument '" + vm[kStray].as<std::vector<std::string>>().front() +
                     "': every input is an --option with its value (" + see + ")");
  }
  return vm;
}

po::variables_map parse_keywords(const Keywords& keywords, const po::options_description& opts,
                                 const std::string& command) {
  std::vector<std::string> named;  // for law_hint: what the keywords would be as options
  for (const auto& [name, text] : keywords) named.push_back("--" + name);
  po::parsed_options parsed(&opts);
  for (const auto& [name, text] : keywords) {
    if (opts.find_nothrow(name, false) == nullptr || name == "help") {
      throw UsageError("unknown option --" + name + law_hint("--" + name, named) + " (see punchsweep " + command +
                       " --help)");
    }
    if (text.find('\0') != std::string::npos) {  // it would cut the value where C strings end
      throw UsageError("--" + name + ": a NUL character cannot be part of an option's value");
    }
    po::option option(name, {text});
    option.original_tokens = {"--" + name, text};
    parsed.options.push_back(std::move(option));
  }
  po::variables_map vm;
  try {
    po::store(parsed, vm);
    po::notify(vm);
  } catch (const po::error& e) {
    throw UsageError(std::string(e.what()) + " (see punchsweep " + command + " --help)");
  }
  return vm;
}

double read_real(const po::variables_map& vm, const char* name, const char* meaning, const char* range,
                 const std::function<bool(double)>& in_range) {
  const std::string option = std::string("--") + name;
  if (!vm.count(name)) {
    throw UsageError("missing required option " + option + " (" + meaning + "; " + range + ")");
  }
  const std::string text = vm[name].as<std::string>();
  double value = 0.0;
  try {
    value = parse_real(text, option);
  } catch (const UsageError& e) {
    throw UsageError(std::string(e.what()) + "; valid range: " + range);
  }
  if (!in_range(value)) throw UsageError(option + " = " + text + " is outside its range: " + range);
  return value;
}

void add_parameter_option(po::options_description& opts, const model::Parameter& parameter,
                          const std::string& requirement) {
  const std::string name(parameter.name);
  std::string upper;
  for (const char c : name) upper += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const std::string needed = !requirement.empty()               ? requirement
                             : parameter.point_default.empty() ? std::string("required")
                                                               : "default " + std::string(parameter.point_default);
  const std::string help = std::string(parameter.meaning) + "; " + needed + "; " + std::string(parameter.range);
  auto* value = po::value<std::string>()->value_name(upper);
  if (!parameter.point_default.empty()) value->default_value(std::string(parameter.point_default));
  opts.add_options()(name.c_str(), value, help.c_str());
}

std::string out_of_range(const model::Parameter& parameter, const std::string& text) {
  return "--" + std::string(parameter.name) + " = " + text + " is outside its range: " + std::string(parameter.range);
}

double read_parameter(const po::variables_map& vm, const model::Parameter& parameter, const PhysicalScales* scales) {
  const std::string name(parameter.name);
  const std::string option = "--" + name;
  const std::string range(parameter.range);
  if (!vm.count(name)) {
    throw UsageError("missing required option " + option + " (" + std::string(parameter.long_name) + "; " + range + ")");
  }
  const std::string text = vm[name].as<std::string>();
  double value = 0.0;
  // A scaled parameter given with a unit (--l 150um, --pbar 20kPa) is divided by its scale.
  if (const std::optional<input::Scale> scale = input::scale_of(parameter.scale, scales ? *scales : PhysicalScales{});
      scale && input::has_unit(text)) {
    try {
      value = input::read_scaled(text, *scale);
    } catch (const std::invalid_argument& e) {
      throw UsageError(option + " = " + e.what() + "; valid range: " + range);
    }
    if (!parameter.admits(value)) {
      throw UsageError(option + " = " + text + " (" + json_number(value) + " " + std::string(parameter.scale) +
                       ") is outside its range: " + range);
    }
    return value;
  }
  try {
    value = parameter.integer ? parse_integer(text, option) : parse_real(text, option);
  } catch (const UsageError& e) {
    if (parameter.integer) throw UsageError(out_of_range(parameter, text));
    throw UsageError(std::string(e.what()) + "; valid range: " + range);
  }
  if (!parameter.admits(value)) throw UsageError(out_of_range(parameter, text));
  return value;
}

model::Shape read_shape(const po::variables_map& vm) {
  model::Shape shape;
  shape.s = static_cast<int>(read_parameter(vm, *model::find_parameter(model::kExponent)));
  shape.C = read_parameter(vm, *model::find_parameter(model::kShapeConstant));
  return shape;
}

void add_point_options(po::options_description& opts, const model::CreepLawSpec& law) {
  opts.add_options()("help", "print this help and exit");
  for (const model::Parameter* p : model::sweep_axes(law.parameters)) add_parameter_option(opts, *p);
  add_parameter_option(opts, *model::find_parameter(model::kShapeConstant));
  add_times_option(opts);
}

void add_times_option(po::options_description& opts) {
  opts.add_options()("times", po::value<std::string>()->value_name("LIST")->default_value("0,0.5,1,2,5"),
                     (std::string("snapshot times in T_eps: a list (commas and/or spaces), linspace(a, b, n) or "
                                  "logspace(a, b, n); ") +
                      kTimesRange)
                         .c_str());
}

model::ContactProblem read_problem(const po::variables_map& vm) {
  model::ContactProblem problem;
  problem.l = read_parameter(vm, *model::find_parameter(model::kPitch));
  problem.dh = read_parameter(vm, *model::find_parameter(model::kHeightDifference));
  problem.pbar0 = read_parameter(vm, *model::find_parameter(model::kPressure));
  problem.shape = read_shape(vm);
  return problem;
}

void add_localization_option(po::options_description& opts, const std::string& fallback) {
  opts.add_options()("localization", po::value<std::string>()->value_name("L")->default_value(fallback),
                     ("the model (docs/model.md, sections 11, 14): " + model::localization_spellings()).c_str());
}

model::Localization read_localization(const po::variables_map& vm) {
  try {
    return model::parse_localization(vm["localization"].as<std::string>());
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--localization: ") + e.what());
  }
}

std::optional<double> read_physical_pressure(const po::variables_map& vm, const model::Material* material) {
  if (!vm.count("pressure")) return std::nullopt;
  const std::string text = vm["pressure"].as<std::string>();
  if (material == nullptr) throw UsageError("--pressure = " + text + ": needs --material (E0* in Pa); use --pbar");
  if (vm.count("pbar")) throw UsageError("--pressure and --pbar both given; valid: one of them");
  if (!has_unit(text)) {
    throw UsageError("--pressure = " + text + ": no unit; valid: a number followed by " +
                     model::unit_names(model::Dimension::pressure) + " (50kPa)");
  }
  double pbar = 0.0;
  try {
    pbar = read_scaled(text, *scale_of(model::problem_parameter(model::kPressure)->scale, scales_of(material)));
  } catch (const std::invalid_argument& e) {
    throw UsageError("--pressure = " + std::string(e.what()));
  }
  if (!(pbar > 0.0)) throw UsageError("--pressure = " + text + " is outside its range: pressure > 0");
  return pbar;
}

model::LoadShape read_loading(const po::variables_map& vm, double* ramp_time, std::string* table_text,
                             const PhysicalScales& scales) {
  const char* range = "ramp time t_r >= 0 (0 is a step)";
  if (vm.count("ramp") && input::has_unit(vm["ramp"].as<std::string>())) {  // --ramp 30s, with a material
    const std::string text = vm["ramp"].as<std::string>();
    try {
      *ramp_time = input::read_scaled(text, *input::scale_of("T_eps", scales));
    } catch (const std::invalid_argument& e) {
      throw UsageError("--ramp = " + std::string(e.what()) + "; valid range: " + range);
    }
    if (!(*ramp_time >= 0.0)) throw UsageError("--ramp = " + text + " is outside its range: " + range);
  } else {
    *ramp_time = read_real(vm, "ramp", "ramp time", range, [](double v) { return v >= 0.0; });
  }
  table_text->clear();
  if (!vm.count("load-table")) return model::LoadShape::ramp(*ramp_time);
  if (*ramp_time > 0.0) throw UsageError("--ramp and --load-table both given; valid: one of them");
  *table_text = vm["load-table"].as<std::string>();
  return parse_load_table(*table_text, "--load-table");
}

PointInputs read_point_inputs(const po::variables_map& vm, const model::CreepLawSpec& law) {
  return read_point_inputs(vm, law, std::nullopt, {});
}

PointInputs read_point_inputs(const po::variables_map& vm, const model::CreepLawSpec& law,
                              std::optional<double> pbar, const PhysicalScales& scales) {
  PointInputs inputs;
  inputs.scales = scales;
  // Each parameter read once, in the order of the options, so the first bad one is reported.
  const model::PointAxes axes(law.parameters, false);
  std::vector<double> values;
  for (const model::PointAxis& axis : axes) {
    const model::Parameter* p = axis.parameter;
    const bool given = pbar && axis.coordinate == model::Coordinate::pressure;
    if (given && !p->admits(*pbar)) throw UsageError("--pressure gives " + p->error(*pbar));
    values.push_back(given ? *pbar : read_parameter(vm, *p, &scales));
    inputs.values.emplace_back(p, values.back());
  }
  const model::Parameter& C = *model::find_parameter(model::kShapeConstant);
  inputs.values.emplace_back(&C, read_parameter(vm, C, &scales));
  model::PointValues point;
  point.problem.shape.C = inputs.values.back().second;
  axes.set(values, &point);
  inputs.problem = point.problem;
  inputs.law = &law;
  inputs.law_values = point.law;
  try {
    inputs.creep = model::make_creep_law(law, inputs.law_values);
  } catch (const std::invalid_argument& e) {
    // A range the law itself holds its parameters to (a material's WLF temperature range),
    // named as the option it came from: "temperature = 40 is outside ...".
    throw UsageError("--" + std::string(e.what()));
  }
  return inputs;
}

std::shared_ptr<const model::Material> read_material_file(const std::string& path, const std::string& option) {
  const std::string text = read_text_file(path, option.empty() ? "material file" : option + " = material file");
  try {
    return std::make_shared<const model::Material>(read_material_text(text, path));
  } catch (const model::MaterialError& e) {
    throw UsageError(e.what());
  }
}

namespace {
PointMaterial point_material_at(const std::optional<std::string>& path) {
  if (!path) return {nullptr, model::creep_laws().front()};
  std::shared_ptr<const model::Material> material = read_material_file(*path);
  return {material, material->spec()};
}
}  // namespace

PointMaterial find_point_material(const std::vector<std::string>& args) {
  std::optional<std::string> path;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--material" && i + 1 < args.size()) path = args[i + 1];
    if (args[i].rfind("--material=", 0) == 0) path = args[i].substr(11);
  }
  return point_material_at(path);
}

PointMaterial find_point_material(const Keywords& keywords) {
  std::optional<std::string> path;
  for (const auto& [name, text] : keywords) {
    if (name == "material") path = text;
  }
  return point_material_at(path);
}

model::LoadShape parse_load_table(const std::string& text, const std::string& key) {
  std::vector<model::LoadShape::Point> points;
  std::string item;
  std::istringstream list(text);
  const std::string form = "; valid: t:phi, t:phi, ... from 0:phi0 to t_n:1, non-decreasing phi in [0, 1]";
  while (std::getline(list, item, ',')) {
    const auto colon = item.find(':');
    if (colon == std::string::npos) throw UsageError(key + " = '" + text + "': '" + item + "' is not t:phi" + form);
    try {
      points.push_back({parse_real(item.substr(0, colon), key), parse_real(item.substr(colon + 1), key)});
    } catch (const UsageError&) {
      throw UsageError(key + " = '" + text + "': '" + item + "' is not two numbers t:phi" + form);
    }
  }
  try {
    return model::LoadShape::table(points);
  } catch (const std::invalid_argument& e) {
    throw UsageError(key + " = '" + text + "': " + e.what());
  }
}

void add_material_options(po::options_description& opts) {
  opts.add_options()("material", po::value<std::string>()->value_name("FILE"),
                     "material file (materials/NAME.ini: a Prony or Kelvin series or a power law in physical units, with an optional WLF/Arrhenius shift and then --temperature); replaces "
                     "--T, times are then in the file's time_unit")(
      "ramp", po::value<std::string>()->value_name("TR")->default_value("0"),
      "ramp time t_r: the nominal pressure rises linearly to pbar over t_r, then holds (time unit as --times; "
      "0 is a step); t_r >= 0")(
      "pressure", po::value<std::string>()->value_name("P"),
      "with --material, the nominal pressure in physical units instead of --pbar: a number and Pa, kPa, MPa or "
      "GPa (50kPa); pbar = P / E0*; --pbar 50kPa says the same")(
      "R", po::value<std::string>()->value_name("LENGTH"),
      "the punch size R of f(r) = C r^s / R^(s-1) with its unit (m, mm, um or nm; for a spherical cap, s = 2 and "
      "C = 0.5, its radius of curvature), e.g. 50um: --l and --dh may then be given with a length unit (150um) "
      "and the output adds them in R's unit")(
      "load-table", po::value<std::string>()->value_name("T:PHI,..."),
      "the nominal pressure pbar phi(t), phi piecewise linear through the points t:phi (time unit as --times), "
      "from 0:phi0 to t_n:1 and non-decreasing (a load that falls is refused: the model holds while the contact "
      "does not recede); instead of --ramp");
}

PhysicalScales read_physical_scales(const po::variables_map& vm, const model::Material* material) {
  if (!vm.count("R")) return input::scales_of(material);
  try {
    return input::scales_of(material, input::read_length_scale(vm["R"].as<std::string>()));
  } catch (const std::invalid_argument& e) {
    throw UsageError("--R = " + std::string(e.what()));
  }
}

PointInputs read_point_inputs(const po::variables_map& vm, const PointMaterial& material) {
  PointInputs inputs = read_point_inputs(vm, material.spec, read_physical_pressure(vm, material.material.get()),
                                         read_physical_scales(vm, material.material.get()));
  inputs.material = material.material;
  inputs.time_unit = material.time_unit();
  double ramp = 0.0;
  inputs.problem.loading = read_loading(vm, &ramp, &inputs.load_text, inputs.scales);
  if (ramp > 0.0) inputs.values.emplace_back(&model::ramp_time_parameter(), ramp);
  return inputs;
}

std::string PointInputs::describe() const {
  std::string text;
  for (const auto& [p, value] : values) {
    if (!text.empty()) text += ", ";
    text.append(p->name);
    text += " = ";
    text += json_number(value);
    if (p->scale == "T_eps") {
      text += ' ' + time_unit;
    } else if (p->scale != "1") {
      text += ' ';
      text.append(p->scale);
    }
    // An echo in physical units where the scale is known (R's unit, Pa), to 12 digits.
    if (const std::optional<PhysicalUnit> unit = physical_unit(p->scale, scales); unit && p->scale != "T_eps") {
      char physical[64];
      std::snprintf(physical, sizeof physical, " (%.12g ", value * unit->per_scaled);
      text += physical + unit->units + ")";
    }
  }
  if (scales.R) text += ", R = " + json_number(scales.R->number) + " " + std::string(scales.R->unit->name);
  if (!load_text.empty()) text += ", load table " + load_text + " (t in " + time_unit + ": fraction of pbar)";
  if (!problem.localization.is_paper()) text += ", localization " + problem.localization.spelling();
  return text;
}

std::vector<double> read_times(const po::variables_map& vm, const PhysicalScales& scales) {
  const std::string text = vm["times"].as<std::string>();
  std::string problem;
  map::Axis times;
  try {
    times = input::read_scaled_axis(text, false, *input::scale_of("T_eps", scales));
    for (const double t : times.values) {
      if (t < 0.0) problem = "value " + input::format_axis_value(t) + " is negative";
    }
  } catch (const std::invalid_argument& e) {
    problem = e.what();
  }
  if (!problem.empty()) throw UsageError("--times = '" + text + "': " + problem + "; valid range: " + kTimesRange);
  return times.values;
}

std::vector<double> read_real_list(const po::variables_map& vm, const char* name, const char* range,
                                   const std::function<bool(double)>& in_range) {
  const std::string option = std::string("--") + name;
  const std::vector<double> values = parse_real_list(vm[name].as<std::string>(), option);
  for (const double v : values) {
    if (!in_range(v)) {
      std::ostringstream msg;
      msg << option << ": value " << v << " is outside its range: " << range;
      throw UsageError(msg.str());
    }
  }
  return values;
}

std::string read_choice(const po::variables_map& vm, const char* name, const std::vector<std::string>& allowed) {
  const std::string text = vm[name].as<std::string>();
  std::string list;
  for (const std::string& a : allowed) {
    if (a == text) return text;
    list += (list.empty() ? "" : ", ") + a;
  }
  throw UsageError(std::string("--") + name + " = '" + text + "' is not one of: " + list);
}

std::string json_string(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      quoted += buf;
      continue;
    }
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

std::string json_array(const std::vector<double>& values) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i) text += (i > 0 ? ", " : "") + json_number(values[i]);
  return text + "]";
}

std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

}  // namespace punchsweep::input

namespace punchsweep::input {

void add_tolerance_option(po::options_description& opts) {
  opts.add_options()(
      "tolerance", po::value<std::string>()->value_name("NAME=VALUE,..."),
      "tolerances on the inputs, e.g. 'dh=0.05um, pressure=5%, temperature=1': the point\n"
      "reports the least and greatest t* over them (t_star_low, t_star_high). VALUE is a\n"
      "percentage of the input, a number in its scale, or a number with a unit");
}

std::vector<model::StatedTolerance> parse_tolerances(
    const std::string& all, const std::string& key,
    const std::function<const model::Parameter*(std::string_view)>& known, const PhysicalScales& scales,
    const std::string& names, const std::string& unknown,
    const std::function<std::string(const model::StatedTolerance&)>& refuse) {
  std::vector<model::StatedTolerance> out;
  const auto bad = [&](const std::string& entry, const std::string& why) {
    return UsageError(key + " '" + entry + "': " + why + " (valid: NAME=VALUE, NAME one of " + names +
                      "; VALUE >= 0: a percentage such as 5%, a number in the input's scale, or one with a unit such "
                      "as 0.05um or 200Pa)");
  };
  std::size_t start = 0;
  while (start <= all.size()) {
    const std::size_t comma = std::min(all.find(',', start), all.size());
    std::string entry = all.substr(start, comma - start);
    start = comma + 1;
    entry.erase(0, entry.find_first_not_of(" \t"));
    entry.erase(entry.find_last_not_of(" \t") + 1);
    if (entry.empty()) {
      if (comma == all.size()) break;
      continue;
    }
    const auto eq = entry.find('=');
    if (eq == std::string::npos) throw bad(entry, "no '='");
    std::string name = entry.substr(0, eq), text = entry.substr(eq + 1);
    name.erase(name.find_last_not_of(" \t") + 1);
    text.erase(0, text.find_first_not_of(" \t"));
    if (name == "pressure") name = std::string(model::kPressure);
    const model::Parameter* parameter = known(name);
    if (parameter == nullptr || parameter->integer) throw bad(entry, "'" + name + "' " + unknown);
    for (const model::StatedTolerance& given : out) {
      if (given.parameter == parameter) throw bad(entry, "'" + name + "' is given twice");
    }
    model::StatedTolerance tol{parameter, 0.0, false, text};
    try {
      if (!text.empty() && text.back() == '%') {
        tol.relative = true;
        tol.width = parse_real(text.substr(0, text.size() - 1), key) / 100.0;
      } else if (parameter->name == model::temperature_parameter().name) {
        const std::string unit = text.substr(std::min(text.find_first_not_of("0123456789.eE+-"), text.size()));
        if (!(unit.empty() || unit == "K" || unit == "degC" || unit == "C")) throw UsageError("not a temperature difference");
        tol.width = parse_real(text.substr(0, text.size() - unit.size()), key);
      } else if (const std::optional<Scale> scale = scale_of(parameter->scale, scales)) {
        tol.width = read_scaled(text, *scale);
      } else {
        tol.width = parse_real(text, key);
      }
    } catch (const UsageError& e) {
      throw bad(entry, e.what());
    } catch (const std::invalid_argument& e) {
      throw bad(entry, e.what());
    }
    if (!(std::isfinite(tol.width) && tol.width >= 0.0)) throw bad(entry, "the tolerance is not a number >= 0");
    if (refuse) {
      if (const std::string why = refuse(tol); !why.empty()) throw bad(entry, why);
    }
    out.push_back(tol);
  }
  return out;
}

std::vector<model::Tolerance> read_tolerances(const po::variables_map& vm, PointInputs& inputs) {
  std::vector<model::Tolerance> out;
  if (!vm.count("tolerance")) return out;
  const std::string all = vm["tolerance"].as<std::string>();
  const auto value_of = [&](const model::Parameter* p) {
    for (const auto& [q, v] : inputs.values) {
      if (q == p) return v;
    }
    return 0.0;
  };
  const auto known = [&](std::string_view name) -> const model::Parameter* {
    for (const auto& [p, v] : inputs.values) {
      if (p->name == name) return p;
    }
    return nullptr;
  };
  for (const model::StatedTolerance& t :
       parse_tolerances(all, "--tolerance", known, inputs.scales,
                        "l, dh, pbar or pressure, C, and the law's T or temperature")) {
    bool clipped = false;
    out.push_back(t.at(value_of(t.parameter), &clipped));
    // Below a range that starts at 0 (dh >= 0): the box's low side at 0, and said so.
    if (clipped) {
      const std::string name(t.parameter->name);
      inputs.notes.push_back("--tolerance " + name + "=" + t.text + ": " + name + " minus " + t.text +
                             " is below 0; the box's low " + name + " is taken at 0");
    }
  }
  return out;
}

}  // namespace punchsweep::input

namespace punchsweep::input {

void add_cap_options(po::options_description& opts) {
  opts.add_options()
      ("cap-radius", po::value<std::string>()->value_name("B"),
       "the base radius of the spherical caps the punches are, in R or with a unit (30um):\n"
       "the point is advised 'beyond_cap' where a contact spot outgrows it")
      ("cap-height", po::value<std::string>()->value_name("H"),
       "or the caps' height (s = 2, C = 0.5): base radius sqrt(H (2R - H))");
}

std::optional<double> read_cap_radius(const po::variables_map& vm, const PointInputs& inputs) {
  if (vm.count("cap-radius") && vm.count("cap-height")) throw UsageError("give --cap-radius or --cap-height, not both");
  for (const char* name : {"cap-radius", "cap-height"}) {
    if (!vm.count(name)) continue;
    const std::string text = vm[name].as<std::string>();
    const std::string option = std::string("--") + name;
    double v = 0.0;
    try {
      v = read_scaled(text, *scale_of("R", inputs.scales));
    } catch (const std::invalid_argument& e) {
      throw UsageError(option + " = '" + text + "': " + e.what());
    }
    const bool height = std::string(name) == "cap-height";
    if (!(std::isfinite(v) && v > 0.0 && (!height || v <= 1.0))) {
      throw UsageError(option + " = " + text + " is outside its range: " +
                       (height ? "0 < H <= R (a hemisphere at most)" : "B > 0"));
    }
    if (height && !(inputs.problem.shape.s == 2 && inputs.problem.shape.C == 0.5)) {
      throw UsageError(option + ": a cap's height gives its base radius only for a sphere (s = 2, C = 0.5); give "
                       "--cap-radius");
    }
    return height ? model::cap_base_radius(v) : v;
  }
  return std::nullopt;
}

po::options_description point_options(const PointMaterial& material) {
  po::options_description opts(
      "punchsweep point: regime, t*, and the contact state over time of one parameter point\n"
      "(two-level square lattice of punches f(r) = C r^s / R^(s-1) pressed with constant\n"
      "nominal pressure into a standard linear solid, or the material of --material FILE).\n\n"
      "Units: lengths in R (punch size), pressures in E0* = E0/(1-nu^2), loads in R^2 E0*,\n"
      "time in T_eps (creep time), or in the material file's time_unit.\n\nOptions");
  add_point_options(opts, material.spec);
  add_material_options(opts);
  add_localization_option(opts, std::string(model::kDefaultLocalization));
  add_tolerance_option(opts);
  add_cap_options(opts);
  opts.add_options()
      ("format", po::value<std::string>()->value_name("FMT")->default_value("table"),
       "output format: table, json or csv");
  return opts;
}

}  // namespace punchsweep::input
