#pragma once
/// @file
/// One point of the paper's two-level square lattice as `punchsweep point`, `design` and
/// Python's point() evaluate it: its options read and checked (input::point_options), the
/// model's answer (model/point/point_evaluation.hpp) with t*'s derivatives, its range over
/// the tolerances and the physical advisories.

#include <boost/program_options/variables_map.hpp>

#include <optional>
#include <vector>

#include "input/command_options.hpp"
#include "model/point/point_evaluation.hpp"
#include "model/point/sensitivity.hpp"

namespace punchsweep::engine {

/// A point as asked: its inputs read and checked, and what its evaluation takes beside them.
struct PointRequest {
  input::PointInputs inputs;
  model::EvaluationOptions options;  ///< the snapshot times
  std::vector<model::Tolerance> tolerances;
  std::optional<double> cap_radius;  ///< the caps' base radius, where given (the advisories')
};

/// One point evaluated: its inputs and its result.
struct PointRun {
  input::PointInputs inputs;
  model::PointResult result;
};

/// The point's options (parsed by input::point_options(material)) read and checked, in the
/// command's order (the first bad one is the one reported). `material` must outlive the
/// request (its law points into it). Throws input::UsageError.
PointRequest read_point(const boost::program_options::variables_map& given, const input::PointMaterial& material);

/// The point evaluated, with t*'s derivatives, its range over the tolerances and the
/// physical advisories. Throws input::UsageError for tolerances the range cannot take.
PointRun evaluate_point(PointRequest request);

/// The point of `punchsweep point` given as keywords (Python's: `l`, `dh`, `material`, ...;
/// no --help or --format), evaluated: the command's options, checks and evaluation, so the
/// numbers are the command's bit for bit. Throws input::UsageError (its message is the
/// command's) for bad input.
PointRun evaluate_point(const input::Keywords& keywords);

}  // namespace punchsweep::engine
