#pragma once
/// @file
/// `punchsweep surface-map`: a texture's map over geometry and load axes (docs/cli.md),
/// surface's options with axes; the map (engine/texture_map.hpp) run over MPI ranks by
/// app/texture_map_run.hpp.

#include <string>
#include <vector>

#include "input/command_options.hpp"

namespace punchsweep::app {

/// surface-map's command line: the map's keywords and the run's switches, or --help's text.
struct SurfaceMapArgs {
  input::Keywords keywords;  ///< the map's (no output or run switches)
  std::string output;
  bool overwrite = false, resume = false, quiet = false;
  std::string help;          ///< --help's text (nothing else is read then)
};
/// Throws input::UsageError for a bad option, no --output, or --resume beside --overwrite.
SurfaceMapArgs read_surface_map_args(const std::vector<std::string>& args);

}  // namespace punchsweep::app
