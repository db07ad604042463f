#include "app/command_options.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "app/usage_error.hpp"
#include "app/value_parsing.hpp"
#include "model/standard_linear_solid.hpp"

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

void add_point_options(po::options_description& opts) {
  opts.add_options()
      ("help", "print this help and exit")
      ("l", po::value<std::string>()->value_name("L"), "lattice pitch l, in R; required; l > 0")
      ("dh", po::value<std::string>()->value_name("DH"),
       "height difference of the two punch levels, in R; required; dh >= 0")
      ("T", po::value<std::string>()->value_name("T"),
       "creep ratio T = T_eps/T_sigma of the standard linear solid (J(inf) = T/E0*); "
       "required; T >= 1 (T = 1: elastic)")
      ("pbar", po::value<std::string>()->value_name("P"),
       "constant nominal pressure pbar0, in E0*; required; pbar > 0")
      ("s", po::value<std::string>()->value_name("S"),
       "shape exponent s of f(r) = C r^s / R^(s-1); required; an integer in [1, 32] "
       "(1 cone, 2 paraboloid)")
      ("C", po::value<std::string>()->value_name("C")->default_value("0.5"),
       "shape constant C; C > 0 (sphere: s = 2, C = 0.5)")
      ("times", po::value<std::string>()->value_name("LIST")->default_value("0,0.5,1,2,5"),
       "snapshot times, comma-separated, in T_eps; each finite and >= 0");
}

model::ContactProblem read_problem(const po::variables_map& vm) {
  model::ContactProblem problem;
  problem.l = read_real(vm, "l", "lattice pitch", "l > 0 (in R)", [](double v) { return v > 0.0; });
  problem.dh = read_real(vm, "dh", "height difference", "dh >= 0 (in R)", [](double v) { return v >= 0.0; });
  problem.pbar0 = read_real(vm, "pbar", "nominal pressure", "pbar > 0 (in E0*)", [](double v) { return v > 0.0; });
  problem.shape = read_shape(vm);
  return problem;
}

double read_creep_ratio(const po::variables_map& vm) {
  return read_real(vm, "T", "creep ratio", "T = T_eps/T_sigma >= 1",
                   [](double v) { return model::creep_ratio_error(v).empty(); });
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
