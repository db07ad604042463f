#include "model/contact_problem.hpp"

#include <cmath>
#include <sstream>

namespace punchsweep::model {

std::string problem_error(const ContactProblem& problem) {
  std::ostringstream out;
  if (!(std::isfinite(problem.l) && problem.l > 0.0)) {
    out << "pitch l = " << problem.l << " is outside its range: l > 0 (in R)";
  } else if (!(std::isfinite(problem.dh) && problem.dh >= 0.0)) {
    out << "height difference dh = " << problem.dh << " is outside its range: dh >= 0 (in R)";
  } else if (!(std::isfinite(problem.pbar0) && problem.pbar0 > 0.0)) {
    out << "nominal pressure pbar0 = " << problem.pbar0
        << " is outside its range: pbar0 > 0 (in E0/(1-nu^2))";
  } else {
    return shape_error(problem.shape);
  }
  return out.str();
}

}  // namespace punchsweep::model
