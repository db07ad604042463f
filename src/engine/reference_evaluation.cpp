#include "engine/reference_evaluation.hpp"

#include <boost/program_options.hpp>

#include <chrono>

#include "input/usage_error.hpp"
#include "sweep/reproducible_fft.hpp"
#include "sweep/sweep_config.hpp"

namespace po = boost::program_options;

namespace punchsweep::engine {

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

ReferenceRun read_reference(const po::variables_map& vm, const input::PointMaterial& material) {
  ReferenceRun run{input::read_point_inputs(vm, material), {}, {}, 0.0};
  reference::scale_steps_to_law(*run.inputs.creep, &run.options);
  run.options.times = input::read_times(vm, run.inputs.scales);
  run.options.n = static_cast<int>(input::read_real(vm, "bem-grid", "grid nodes per side", "an even integer in [16, 2048]",
                                             [](double v) { return sweep::is_bem_grid(v); }));
  return run;
}

void solve_reference(ReferenceRun* run) {
  // As in `punchsweep sweep --reference bem`, so that a point gives the same bits in both.
  sweep::use_reproducible_fft_plans();
  const auto start = std::chrono::steady_clock::now();
  run->result = reference::evaluate_reference_point(run->inputs.problem, *run->inputs.creep, run->options);
  run->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

ReferenceRun evaluate_reference(const input::Keywords& keywords, const model::StopRequest& stop) {
  const input::PointMaterial material = input::find_point_material(keywords);
  ReferenceRun run =
      read_reference(input::parse_keywords(keywords, reference_options(material), "reference"), material);
  run.options.stop = stop;
  solve_reference(&run);
  return run;
}

}  // namespace punchsweep::engine
