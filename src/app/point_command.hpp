#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include <boost/program_options/options_description.hpp>

#include "input/command_options.hpp"
#include "model/point/point_evaluation.hpp"

namespace punchsweep::app {

/// The options of `punchsweep point` for `material` (the design command reads its points
/// through them too).
boost::program_options::options_description point_options(const input::PointMaterial& material);

/// `punchsweep point ...`: evaluates one parameter point and prints it.
/// Returns the exit code; throws UsageError for bad input (before printing anything).
int run_point_command(const std::vector<std::string>& args, std::ostream& out);

/// One point as `punchsweep point ARGS` evaluates it: its inputs and its result.
struct PointRun {
  input::PointInputs inputs;
  model::PointResult result;
};

/// The point of `punchsweep point` given as keywords (Python's: `l`, `dh`, `material`, ...;
/// no --help or --format), evaluated: the command's options, checks and evaluation, so the
/// numbers are the command's bit for bit. Throws UsageError (its message is the command's)
/// for bad input.
PointRun evaluate_point(const input::Keywords& keywords);

}  // namespace punchsweep::app
