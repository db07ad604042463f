#include "app/reference_command.hpp"

#include <boost/program_options.hpp>

#include <chrono>
#include <cstdio>
#include <ostream>

#include "input/command_options.hpp"
#include "input/usage_error.hpp"
#include "reference/reference_point.hpp"
#include "sweep/reproducible_fft.hpp"
#include "sweep/sweep_config.hpp"

namespace po = boost::program_options;

namespace punchsweep::app {
namespace {

template <class Field>
std::string series_array(const reference::ReferenceResult& r, Field field) {
  std::string text = "[";
  for (std::size_t i = 0; i < r.series.size(); ++i) text += (i ? ", " : "") + input::json_number(field(r.series[i]));
  return text + "]";
}

po::options_description reference_options(const input::PointMaterial& material) {
  po::options_description opts(
      "punchsweep reference: one parameter point solved by the periodic boundary-element\n"
      "reference solver (the full two-level contact problem on an N x N grid of the l x l\n"
      "cell, FFT influence, constrained conjugate gradient, viscoelastic creep stepping),\n"
      "with the inputs and series of `punchsweep point`, to hold the localization model to.\n\n"
      "Units: lengths in R, pressures in E0* = E0/(1-nu^2), loads in R^2 E0*, time in T_eps\n"
      "(or the --material file's time_unit).\n\n"
      "Options");
  input::add_point_options(opts, material.spec);
  input::add_material_options(opts);
  opts.add_options()
      ("bem-grid", po::value<std::string>()->value_name("N")->default_value("128"),
       "grid nodes per side N (the cell spacing is l/N); an even integer in [16, 2048]")
      ("format", po::value<std::string>()->value_name("FMT")->default_value("json"), "output format: json or table");
  return opts;
}

/// The point's inputs and the solver's options, read and checked in the command's order.
ReferenceRun read_reference(const po::variables_map& vm, const input::PointMaterial& material) {
  ReferenceRun run{input::read_point_inputs(vm, material), {}, {}, 0.0};
  reference::scale_steps_to_law(*run.inputs.creep, &run.options);
  run.options.times = input::read_times(vm, run.inputs.scales);
  run.options.n = static_cast<int>(input::read_real(vm, "bem-grid", "grid nodes per side", "an even integer in [16, 2048]",
                                             [](double v) { return sweep::is_bem_grid(v); }));
  return run;
}

void solve(ReferenceRun* run) {
  // As in `punchsweep sweep --reference bem`, so that a point gives the same bits in both.
  sweep::use_reproducible_fft_plans();
  const auto start = std::chrono::steady_clock::now();
  run->result = reference::evaluate_reference_point(run->inputs.problem, *run->inputs.creep, run->options);
  run->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

ReferenceRun evaluate_reference(const input::Keywords& keywords, const model::StopRequest& stop) {
  const input::PointMaterial material = input::find_point_material(keywords);
  ReferenceRun run =
      read_reference(input::parse_keywords(keywords, reference_options(material), "reference"), material);
  run.options.stop = stop;
  solve(&run);
  return run;
}

int run_reference_command(const std::vector<std::string>& args, std::ostream& out) {
  const input::PointMaterial material = input::find_point_material(args);
  const po::options_description opts = reference_options(material);
  const po::variables_map vm = input::parse_command(args, opts, "reference");
  if (vm.count("help")) {
    out << "usage: punchsweep reference --l L --dh DH --T T --pbar P --s S [--bem-grid N] [options]\n\n" << opts
        << "\nRadii are equivalent radii sqrt(area / pi) of the nodes in contact: their error is of\n"
           "order one grid spacing (about 1% needs a/h >= 15).\n";
    return 0;
  }
  ReferenceRun run = read_reference(vm, material);
  const std::string format = input::read_choice(vm, "format", {"json", "table"});
  solve(&run);
  const input::PointInputs& inputs = run.inputs;
  const reference::ReferenceOptions& options = run.options;
  const reference::ReferenceResult& r = run.result;
  const double seconds = run.seconds;
  const std::string regime(model::regime_name(r.regime));
  if (format == "table") {
    char line[200];
    out << "punchsweep reference: " << inputs.describe() << "; grid " << options.n << " x " << options.n << " (h = "
        << input::json_number(r.spacing) << " R)\n  regime " << regime << ", t_star "
        << (r.t_star ? input::json_number(*r.t_star) + " " + inputs.time_unit : "none") << ", converged " << (r.converged ? "yes" : "no")
        << " (" << r.cg_iterations << " CG iterations, largest residual " << input::json_number(r.max_residual) << "), "
        << r.steps << " steps, " << r.solves << " solves, " << input::json_number(seconds) << " s\n"
        << "   t [" << inputs.time_unit << "]      a1 [R]      a2 [R]   P1 [R^2 E0*]   P2 [R^2 E0*]  area_fraction\n";
    for (const auto& s : r.series) {
      std::snprintf(line, sizeof line, "%12.4f%12.7f%12.7f%15.9f%15.9f%15.7f\n", s.t, s.a1, s.a2, s.P1, s.P2,
                    s.area_fraction);
      out << line;
    }
    return 0;
  }
  out << "{\n  \"regime\": \"" << regime << "\",\n  \"t_star\": " << (r.t_star ? input::json_number(*r.t_star) : "null")
      << ",\n  \"t_star_lower\": " << input::json_number(r.t_star_lower) << ",\n  \"t_star_upper\": "
      << input::json_number(r.t_star_upper) << ",\n  \"converged\": " << (r.converged ? "true" : "false")
      << ",\n  \"cg_iterations\": " << r.cg_iterations << ",\n  \"max_residual\": " << input::json_number(r.max_residual)
      << ",\n  \"bem_grid\": " << options.n << ",\n  \"spacing\": " << input::json_number(r.spacing)
      << ",\n  \"steps\": " << r.steps << ",\n  \"solves\": " << r.solves << ",\n  \"seconds\": " << input::json_number(seconds)
      << ",\n  \"series\": {\n    \"t\": " << series_array(r, [](const auto& s) { return s.t; })
      << ",\n    \"a1\": " << series_array(r, [](const auto& s) { return s.a1; })
      << ",\n    \"a2\": " << series_array(r, [](const auto& s) { return s.a2; })
      << ",\n    \"P1\": " << series_array(r, [](const auto& s) { return s.P1; })
      << ",\n    \"P2\": " << series_array(r, [](const auto& s) { return s.P2; })
      << ",\n    \"area_fraction\": " << series_array(r, [](const auto& s) { return s.area_fraction; })
      << ",\n    \"h\": " << series_array(r, [](const auto& s) { return s.h; }) << "\n  }\n}\n";
  return 0;
}

}  // namespace punchsweep::app
