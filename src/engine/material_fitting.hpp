#pragma once
/// @file
/// A material from measurements (docs/fitting.md), as `punchsweep fit` and Python's
/// fit_material() make it: the measurement files read and shifted onto a master curve,
/// the Prony series fitted (fit/), the material file and its .fit.json written whole.

#include <boost/program_options/options_description.hpp>
#include <boost/program_options/variables_map.hpp>

#include <memory>
#include <string>
#include <vector>

#include "fit/material_fit.hpp"
#include "input/command_options.hpp"
#include "model/laws/material.hpp"

namespace punchsweep::engine {

/// A fit and the material file it makes (docs/fitting.md).
struct FitRun {
  fit::MaterialFit fit;
  std::vector<std::string> sources;  ///< the measurement files as given
  std::vector<std::string> samples;  ///< each file's sample name from its preamble, or ""
  double poisson = 0.5;
  double window_lo = 0.0, window_hi = 0.0;  ///< the time window, s at T_ref
  std::string modulus_unit;          ///< of the file's E_inf, E_i
  std::string material_text;         ///< the material file, as written
  std::shared_ptr<const model::Material> material;  ///< the engine's reading of material_text
  std::string report;                ///< the text `punchsweep fit` prints
  std::string output;                ///< the material file's path ("" from Python without output)
  std::string details;               ///< the JSON file beside it (readings, shifts, fit), or ""
  std::string details_json;          ///< its text
  /// The fit's verdict (fit::fit_problems): empty for a good fit; a poor one is written only
  /// with --accept-poor-fit, the problems recorded in both files.
  std::vector<std::string> problems;
};

/// The options of `punchsweep fit`.
boost::program_options::options_description fit_options();

/// The fit of `given` (parsed by fit_options()): its report, material text and details, not
/// written. Throws input::UsageError for bad input or data that give no material.
FitRun run_fit(const boost::program_options::variables_map& given);

/// Writes the fit's .fit.json and its material file, each whole, then renamed into place.
void write_fit_files(const FitRun& run);

/// The fit of `punchsweep fit`'s options as keywords (Python's; output optional: without
/// it nothing is written), with its files written where it has one.
FitRun fit_material(const input::Keywords& keywords);

}  // namespace punchsweep::engine
