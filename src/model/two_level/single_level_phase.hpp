#pragma once

#include "model/problem/contact_problem.hpp"
#include "model/two_level/periodic_model.hpp"
#include "model/localization/single_level.hpp"
#include "model/localization/single_level_shells.hpp"

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

}  // namespace punchsweep::model
