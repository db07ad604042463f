#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "input/command_options.hpp"
#include "model/numerics/stop_request.hpp"
#include "reference/reference_point.hpp"

namespace punchsweep::app {

/// `punchsweep reference ...`: one point by the periodic boundary-element solver (the
/// full contact problem on an N x N grid), with the same inputs and series as `point`.
/// Returns the exit code; throws UsageError for bad input.
int run_reference_command(const std::vector<std::string>& args, std::ostream& out);

/// One point as `punchsweep reference ARGS` solves it.
struct ReferenceRun {
  input::PointInputs inputs;
  reference::ReferenceOptions options;
  reference::ReferenceResult result;
  double seconds = 0.0;  ///< the solve's own wall time
};

/// The point of `punchsweep reference` given as keywords (no --help or --format), solved
/// with the command's options, checks and FFTW plans, so the numbers are the command's bit
/// for bit. Throws UsageError (its message is the command's) for bad input, and
/// model::Stopped when `stop` is requested between the BEM's time steps.
ReferenceRun evaluate_reference(const input::Keywords& keywords, const model::StopRequest& stop = {});

}  // namespace punchsweep::app
