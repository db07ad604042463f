#include "run/preflight.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>
#include <optional>
#include <vector>

#include "io/output_file.hpp"
#include "io/regime_map_reader.hpp"
#include "io/tile_journal.hpp"
#include "run/resume_policy.hpp"
#include "run/text_lines.hpp"

namespace fs = std::filesystem;

namespace punchsweep::run {

std::string output_folder_problem(const OutputPaths& paths) {
  const fs::path final_path(paths.final_path);
  const fs::path dir = final_path.has_parent_path() ? final_path.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    return "output.file = " + paths.final_path + ": the folder " + dir.string() + " does not exist";
  }
  const long limit = ::pathconf(dir.c_str(), _PC_NAME_MAX);
  const std::size_t most = limit > 0 ? static_cast<std::size_t>(limit) : 255;
  for (const std::string& path : {paths.journal, paths.partial, paths.lock, paths.final_path}) {
    const std::size_t length = fs::path(path).filename().string().size();
    if (length > most) {
      return "output.file = " + paths.final_path + ": the name is too long: " + fs::path(path).filename().string() +
             " would have " + std::to_string(length) + " bytes; valid: at most " + std::to_string(most) +
             " bytes for the map's name with its longest suffix, .partial.journal (so at most " +
             std::to_string(most - 16) + " for the map's own name)";
    }
  }
  // Create-and-remove a probe: access() says yes to root even where nothing can be created.
  const std::string probe = (dir / (".punchsweep-probe-" + std::to_string(::getpid()))).string();
  const int probe_fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (probe_fd < 0) {
    return "output.file = " + paths.final_path + ": the folder " + dir.string() + " is not writable";
  }
  ::close(probe_fd);
  ::unlink(probe.c_str());
  return {};
}

std::string preflight(const sweep::SweepConfig& config, const OutputPaths& paths, Start* start) {
  if (std::string problem = output_folder_problem(paths); !problem.empty()) return problem;
  const fs::path final_path(paths.final_path);
  std::error_code ec;
  // HDF5 holds a lock on a file it writes: if the .partial is locked, a sweep into this map
  // is still running (perhaps an orphan of a killed job).
  if (const int fd = ::open(paths.partial.c_str(), O_RDONLY); fd >= 0) {
    const bool busy = ::flock(fd, LOCK_SH | LOCK_NB) != 0;
    ::close(fd);
    if (busy) {
      return "output.file = " + paths.final_path + ": " + paths.partial +
             " is being written by another running sweep; wait for it or stop it first";
    }
  }
  // The rule for every written file (io::output_file_problem): no link (one planted at these
  // names would have the run write where it points), nothing but a regular file (the map is
  // renamed over a device, a pipe or a folder), no input of this run. Checked now, not after
  // the whole grid is computed.
  for (const std::string& path : {paths.final_path, paths.partial, paths.journal}) {
    if (std::string problem = io::output_file_problem(path, config.input_files); !problem.empty()) {
      return "output.file = " + paths.final_path + ": " + problem;
    }
  }
  const bool final_exists = fs::exists(final_path, ec);
  const bool journal_exists = fs::exists(paths.journal, ec);
  *start = Start::fresh;
  if (config.overwrite) return {};
  if (config.resume) {
    if (final_exists && !journal_exists) {
      // A finished map is compared like an interrupted one: a job script that always
      // passes --resume must not keep a map of another configuration.
      std::string recorded;
      try {
        recorded = io::read_map_identity(paths.final_path);
      } catch (const std::exception& e) {
        return "--resume refused: " + std::string(e.what()) + "; choose another file or pass --overwrite to replace it";
      }
      const std::vector<std::string> differences = identity_differences(split_lines(recorded), config.identity);
      if (!differences.empty()) {
        return "--resume refused: the finished map " + paths.final_path + " was made with another configuration:\n  " +
               join(differences, "\n  ") + "\n  (restore the configuration, or pass --overwrite to replace the map)";
      }
      *start = Start::already_complete;
      return {};
    }
    if (!journal_exists) return {};  // nothing to resume yet: a fresh start (job scripts pass --resume always)
    std::string header;
    try {
      header = io::TileJournal::read_header(paths.journal);
    } catch (const std::exception& e) {
      return std::string("--resume: ") + e.what() + "; pass --overwrite to start over";
    }
    const std::vector<std::string> differences = identity_differences(split_lines(header), config.identity);
    if (!differences.empty()) {
      return "--resume refused: the interrupted map " + paths.partial + " was started with another " +
             "configuration:\n  " + join(differences, "\n  ") +
             "\n  (restore the configuration, or pass --overwrite to start over)";
    }
    *start = Start::resume;
    return {};
  }
  if (final_exists) {
    return "output.file = " + paths.final_path + " exists; pass --overwrite to replace it or choose another file";
  }
  if (journal_exists) {
    return "an interrupted sweep left " + paths.partial + " and " + paths.journal +
           "; pass --resume to finish it or --overwrite to start over";
  }
  return {};
}

void resolve_chunk(sweep::SweepConfig& config, const OutputPaths& paths, int ranks) {
  if (config.chunk != sweep::kAutoChunk) return;
  if (config.resume && !config.overwrite) {
    std::error_code ec;
    std::string recorded;
    try {
      if (fs::exists(paths.journal, ec)) {
        recorded = io::TileJournal::read_header(paths.journal);
      } else if (fs::exists(paths.final_path, ec)) {
        recorded = io::read_map_identity(paths.final_path);
      }
    } catch (const std::exception&) {
      recorded.clear();  // preflight reports what is wrong with the file
    }
    const std::optional<std::string> value = identity_value(split_lines(recorded), "run.chunk");
    if (value && !value->empty() && value->find_first_not_of("0123456789") == std::string::npos) {
      sweep::set_chunk(config, std::stoull(*value));
      return;
    }
  }
  sweep::set_chunk(config, sweep::auto_chunk(config, ranks));
}

}  // namespace punchsweep::run
