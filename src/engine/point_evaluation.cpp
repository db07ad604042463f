#include "engine/point_evaluation.hpp"

#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "input/usage_error.hpp"
#include "model/point/advisory.hpp"

namespace punchsweep::engine {

PointRequest read_point(const boost::program_options::variables_map& vm, const input::PointMaterial& material) {
  PointRequest request{input::read_point_inputs(vm, material), {}, {}, {}};
  input::PointInputs& in = request.inputs;
  in.problem.localization = input::read_localization(vm);
  if (const std::string e = in.problem.localization.exponent_error(in.problem.shape.s); !e.empty()) {
    throw input::UsageError(e);
  }
  request.options.times = input::read_times(vm, in.scales);
  request.tolerances = input::read_tolerances(vm, in);
  request.cap_radius = input::read_cap_radius(vm, in);
  return request;
}

PointRun evaluate_point(PointRequest request) {
  PointRun run{std::move(request.inputs), {}};
  const input::PointInputs& in = run.inputs;
  run.result = model::evaluate_point(in.problem, *in.creep, request.options);
  const double t_star = run.result.t_star.value_or(std::numeric_limits<double>::infinity());
  run.result.t_star_derivatives = model::t_star_derivatives(in.problem, *in.law, in.law_values, t_star);
  const model::Advisories advice = model::advise(in.problem, run.result, request.cap_radius);
  run.result.advisories = advice.names();
  run.result.advisory_reason = advice.reason(request.cap_radius.value_or(0.0));
  run.result.strain = advice.strain;
  if (!request.tolerances.empty()) {
    try {
      run.result.t_star_range = model::t_star_range(in.problem, *in.law, in.law_values, request.tolerances);
    } catch (const std::invalid_argument& e) {
      throw input::UsageError(std::string("--tolerance: ") + e.what());
    }
  }
  return run;
}

PointRun evaluate_point(const input::Keywords& keywords) {
  const input::PointMaterial material = input::find_point_material(keywords);
  return evaluate_point(read_point(input::parse_keywords(keywords, input::point_options(material), "point"), material));
}

}  // namespace punchsweep::engine
