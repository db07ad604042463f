#pragma once

#include <string>

#include "sweep/sweep_config.hpp"

namespace punchsweep::run {

/// The files of a map: the final one, the one under construction, the journal, and the
/// lock that the running sweep holds (OutputLock).
struct OutputPaths {
  std::string final_path;
  std::string partial;
  std::string journal;
  std::string lock;
  explicit OutputPaths(const std::string& file)
      : final_path(file), partial(file + ".partial"), journal(file + ".partial.journal"), lock(file + ".lock") {}
};

/// Whether the map can be written where it is to go: "" or the refusal naming the file
/// and the problem: the output's folder does not exist, cannot be written (a probe file is
/// created and removed), or a name of the map's with its suffix (F.h5.partial.journal the
/// longest) would exceed the folder's NAME_MAX (usually 255 bytes). The sweep asks it
/// before it creates its lock file; preflight asks it first.
std::string output_folder_problem(const OutputPaths& paths);

/// What a run decided before any work: start fresh, resume from the journal, or nothing
/// to do (the map is complete and --resume was given).
enum class Start { fresh, resume, already_complete };

/// The resume policy, checked before anything is created (and under the run's OutputLock):
/// output_folder_problem, then the map's paths must not be symbolic
/// links, folders or other non-regular files, and no other sweep may be writing its
/// .partial (HDF5's lock, for a sweep of an engine before the lock file). Then: --overwrite starts fresh;
/// --resume resumes a journal whose configuration identity equals this run's (else
/// refuses with the differences), starts fresh when there is nothing to resume, and
/// reports already_complete for a finished map of the same identity (a finished map of
/// another identity, or a file that is no punchsweep map, is refused); without either, an
/// existing map or an interrupted one is refused. Returns "" (and sets *start) or the refusal, one
/// or more lines naming the file and what to do.
std::string preflight(const sweep::SweepConfig& config, const OutputPaths& paths, Start* start);

/// Resolves run.chunk = auto (else leaves the config alone): a run that will resume takes
/// the size its map was started with (from the journal, or a finished map's identity), so
/// its tiles are the same whatever the rank count; a fresh run sizes it for `ranks`
/// (sweep::auto_chunk).
void resolve_chunk(sweep::SweepConfig& config, const OutputPaths& paths, int ranks);

}  // namespace punchsweep::run
