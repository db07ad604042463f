#include "model/problem/contact_problem.hpp"

#include "model/problem/parameter.hpp"

namespace punchsweep::model {

std::string problem_error(const ContactProblem& problem) {
  const double values[] = {problem.l, problem.dh, problem.pbar0};
  const std::string_view names[] = {kPitch, kHeightDifference, kPressure};
  for (std::size_t k = 0; k < std::size(values); ++k) {
    if (std::string e = problem_parameter(names[k])->error(values[k]); !e.empty()) return e;
  }
  return shape_error(problem.shape);
}

double* problem_field(ContactProblem& problem, std::string_view name) {
  if (name == kPitch) return &problem.l;
  if (name == kHeightDifference) return &problem.dh;
  if (name == kPressure) return &problem.pbar0;
  if (name == kShapeConstant) return &problem.shape.C;
  return nullptr;
}

}  // namespace punchsweep::model
