#pragma once
/// @file
/// `punchsweep design`: the design (texture/design.hpp) of the options given on the command
/// line, printed as a table or as JSON.

#include <iosfwd>
#include <string>
#include <vector>

#include "input/command_options.hpp"

namespace punchsweep::app {

/// `punchsweep design ...`: evaluates and prints. Returns the exit code; throws UsageError
/// for bad input (before printing anything).
int run_design_command(const std::vector<std::string>& args, std::ostream& out);

}  // namespace punchsweep::app
