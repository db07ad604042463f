#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace punchsweep::app {

/// The folder where the refined localizations' neighbour tables (model::ShellSums, about
/// 2 s to build per shape exponent) are kept between runs: $PUNCHSWEEP_CACHE if set ("off"
/// or empty: none), else $XDG_CACHE_HOME/punchsweep, else $HOME/.cache/punchsweep.
std::optional<std::filesystem::path> table_cache_folder();

/// A file of the cache: "PSWTAB01", the count n (uint64), n doubles and their FNV-1a hash
/// (uint64), host byte order. read_tables gives empty for a missing, short or damaged file.
std::vector<double> read_tables(const std::filesystem::path& file);
/// Written beside the file and renamed over it (ranks that save the same tables at once
/// leave one whole file); a folder or file that cannot be written is skipped silently (the
/// tables are then built again next time).
void write_tables(const std::filesystem::path& file, const std::vector<double>& tables);

/// Gives the model a store in table_cache_folder(), if any.
void use_table_cache();

}  // namespace punchsweep::app
