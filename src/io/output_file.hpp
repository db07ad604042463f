#pragma once

#include <string>
#include <vector>

namespace punchsweep::io {

/// The one rule for every file a command writes (a map and its .partial and journal, a
/// material file and its .fit.json, a table source; Python's pictures and pages follow the
/// same rule in postprocess/punchsweep_maps.py, check_output). Returns "" when `path` may
/// be written, else why not, naming the path: its folder does not exist or is no folder;
/// it is a symbolic link (a link planted there would have the file written where it
/// points); it exists and is not a regular file (a folder, a device such as /dev/null, a
/// pipe: renaming a new file over it would replace it); it is the same file as one of
/// `inputs` (compared by device and inode, so another spelling or a hard link is caught),
/// which writing would destroy. Inputs that do not exist are ignored.
std::string output_file_problem(const std::string& path, const std::vector<std::string>& inputs = {});

/// Writes `text` to `path` whole: checks output_file_problem, writes a temporary file beside
/// it (created exclusively) and renames it over `path`, so a reader never sees half a file
/// and nothing is left on failure. Throws std::runtime_error naming the path.
void write_file_whole(const std::string& path, const std::string& text, const std::vector<std::string>& inputs = {});

}  // namespace punchsweep::io
