#include "app/reference_command.hpp"

#include <boost/program_options.hpp>

#include <cstdio>
#include <ostream>

#include "engine/reference_evaluation.hpp"
#include "input/command_options.hpp"

namespace po = boost::program_options;

namespace punchsweep::app {
namespace {

template <class Field>
std::string series_array(const reference::ReferenceResult& r, Field field) {
  std::string text = "[";
  for (std::size_t i = 0; i < r.series.size(); ++i) text += (i ? ", " : "") + input::json_number(field(r.series[i]));
  return text + "]";
}

}  // namespace

int run_reference_command(const std::vector<std::string>& args, std::ostream& out) {
  const input::PointMaterial material = input::find_point_material(args);
  const po::options_description opts = engine::reference_options(material);
  const po::variables_map vm = input::parse_command(args, opts, "reference");
  if (vm.count("help")) {
    out << "usage: punchsweep reference --l L --dh DH --T T --pbar P --s S [--bem-grid N] [options]\n\n" << opts
        << "\nRadii are equivalent radii sqrt(area / pi) of the nodes in contact: their error is of\n"
           "order one grid spacing (about 1% needs a/h >= 15).\n";
    return 0;
  }
  engine::ReferenceRun run = engine::read_reference(vm, material);
  const std::string format = input::read_choice(vm, "format", {"json", "table"});
  engine::solve_reference(&run);
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
