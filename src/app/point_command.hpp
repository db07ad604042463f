#pragma once
/// @file
/// `punchsweep point`: one parameter point of the paper's lattice (engine/point_evaluation.hpp),
/// printed as a table, JSON or CSV (app/point_output.hpp).

#include <iosfwd>
#include <string>
#include <vector>

namespace punchsweep::app {

/// `punchsweep point ...`: evaluates one parameter point and prints it.
/// Returns the exit code; throws UsageError for bad input (before printing anything).
int run_point_command(const std::vector<std::string>& args, std::ostream& out);

}  // namespace punchsweep::app
