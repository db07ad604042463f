#pragma once

#include <iosfwd>

#include "app/command_options.hpp"
#include "model/point_evaluation.hpp"

namespace punchsweep::app {

enum class OutputFormat { table, json, csv };

/// Writes one evaluated point. The keys are map::kQuantities' model quantities (a
/// contract, in that order): regime, t_star (null for never), h_0, h_inf, valid (with
/// reason after it), a1_inf, a2_inf, area_fraction_inf, and series with arrays t and the
/// series quantities a1, a2, P1, P2, area_fraction. Numbers that could not be computed are
/// null (JSON), nan (CSV, table).
void write_point(std::ostream& out, OutputFormat format, const PointInputs& inputs, const model::PointResult& result);

}  // namespace punchsweep::app
