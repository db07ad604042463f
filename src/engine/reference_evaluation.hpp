#pragma once
/// @file
/// One point of the paper's lattice solved by the periodic boundary-element reference
/// (reference/reference_point.hpp), as `punchsweep reference` and Python's reference() ask
/// it: the point's options and the solver's, read and checked, and the solve.

#include <boost/program_options/options_description.hpp>
#include <boost/program_options/variables_map.hpp>

#include "input/command_options.hpp"
#include "model/numerics/stop_request.hpp"
#include "reference/reference_point.hpp"

namespace punchsweep::engine {

/// The options of `punchsweep reference` for `material`: the point's, --bem-grid, --format.
boost::program_options::options_description reference_options(const input::PointMaterial& material);

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

/// The point's inputs and the solver's options, read and checked in the command's order
/// (the first bad one is the one reported). Throws input::UsageError.
ReferenceRun read_reference(const boost::program_options::variables_map& given, const input::PointMaterial& material);

/// Solves `run` (read_reference's) with the sweep's reproducible FFT plans, so that a point
/// gives the same bits here and in `punchsweep sweep --reference bem`; times the solve.
void solve_reference(ReferenceRun* run);

}  // namespace punchsweep::engine
