#include "app/curve_commands.hpp"

#include <boost/program_options.hpp>

#include <cstdio>
#include <limits>
#include <optional>
#include <ostream>

#include "input/command_options.hpp"
#include "input/usage_error.hpp"
#include "model/laws/creep_laws.hpp"
#include "model/load/creep_weighted_load.hpp"
#include "model/localization/localization_model.hpp"
#include "model/paper/elastic_two_level.hpp"
#include "model/problem/localization.hpp"
#include "model/paper/single_level.hpp"
#include "model/shells/single_level_shells.hpp"
#include "model/paper/two_level.hpp"
#include "model/point/parameters.hpp"

namespace po = boost::program_options;

namespace punchsweep::app {
namespace {

constexpr const char* kUnits =
    "Units: lengths in R (punch size), pressures and moduli in E0* = E0/(1-nu^2), loads in\n"
    "R^2 E0*, time in T_eps (creep time).\n\nOptions";

const model::Parameter& parameter(std::string_view name) { return *model::find_parameter(name); }

void add_shape_options(po::options_description& opts) {
  input::add_parameter_option(opts, parameter(model::kExponent));
  input::add_parameter_option(opts, parameter(model::kShapeConstant));
}

std::string json_array(const std::vector<double>& values) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + input::json_number(values[i]);
  return text + "]";
}

bool positive(double v) { return v > 0.0; }

}  // namespace

