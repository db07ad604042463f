#include "app/command_options.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "app/usage_error.hpp"
#include "app/value_parsing.hpp"

namespace po = boost::program_options;

namespace punchsweep::app {

po::variables_map parse_command(const std::vector<std::string>& args, const po::options_description& opts,
                                const std::string& command) {
  po::variables_map vm;
  const po::positional_options_description no_positionals;
  const std::string see = " (see punchsweep " + command + " --help)";
  try {
    const auto style = po::command_line_style::unix_style ^ po::command_line_style::allow_short;
    po::store(po::command_line_parser(args).options(opts).style(style).positional(no_positionals).run(), vm);
    po::notify(vm);
  } catch (const po::unknown_option& e) {
    throw UsageError("unknown option " + e.get_option_name() + see);
  } catch (const po::too_many_positional_options_error&) {
    throw UsageError("unexpected argument (every input is an --option;" + see.substr(1));
  } catch (const po::error& e) {
    throw UsageError(std::string(e.what()) + see);
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

model::Shape read_shape(const po::variables_map& vm) {
  const char* range = "an integer in [1, 32]";
  if (!vm.count("s")) throw UsageError(std::string("missing required option --s (shape exponent; ") + range + ")");
  const std::string text = vm["s"].as<std::string>();
  model::Shape shape;
  try {
    shape.s = parse_integer(text, "--s");
  } catch (const UsageError&) {
    throw UsageError("--s = " + text + " is outside its range: " + range);
  }
  if (shape.s < model::Shape::kMinExponent || shape.s > model::Shape::kMaxExponent) {
    throw UsageError("--s = " + text + " is outside its range: " + range);
  }
  shape.C = read_real(vm, "C", "shape constant", "C > 0", [](double v) { return v > 0.0; });
  return shape;
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

std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

}  // namespace punchsweep::app
