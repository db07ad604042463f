#pragma once
/// @file
/// The problem's localization model, chosen once by problem.localization: the paper's
/// (SingleLevel and the frozen-radii TwoLevelSystem, docs/model.md sections 9-10), the
/// refined family's (SingleLevelShells and ShellsBranch, section 11) or the periodic
/// solution's (PeriodicSingleLevel and PeriodicBranch, section 14). The one place that
/// dispatches on it; everything else reads a model through these faces, so the model units
/// below depend on none of this (and on no other model).

#include <memory>

#include "model/problem/contact_problem.hpp"
#include "model/laws/creep_law.hpp"
#include "model/paper/single_level.hpp"
#include "model/shells/single_level_shells.hpp"
#include "model/paper/elastic_two_level.hpp"
#include "model/paper/long_term_guide.hpp"
#include "model/periodic/periodic_model.hpp"
#include "model/contact/regime.hpp"
#include "model/contact/two_level_branch.hpp"

namespace punchsweep::model {

/// Calls f with the single-level phase of the problem's localization: SingleLevel (the
/// paper's eqs 9.5/9.10, fast closed forms), SingleLevelShells (the family of
/// docs/model.md, section 11) or PeriodicSingleLevel (the periodic tables, section 14). They
/// share contact_radius and displacement_difference; touchdown() follows each one's own way.
template <class F>
decltype(auto) visit_single_level(const ContactProblem& problem, F&& f) {
  if (problem.localization.periodic) return f(PeriodicSingleLevel(problem));
  if (problem.localization.is_paper()) return f(SingleLevel(problem.l, problem.shape));
  return f(SingleLevelShells(problem.l, problem.shape, problem.localization));
}

/// The touchdown point of the problem under its localization.
Touchdown touchdown(const ContactProblem& problem);

/// Classifies one point (the problem must satisfy problem_error() == "").
Classification classify(const ContactProblem& problem, const CreepLaw& creep);

/// The branch of the problem's localization from its touchdown: the periodic tables'
/// (PeriodicBranch) or the refined family's (ShellsBranch). Not for the paper's model, whose
/// radii are frozen (TwoLevelSystem). Shared: a sweep's and classify's points share one per
/// (l, s, C, dh) (model::DhParts), and make_shared allocates it with its count at once.
std::shared_ptr<const TwoLevelBranch> make_branch(const ContactProblem& problem, const Touchdown& touch);

/// The elastic two-level state under the problem's localization: solve_elastic_two_level
/// for the paper's; for the family of docs/model.md, section 11 (radii from the loads) the
/// state of its branch at X = pbar/E (ShellsBranch, built here if null). `guide` serves
/// the paper's only, `branch` the family's.
ElasticTwoLevel solve_elastic(const ContactProblem& problem, double E, const LongTermGuide* guide = nullptr,
                              const TwoLevelBranch* branch = nullptr);

}  // namespace punchsweep::model