int run_single_level_command(const std::vector<std::string>& args, std::ostream& out) {
  po::options_description opts(std::string(
      "punchsweep single-level: the single-level phase on its own (only level-1 punches\n"
      "touch; level 2 ignored): h(a1) along the solution curve and its slope (Fig. 9.2),\n"
      "and with --pbar and --T the radius a1(t) and h(t) (Fig. 9.3). h is the displacement\n"
      "difference between a level-1 punch tip and the square centre (eq 9.10).\n\n") + kUnits);
  const input::PointMaterial point_material = input::find_point_material(args);
  const model::CreepLawSpec& law = point_material.spec;
  opts.add_options()("help", "print this help and exit");
  input::add_parameter_option(opts, parameter(model::kPitch));
  add_shape_options(opts);
  input::add_parameter_option(opts, parameter(model::kPressure), "with the creep law's parameters: time series");
  for (const model::Parameter& p : law.parameters) input::add_parameter_option(opts, p, "with --pbar: time series");
  input::add_times_option(opts);
  input::add_material_options(opts);
  opts.add_options()
      ("a1-points", po::value<std::string>()->value_name("N")->default_value("101"),
       "points of the h(a1) curve, evenly spaced in a1 from 0 to l/2; an integer in [2, 100000]")
      ("format", po::value<std::string>()->value_name("FMT")->default_value("json"), "output format: json or csv");
  input::add_localization_option(opts, "paper");
  const po::variables_map vm = input::parse_command(args, opts, "single-level");
  if (vm.count("help")) {
    out << "usage: punchsweep single-level --l L --s S [--C C] [--pbar P --T T] [options]\n\n" << opts << "\n";
    return 0;
  }
  const double l = input::read_parameter(vm, parameter(model::kPitch));
  const model::Shape shape = input::read_shape(vm);
  const double n_real = input::read_real(vm, "a1-points", "points of h(a1)", "an integer in [2, 100000]",
                                  [](double v) { return v >= 2 && v <= 100000 && v == std::floor(v); });
  const std::size_t n = static_cast<std::size_t>(n_real);
  bool series = vm.count("pbar") > 0 || vm.count("pressure") > 0 || point_material.material != nullptr;
  for (const model::Parameter& p : law.parameters) series = series || vm.count(std::string(p.name)) > 0;
  const std::string format = input::read_choice(vm, "format", {"json", "csv"});
  const model::Localization localization = input::read_localization(vm);
  if (localization.periodic) {
    throw input::UsageError("--localization: periodic has no h(a1) curve to draw here (its tables are in the load X: "
                     "`punchsweep point --localization periodic` gives a1(t) and h(t)); valid here: paper, refined, "
                     "shells:D, point-shells:D");
  }

  // h(a1) up to 2 a1 = l (beyond, level-1 spots merge: the model's validity ends there);
  // null where the localization model has no solution (beyond its radius limit).
  std::vector<double> a1_curve;
  std::vector<double> h_curve;
  std::vector<double> rate_curve;
  std::vector<double> times;
  std::vector<double> a1_t;
  std::vector<double> h_t;
  std::unique_ptr<model::CreepLaw> creep;
  std::string material;  // "T = 2.5": the law's parameters as given
  model::LoadShape loading;
  double pbar = 0.0;
  double h_inf = 0.0;
  const auto compute = [&](const auto& single) {
    for (std::size_t i = 0; i < n; ++i) {
      const double a1 = 0.5 * l * static_cast<double>(i) / static_cast<double>(n - 1);
      a1_curve.push_back(a1);
      h_curve.push_back(i == 0 ? 0.0 : single.displacement_difference(a1));
      rate_curve.push_back(i == 0 ? 0.0 : single.displacement_difference_rate(a1));
    }
    if (!series) return;
    const std::optional<double> physical = input::read_physical_pressure(vm, point_material.material.get());
    pbar = physical ? *physical : input::read_parameter(vm, parameter(model::kPressure));
    std::vector<double> values;
    if (point_material.material) material = point_material.material->name();
    for (const model::Parameter& p : law.parameters) {
      values.push_back(input::read_parameter(vm, p));
      material += (material.empty() ? "" : ", ") + std::string(p.name) + " = " + input::json_number(values.back());
    }
    creep = model::make_creep_law(law, values);
    times = input::read_times(vm);
    double ramp = 0.0;
    std::string table;
    loading = input::read_loading(vm, &ramp, &table);
    if (ramp > 0.0) material += ", ramp over " + input::json_number(ramp) + " " + point_material.time_unit();
    if (!table.empty()) material += ", load table " + table;
    const model::CreepWeightedLoad load(*creep, pbar, loading);
    for (const double t : times) {
      const double X = load(t);
      a1_t.push_back(single.contact_radius(X));
      h_t.push_back(single.displacement_difference(a1_t.back(), X));
    }
    const double X_inf = load.final();
    h_inf = single.displacement_difference(single.contact_radius(X_inf), X_inf);
  };
  if (localization.is_paper()) {
    compute(model::SingleLevel(l, shape));
  } else {
    compute(model::SingleLevelShells(l, shape, localization));
  }

  if (format == "csv") {
    out << "# punchsweep single-level: l = " << input::json_number(l) << " R, s = " << shape.s << ", C = " << input::json_number(shape.C)
        << "\n# h(a1) along the solution curve; units: a1 and h in R, dh_da1 dimensionless\na1,h,dh_da1\n";
    for (std::size_t i = 0; i < n; ++i) {
      out << input::json_number(a1_curve[i]) << ',' << input::json_number(h_curve[i]) << ',' << input::json_number(rate_curve[i]) << "\n";
    }
    if (series) {
      out << "\n# time series at pbar0 = " << input::json_number(pbar) << " E0*, " << material
          << "; units: t in " << point_material.time_unit() << ", a1 and h in R\nt,a1,h\n";
      for (std::size_t i = 0; i < times.size(); ++i) {
        out << input::json_number(times[i]) << ',' << input::json_number(a1_t[i]) << ',' << input::json_number(h_t[i]) << "\n";
      }
    }
    return 0;
  }
  out << "{\n  \"h_of_a1\": {\n    \"a1\": " << json_array(a1_curve) << ",\n    \"h\": " << json_array(h_curve)
      << ",\n    \"dh_da1\": " << json_array(rate_curve) << "\n  }";
  if (series) {
    out << ",\n  \"h_inf\": " << input::json_number(h_inf)
        << ",\n  \"series\": {\n    \"t\": " << json_array(times) << ",\n    \"a1\": " << json_array(a1_t)
        << ",\n    \"h\": " << json_array(h_t) << "\n  }";
  }
  out << "\n}\n";
  return 0;
}

