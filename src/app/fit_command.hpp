#pragma once

#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "fit/material_fit.hpp"
#include "input/command_options.hpp"
#include "model/laws/material.hpp"

namespace punchsweep::app {

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

/// `punchsweep fit`: reads the measurement files, fits, writes the material file and its
/// .fit.json beside it (each written whole, then renamed into place), prints the report.
int run_fit_command(const std::vector<std::string>& args, std::ostream& out);

/// The same from Python's keywords (output optional: without it nothing is written).
FitRun fit_material(const input::Keywords& keywords);

}  // namespace punchsweep::app
