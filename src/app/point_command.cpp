#include "app/point_command.hpp"

#include <boost/program_options.hpp>

#include <limits>
#include <ostream>

#include "input/command_options.hpp"
#include "app/point_output.hpp"
#include "input/usage_error.hpp"
#include "model/problem/localization.hpp"
#include "model/point/advisory.hpp"
#include "model/point/point_evaluation.hpp"

namespace po = boost::program_options;

namespace punchsweep::app {
namespace {

constexpr const char* kUsage = "usage: punchsweep point --l L --dh DH --T T --pbar P --s S [options]";

}  // namespace

po::options_description point_options(const input::PointMaterial& material) {
  po::options_description opts(
      "punchsweep point: regime, t*, and the contact state over time of one parameter point\n"
      "(two-level square lattice of punches f(r) = C r^s / R^(s-1) pressed with constant\n"
      "nominal pressure into a standard linear solid, or the material of --material FILE).\n\n"
      "Units: lengths in R (punch size), pressures in E0* = E0/(1-nu^2), loads in R^2 E0*,\n"
      "time in T_eps (creep time), or in the material file's time_unit.\n\nOptions");
  input::add_point_options(opts, material.spec);
  input::add_material_options(opts);
  input::add_localization_option(opts, std::string(model::kDefaultLocalization));
  input::add_tolerance_option(opts);
  input::add_cap_options(opts);
  opts.add_options()
      ("format", po::value<std::string>()->value_name("FMT")->default_value("table"),
       "output format: table, json or csv");
  return opts;
}

namespace {

/// The point's inputs read and checked, in the command's order (the first bad one is the
/// one reported), with the snapshot times and the tolerances.
PointRun read_point(const po::variables_map& vm, const input::PointMaterial& material, model::EvaluationOptions* options,
                    std::vector<model::Tolerance>* tolerances, std::optional<double>* cap_radius) {
  PointRun run{input::read_point_inputs(vm, material), {}};
  run.inputs.problem.localization = input::read_localization(vm);
  if (const std::string e = run.inputs.problem.localization.exponent_error(run.inputs.problem.shape.s); !e.empty()) {
    throw input::UsageError(e);
  }
  options->times = input::read_times(vm, run.inputs.scales);
  *tolerances = input::read_tolerances(vm, run.inputs);
  *cap_radius = input::read_cap_radius(vm, run.inputs);
  return run;
}

/// The point evaluated, with t*'s derivatives, its range over the tolerances and the
/// physical advisories.
void evaluate(PointRun& run, const model::EvaluationOptions& options, const std::vector<model::Tolerance>& tolerances,
              std::optional<double> cap_radius) {
  const input::PointInputs& in = run.inputs;
  run.result = model::evaluate_point(in.problem, *in.creep, options);
  const double t_star = run.result.t_star.value_or(std::numeric_limits<double>::infinity());
  run.result.t_star_derivatives = model::t_star_derivatives(in.problem, *in.law, in.law_values, t_star);
  const model::Advisories advice = model::advise(in.problem, run.result, cap_radius);
  run.result.advisories = advice.names();
  run.result.advisory_reason = advice.reason(cap_radius.value_or(0.0));
  run.result.strain = advice.strain;
  if (!tolerances.empty()) {
    try {
      run.result.t_star_range = model::t_star_range(in.problem, *in.law, in.law_values, tolerances);
    } catch (const std::invalid_argument& e) {
      throw input::UsageError(std::string("--tolerance: ") + e.what());
    }
  }
}

}  // namespace

int run_point_command(const std::vector<std::string>& args, std::ostream& out) {
  const input::PointMaterial material = input::find_point_material(args);
  const po::options_description opts = point_options(material);
  const po::variables_map vm = input::parse_command(args, opts, "point");
  if (vm.count("help")) {
    out << kUsage << "\n\n" << opts << "\n"
        << "Example: punchsweep point --l 0.75 --dh 0.075 --T 2.5 --pbar 0.06 --s 2 --format json\n"
        << "Exit codes: 0 success (a flagged point is still a success: see 'valid'), 2 bad input.\n";
    return 0;
  }
  model::EvaluationOptions options;
  std::vector<model::Tolerance> tolerances;
  std::optional<double> cap_radius;
  PointRun run = read_point(vm, material, &options, &tolerances, &cap_radius);
  const OutputFormat format = read_output_format(vm);
  evaluate(run, options, tolerances, cap_radius);
  write_point(out, format, run.inputs, run.result);
  return 0;
}

PointRun evaluate_point(const input::Keywords& keywords) {
  const input::PointMaterial material = input::find_point_material(keywords);
  model::EvaluationOptions options;
  std::vector<model::Tolerance> tolerances;
  std::optional<double> cap_radius;
  PointRun run = read_point(input::parse_keywords(keywords, point_options(material), "point"), material, &options,
                            &tolerances, &cap_radius);
  evaluate(run, options, tolerances, cap_radius);
  return run;
}

}  // namespace punchsweep::app
