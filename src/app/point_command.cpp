#include "app/point_command.hpp"

#include <boost/program_options.hpp>

#include <ostream>
#include <sstream>

#include "app/point_output.hpp"
#include "app/usage_error.hpp"
#include "app/value_parsing.hpp"
#include "model/point_evaluation.hpp"
#include "model/standard_linear_solid.hpp"

namespace po = boost::program_options;

namespace punchsweep::app {
namespace {

constexpr const char* kUsage = "usage: punchsweep point --l L --dh DH --T T --pbar P --s S [options]";

po::options_description point_options() {
  po::options_description opts(
      "punchsweep point: regime, t*, and the contact state over time of one parameter point\n"
      "(two-level square lattice of punches f(r) = C r^s / R^(s-1) pressed with constant\n"
      "nominal pressure into a standard linear solid).\n\n"
      "Units: lengths in R (punch size), pressures in E0* = E0/(1-nu^2), loads in R^2 E0*,\n"
      "time in T_eps (creep time).\n\nOptions");
  opts.add_options()
      ("help", "print this help and exit")
      ("l", po::value<std::string>()->value_name("L"),
       "lattice pitch l, in R; required; l > 0")
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
       "snapshot times, comma-separated, in T_eps; each finite and >= 0")
      ("format", po::value<std::string>()->value_name("FMT")->default_value("table"),
       "output format: table, json or csv");
  return opts;
}

}  // namespace

int run_point_command(const std::vector<std::string>& args, std::ostream& out) {
  const po::options_description opts = point_options();
  po::variables_map vm;
  const po::positional_options_description no_positionals;
  try {
    // Long options only, so that "--l -0.5" reads -0.5 as a value, not as an option.
    const auto style = po::command_line_style::unix_style ^ po::command_line_style::allow_short;
    po::store(po::command_line_parser(args).options(opts).style(style).positional(no_positionals).run(), vm);
    po::notify(vm);
  } catch (const po::unknown_option& e) {
    throw UsageError("unknown option " + e.get_option_name() + " (see punchsweep point --help)");
  } catch (const po::too_many_positional_options_error&) {
    throw UsageError("unexpected argument (every input is an --option; see punchsweep point --help)");
  } catch (const po::error& e) {
    throw UsageError(std::string(e.what()) + " (see punchsweep point --help)");
  }
  if (vm.count("help")) {
    out << kUsage << "\n\n" << opts << "\n"
        << "Example: punchsweep point --l 0.75 --dh 0.075 --T 2.5 --pbar 0.06 --s 2 --format json\n"
        << "Exit codes: 0 success (a flagged point is still a success: see 'valid'), 2 bad input.\n";
    return 0;
  }

  // Each numeric option: its valid range (as printed) and the test of it.
  const auto real = [&](const char* name, const char* meaning, const char* range, auto in_range) {
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
    if (!in_range(value)) {
      throw UsageError(option + " = " + text + " is outside its range: " + range);
    }
    return value;
  };
  model::ContactProblem problem;
  problem.l = real("l", "lattice pitch", "l > 0 (in R)", [](double v) { return v > 0.0; });
  problem.dh = real("dh", "height difference", "dh >= 0 (in R)", [](double v) { return v >= 0.0; });
  const double T = real("T", "creep ratio", "T = T_eps/T_sigma >= 1",
                        [](double v) { return model::creep_ratio_error(v).empty(); });
  problem.pbar0 = real("pbar", "nominal pressure", "pbar > 0 (in E0*)", [](double v) { return v > 0.0; });
  const char* s_range = "an integer in [1, 32]";
  if (!vm.count("s")) throw UsageError(std::string("missing required option --s (shape exponent; ") + s_range + ")");
  const std::string s_text = vm["s"].as<std::string>();
  try {
    problem.shape.s = parse_integer(s_text, "--s");
  } catch (const UsageError&) {
    throw UsageError("--s = " + s_text + " is outside its range: " + s_range);
  }
  if (problem.shape.s < model::Shape::kMinExponent || problem.shape.s > model::Shape::kMaxExponent) {
    throw UsageError("--s = " + s_text + " is outside its range: " + s_range);
  }
  problem.shape.C = real("C", "shape constant", "C > 0", [](double v) { return v > 0.0; });

  model::EvaluationOptions options;
  options.times = parse_real_list(vm["times"].as<std::string>(), "--times");
  for (const double t : options.times) {
    if (t < 0.0) {
      std::ostringstream msg;
      msg << "--times: time " << t << " is outside its range: t >= 0 (in T_eps)";
      throw UsageError(msg.str());
    }
  }

  const std::string format_text = vm["format"].as<std::string>();
  OutputFormat format;
  if (format_text == "table") format = OutputFormat::table;
  else if (format_text == "json") format = OutputFormat::json;
  else if (format_text == "csv") format = OutputFormat::csv;
  else throw UsageError("--format = '" + format_text + "' is not one of: table, json, csv");

  const model::StandardLinearSolid creep(T);
  const model::PointResult result = model::evaluate_point(problem, creep, options);
  write_point(out, format, problem, creep, result);
  return 0;
}

}  // namespace punchsweep::app
