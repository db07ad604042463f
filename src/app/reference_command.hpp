#pragma once
/// @file
/// `punchsweep reference`: one point by the boundary-element reference
/// (engine/reference_evaluation.hpp), printed as JSON or a table.

#include <iosfwd>
#include <string>
#include <vector>

namespace punchsweep::app {

/// `punchsweep reference ...`: one point by the periodic boundary-element solver (the
/// full contact problem on an N x N grid), with the same inputs and series as `point`.
/// Returns the exit code; throws UsageError for bad input.
int run_reference_command(const std::vector<std::string>& args, std::ostream& out);

}  // namespace punchsweep::app
