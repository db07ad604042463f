#pragma once
/// @file
/// A texture map's run over MPI ranks: `punchsweep sweep` with a [texture] section and
/// `punchsweep surface-map` both end here. A tile (a geometry's load points in rows of the
/// pressure axis; its first also builds the geometry's load curve, seconds to minutes) is
/// the unit of work: the sweep's scheduler deals them dynamically, every finished tile goes
/// into the sweep's tile journal before anything else, so a run killed at any moment (kill
/// -9, a Slurm requeue) resumes with --resume and computes only the tiles the journal lacks;
/// the resume policy, the output lock and the exit codes are the sweep's
/// (run/preflight.hpp). Each tile is a pure function of its keywords, so the map is
/// bit-identical on any number of ranks, in any tiles and after any resume.

#include <string>
#include <vector>

#include "input/command_options.hpp"

namespace punchsweep::app {

/// What to map and where.
struct TextureMapJob {
  input::Keywords keywords;     ///< surface's, with axes (TextureMapPlan); no output or run switches
  std::string output;           ///< the map (netCDF-4)
  bool overwrite = false;
  bool resume = false;
  bool quiet = false;           ///< no progress lines
  bool dry_run = false;         ///< say what the map asks (its curves' grids, memory, time) and write nothing
  std::vector<std::string> input_files;  ///< files the run reads besides the keywords' (the config file)
  std::string program;          ///< "punchsweep sweep" or "punchsweep surface-map": its messages' prefix
  std::string command;          ///< the command as typed: the lock's holder, the resume hint
};

/// Runs `job` on every rank of MPI_COMM_WORLD (collective); with `dry_run` rank 0 prints
/// what the map asks on stdout and nothing is written. Returns the exit code: 0, 2 bad
/// input (said once, by rank 0; nothing written), 3 stopped by a signal (the journal kept),
/// 1 a failure.
int run_texture_map(const TextureMapJob& job, int rank, int ranks);

/// `mpirun -n N punchsweep surface-map ...`: the texture map's run with surface's options
/// (app/surface_map_command.hpp reads them). Collective; the exit code (2 for bad input,
/// said by rank 0).
int run_surface_map_command(const std::vector<std::string>& args);

}  // namespace punchsweep::app
