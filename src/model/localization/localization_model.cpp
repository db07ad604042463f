#include "model/localization/localization_model.hpp"

#include "model/shells/shells_branch.hpp"

namespace punchsweep::model {

Touchdown touchdown(const ContactProblem& problem) {
  return visit_single_level(problem, [&](const auto& single) {
    if constexpr (requires { single.touchdown(problem.dh); }) {
      return single.touchdown(problem.dh);  // the periodic tables: in X directly
    } else {
      return touchdown(single, problem.dh);
    }
  });
}

Classification classify(const ContactProblem& problem, const CreepLaw& creep) {
  return classify(touchdown(problem), CreepWeightedLoad(creep, problem.pbar0, problem.loading));
}

std::shared_ptr<const TwoLevelBranch> make_branch(const ContactProblem& problem, const Touchdown& touch) {
  if (problem.localization.periodic) return std::make_shared<const PeriodicBranch>(problem, touch);
  return std::make_shared<const ShellsBranch>(problem, touch);
}

ElasticTwoLevel solve_elastic(const ContactProblem& problem, double E, const LongTermGuide* guide,
                              const TwoLevelBranch* branch) {
  if (problem.localization.is_paper()) return solve_elastic_two_level(problem, E, guide);
  std::shared_ptr<const TwoLevelBranch> own;
  if (branch == nullptr) {
    own = make_branch(problem, touchdown(problem));
    branch = own.get();
  }
  ElasticTwoLevel out;
  const double X = problem.pbar0 / E;
  out.level2_touches = branch->X_star() <= X;
  if (!out.level2_touches) {
    // Level 2 does not touch: the family's single-level state.
    const double a1 = visit_single_level(problem, [&](const auto& single) { return single.contact_radius(X); });
    out.state = TwoLevelState{a1, 0.0, problem.l * problem.l * X, 0.0};
    out.converged = true;
  } else {
    const TwoLevelSolve r = branch->at(X);
    out.state = r.state;
    out.converged = r.converged;
  }
  out.radii = branch->radii(out.state, X);
  return out;
}

}  // namespace punchsweep::model
