#include "model/two_level/two_level_branch.hpp"

#include "model/two_level/periodic_model.hpp"
#include "model/two_level/shells_branch.hpp"

namespace punchsweep::model {

std::shared_ptr<const TwoLevelBranch> make_branch(const ContactProblem& problem, const Touchdown& touch) {
  if (problem.localization.periodic) return std::make_shared<const PeriodicBranch>(problem, touch);
  return std::make_shared<const ShellsBranch>(problem, touch);
}

}  // namespace punchsweep::model
