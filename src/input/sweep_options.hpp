#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "sweep/sweep_config.hpp"

namespace punchsweep::input {

/// Resolves the arguments that follow `punchsweep sweep` into a validated SweepConfig:
/// command line > --config INI file > embedded defaults (also per [grid] key when a file
/// leaves one out). With --help it writes the help text to `help_out`, sets *help_shown
/// (when not null) and returns a default SweepConfig; otherwise *help_shown is false.
/// Throws UsageError for bad input: an unknown or conflicting option, an unreadable or
/// malformed config file, or values out of range. Value problems are all collected, one
/// line each, "KEY = VALUE: PROBLEM; valid range: RANGE", joined by '\n'.
sweep::SweepConfig parse_sweep_options(const std::vector<std::string>& args, std::ostream& help_out,
                                       bool* help_shown);

}  // namespace punchsweep::input
