#pragma once
/// @file
/// The load curve of the paper's lattice read off the periodic model's solution
/// (docs/model.md, sections 14 and 17.6): the two-level square lattice of power-law punches
/// (model::lattice_cell(square, l, shape, {dh})) has its solution tabulated already, at
/// n = 512 with the small-spot table below the boundary elements' reach, so its curve is
/// that solution sampled, not a solve of its own: `surface` then answers as `point
/// --localization periodic` does (the same touchdown load, so the same t*; loads and areas
/// interpolated between samples dense enough that they differ by less than 1e-5 of the
/// cell's load and 1e-4 of the area).

#include <optional>

#include "model/periodic/periodic_solution.hpp"
#include "model/problem/contact_problem.hpp"
#include "model/surface/load_curve.hpp"

namespace punchsweep::model {

/// Samples of the curve: per decade of X below level 2's touchdown (log-spaced, from
/// kPeriodicCurveFirst C l^(s-1) up), and along the two levels' part (uniform in
/// (X - X*)^(1/(s+1)), the tables' own variable) to full contact.
inline constexpr int kPeriodicCurvePerDecade = 96;
inline constexpr int kPeriodicCurveTwoLevel = 480;
inline constexpr double kPeriodicCurveFirst = 1e-12;

/// The curve of the lattice of `problem` (its l, dh and shape; sites in lattice_cell's
/// order: the tall punch at the corner, level 1 at the centre) from `solution` (of the
/// shape's s). Empty where the solution does not reach the lattice: dh above the tables'
/// top (delta_top, just short of where level 2 hides) while level 2 still touches.
/// X_resolved is 0: the small-spot table answers for the continuum down to zero load.
std::optional<LoadCurve> periodic_load_curve(const PeriodicSolution& solution, const ContactProblem& problem);

/// Whether periodic_load_curve has the lattice's curve (the tables reach its dh), found
/// without sampling it.
bool periodic_curve_reaches(const PeriodicSolution& solution, const ContactProblem& problem);

}  // namespace punchsweep::model
