#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "sweep/sweep_config.hpp"

namespace punchsweep::app {

/// Resolves the arguments that follow `punchsweep sweep` into a validated SweepConfig:
/// command line > --config INI file > embedded defaults (also per [grid] key when a file
/// leaves one out). With --help it writes the help text to `help_out`, sets *help_shown
/// (when not null) and returns a default SweepConfig; otherwise *help_shown is false.
/// Throws UsageError for bad input: an unknown or conflicting option, an unreadable or
/// malformed config file, or values out of range. Value problems are all collected, one
/// line each, "KEY = VALUE: PROBLEM; valid range: RANGE", joined by '\n'.
sweep::SweepConfig parse_sweep_options(const std::vector<std::string>& args, std::ostream& help_out,
                                       bool* help_shown);

/// One sentence per key whose identity line differs between an existing map and this
/// run, e.g. "grid.T: the existing map has 2, 5, 10; this run asks for 2, 5". Empty when
/// the two describe the same map. Lines are "section.key = value", as in SweepConfig::identity.
std::vector<std::string> identity_differences(const std::vector<std::string>& existing,
                                              const std::vector<std::string>& requested);

}  // namespace punchsweep::app
