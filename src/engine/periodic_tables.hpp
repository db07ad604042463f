#pragma once
/// @file
/// Where the periodic model's tables come from (docs/model.md, sections 14.3 and 14.7): the
/// ones shipped with the engine (s = 1, 2, 3), else the table cache (texture/table_cache.hpp, its
/// rules), else built by the boundary elements (about a minute per s) and kept there; and
/// the small-spot table beside them, shipped or built (about 2 s, the refined localization's
/// shell sums, which the cache keeps, most of it).

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "model/periodic/periodic_solution.hpp"
#include "model/periodic/periodic_table.hpp"
#include "model/periodic/small_spot_table.hpp"
#include "reference/periodic_table_builder.hpp"

namespace punchsweep::engine {

/// The grid of the tables the engine uses.
inline constexpr int kPeriodicTableGrid = 512;

/// The tables shipped in the source tree (src/engine/periodic_tables/), if any for (s, n).
std::optional<model::PeriodicTable> shipped_periodic_table(int s, int n = kPeriodicTableGrid);

/// Whether loaded tables are the boundary elements' own: three single-level samples and one
/// sample of every two-level row, drawn from `seed`, solved again (loads and h to 1e-6, areas
/// to one node), and every row's level-2 share recomputed. A table edited as a whole or row
/// by row fails it whatever its checksum says; one edited sample is caught with probability
/// 1/(K - 1) per check. Costs J + 3 contact solves (about 5 s at n = 512). The tests hold
/// the shipped tables to it; the cache does not need it (its files are signed).
bool spot_check(const model::PeriodicTable& table, std::uint64_t seed);

/// Builds the tables of s on an n grid, with progress on stderr (unless quiet) and a last
/// line saying how long it took and `where` they go.
model::PeriodicTable build_periodic_table_with_progress(int s, int n, bool quiet,
                                                       const reference::PeriodicTableOptions& options,
                                                       const std::string& where);

/// Where periodic_table_for found the tables.
enum class TableOrigin { shipped, cache, built };

/// The tables of s on an n grid: shipped, else from `folder` (if set; its signature checked,
/// under a lock so that concurrent builders build once), else built (progress on stderr unless
/// quiet) and saved there. `origin`, if set, says which.
std::shared_ptr<const model::PeriodicTable> periodic_table_for(int s, int n,
                                                              const std::optional<std::filesystem::path>& folder,
                                                              bool quiet = false,
                                                              const reference::PeriodicTableOptions& options = {},
                                                              TableOrigin* origin = nullptr);

/// The small-spot table shipped in the source tree (src/engine/periodic_tables/), if any for s.
std::optional<model::SmallSpotTable> shipped_small_spot_table(int s);

/// The small-spot table of s: shipped, else built (a line on stderr where that took a second
/// or more, unless quiet).
std::shared_ptr<const model::SmallSpotTable> small_spot_table_for(int s, bool quiet = false);

/// The periodic solution of s: the boundary elements' tables on the engine's grid
/// (periodic_table_for, with `folder` as the cache) and the small-spot table.
std::shared_ptr<const model::PeriodicSolution> periodic_solution_for(int s, const std::optional<std::filesystem::path>& folder,
                                                                    bool quiet = false);

/// Gives the model its tables' sources: the periodic solutions (periodic_solution_for) and
/// the refined model's shell sums, kept in table_cache_folder() if any and if trusted;
/// otherwise says once on stderr why the cache is not used (the tables are then built in
/// memory).
void use_table_cache();

/// The tables as C++ source text (an initializer list of hex-float numbers with a header
/// saying how they were made), what src/engine/periodic_tables/ holds.
std::string periodic_table_source(const model::PeriodicTable& table, const std::string& provenance);
std::string small_spot_table_source(const model::SmallSpotTable& table, const std::string& provenance);

}  // namespace punchsweep::engine
