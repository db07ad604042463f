#pragma once

#include <iosfwd>

#include "model/contact_problem.hpp"
#include "model/point_evaluation.hpp"
#include "model/standard_linear_solid.hpp"

namespace punchsweep::app {

enum class OutputFormat { table, json, csv };

/// Writes one evaluated point. JSON keys (a contract): regime, t_star (null for never),
/// h_0, h_inf, valid, reason, a1_inf, a2_inf, area_fraction_inf, and series with arrays
/// t, a1, a2, P1, P2, area_fraction. Numbers that could not be computed are null.
void write_point(std::ostream& out, OutputFormat format, const model::ContactProblem& problem,
                 const model::StandardLinearSolid& creep, const model::PointResult& result);

}  // namespace punchsweep::app