int run_elastic_command(const std::vector<std::string>& args, std::ostream& out) {
  po::options_description opts(std::string(
      "punchsweep elastic: the elastic two-level problem, eqs (9.12)-(9.15), with the\n"
      "nominal-pressure radii A1, A2 solved for (Table 9.1), for each modulus E.\n\n") + kUnits);
  opts.add_options()("help", "print this help and exit");
  for (const std::string_view name : {model::kPitch, model::kHeightDifference, model::kPressure}) {
    input::add_parameter_option(opts, parameter(name));
  }
  add_shape_options(opts);
  opts.add_options()
      ("E", po::value<std::string>()->value_name("LIST")->default_value("1"),
       "moduli E, comma-separated, in E0* (1 instantaneous, 1/T long-term); each > 0")
      ("format", po::value<std::string>()->value_name("FMT")->default_value("json"),
       "output format: json or markdown (a table like Table 9.1)");
  input::add_localization_option(opts, "paper");
  const po::variables_map vm = input::parse_command(args, opts, "elastic");
  if (vm.count("help")) {
    out << "usage: punchsweep elastic --l L --dh DH --pbar P --s S [--C C] [--E LIST] [--format FMT]\n\n" << opts << "\n";
    return 0;
  }
  model::ContactProblem problem;
  problem = input::read_problem(vm);
  const std::vector<double> moduli = input::read_real_list(vm, "E", "E > 0 (in E0*)", positive);
  const std::string format = input::read_choice(vm, "format", {"json", "markdown"});

  problem.localization = input::read_localization(vm);
  std::vector<double> P1, P2, a1, a2, A1, A2, touches, converged;
  for (const double E : moduli) {
    model::ElasticTwoLevel r = model::solve_elastic(problem, E);
    if (!r.converged) {
      constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
      r.state = model::TwoLevelState{kNaN, kNaN, kNaN, kNaN};
      r.radii = model::NominalRadii{kNaN, kNaN};
    }
    P1.push_back(E * r.state.Q1);  // P = E Q
    P2.push_back(E * r.state.Q2);
    a1.push_back(r.state.a1);
    a2.push_back(r.state.a2);
    A1.push_back(r.radii.A1);
    A2.push_back(r.radii.A2);
    touches.push_back(r.level2_touches);
    converged.push_back(r.converged);
  }
  if (format == "markdown") {
    out << "| E/E0 | P1 | P2 | a1 | a2 | A1 | A2 |\n|---|---|---|---|---|---|---|\n";
    for (std::size_t i = 0; i < moduli.size(); ++i) {
      char row[256];
      std::snprintf(row, sizeof row, "| %g | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f |\n", moduli[i], P1[i], P2[i],
                    a1[i], a2[i], A1[i], A2[i]);
      out << row;
    }
    out << "\n(pbar0 = " << input::json_number(problem.pbar0) << " E0*, l = " << input::json_number(problem.l)
        << " R, dh = " << input::json_number(problem.dh) << " R, s = " << problem.shape.s << ", C = "
        << input::json_number(problem.shape.C) << "; loads in R^2 E0*, lengths in R)\n";
    return 0;
  }
  const auto flags = [](const std::vector<double>& v) {
    std::string text = "[";
    for (std::size_t i = 0; i < v.size(); ++i) text += std::string(i ? ", " : "") + (v[i] != 0.0 ? "true" : "false");
    return text + "]";
  };
  out << "{\n  \"E\": " << json_array(moduli) << ",\n  \"P1\": " << json_array(P1) << ",\n  \"P2\": " << json_array(P2)
      << ",\n  \"a1\": " << json_array(a1) << ",\n  \"a2\": " << json_array(a2) << ",\n  \"A1\": " << json_array(A1)
      << ",\n  \"A2\": " << json_array(A2) << ",\n  \"level2_touches\": " << flags(touches)
      << ",\n  \"converged\": " << flags(converged) << "\n}\n";
  return 0;
}

}  // namespace punchsweep::app
