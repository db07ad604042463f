#include "engine/periodic_tables.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <cinttypes>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <random>
#include <span>
#include <sstream>
#include <vector>

#include "engine/table_cache.hpp"
#include "io/file_descriptor.hpp"
#include "model/shells/shell_sums.hpp"
#include "model/periodic/small_spot_builder.hpp"
#include "reference/periodic_grid.hpp"
#include "sweep/reproducible_fft.hpp"

namespace punchsweep::engine {
namespace {

// The shipped tables: made by `punchsweep tables --s S --write-source F` (the provenance is
// at the top of each file).
#if __has_include("engine/periodic_tables/periodic-s1-n512.inc")
constexpr double kShippedS1[] = {
#include "engine/periodic_tables/periodic-s1-n512.inc"
};
#define PUNCHSWEEP_SHIPPED_S1 1
#endif
#if __has_include("engine/periodic_tables/periodic-s2-n512.inc")
constexpr double kShippedS2[] = {
#include "engine/periodic_tables/periodic-s2-n512.inc"
};
#define PUNCHSWEEP_SHIPPED_S2 1
#endif
#if __has_include("engine/periodic_tables/periodic-s3-n512.inc")
constexpr double kShippedS3[] = {
#include "engine/periodic_tables/periodic-s3-n512.inc"
};
#define PUNCHSWEEP_SHIPPED_S3 1
#endif

#if __has_include("engine/periodic_tables/small_spot-s1.inc")
constexpr double kSmallSpotS1[] = {
#include "engine/periodic_tables/small_spot-s1.inc"
};
#define PUNCHSWEEP_SMALL_SPOT_S1 1
#endif
#if __has_include("engine/periodic_tables/small_spot-s2.inc")
constexpr double kSmallSpotS2[] = {
#include "engine/periodic_tables/small_spot-s2.inc"
};
#define PUNCHSWEEP_SMALL_SPOT_S2 1
#endif
#if __has_include("engine/periodic_tables/small_spot-s3.inc")
constexpr double kSmallSpotS3[] = {
#include "engine/periodic_tables/small_spot-s3.inc"
};
#define PUNCHSWEEP_SMALL_SPOT_S3 1
#endif

std::span<const double> shipped_small_spot_numbers(int s) {
  switch (s) {
#ifdef PUNCHSWEEP_SMALL_SPOT_S1
    case 1: return kSmallSpotS1;
#endif
#ifdef PUNCHSWEEP_SMALL_SPOT_S2
    case 2: return kSmallSpotS2;
#endif
#ifdef PUNCHSWEEP_SMALL_SPOT_S3
    case 3: return kSmallSpotS3;
#endif
    default: return {};
  }
}

/// Numbers as C++ source: an initializer list of hex floats, four a line, under a header.
std::string numbers_source(const std::vector<double>& numbers, const std::string& title, const std::string& provenance) {
  std::ostringstream out;
  out << "// " << title << "\n";
  std::istringstream lines(provenance);
  for (std::string line; std::getline(lines, line);) out << "// " << line << "\n";
  char text[40];
  for (std::size_t i = 0; i < numbers.size(); ++i) {
    std::snprintf(text, sizeof text, "%a,", numbers[i]);
    out << text << ((i + 1) % 4 == 0 ? "\n" : " ");
  }
  out << "\n";
  return out.str();
}

std::span<const double> shipped_numbers(int s) {
  switch (s) {
#ifdef PUNCHSWEEP_SHIPPED_S1
    case 1: return kShippedS1;
#endif
#ifdef PUNCHSWEEP_SHIPPED_S2
    case 2: return kShippedS2;
#endif
#ifdef PUNCHSWEEP_SHIPPED_S3
    case 3: return kShippedS3;
#endif
    default: return {};
  }
}

/// Agreement of a re-solved sample with the table: the loads and h to the solver's
/// tolerance (relative); a level's contact area to one node and its mirror images (a node at
/// the rim may tip either way between a solve warm-started along the path and one from the
/// uniform pressure).
constexpr double kLoadAgreement = 1e-6;

bool agrees(double table, double direct, double relative, double floor) {
  return std::abs(table - direct) <= relative * std::abs(direct) + floor;
}
bool same_area(double a_table, double a_direct, int n) {
  return std::abs(std::numbers::pi * (a_table * a_table - a_direct * a_direct)) <= 4.5 / (double(n) * n);
}

}  // namespace

std::optional<model::PeriodicTable> shipped_periodic_table(int s, int n) {
  if (n != kPeriodicTableGrid) return std::nullopt;
  const std::span<const double> numbers = shipped_numbers(s);
  if (numbers.empty()) return std::nullopt;
  return model::PeriodicTable::from_tables(std::vector<double>(numbers.begin(), numbers.end()));
}

bool spot_check(const model::PeriodicTable& table, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  const auto draw = [&](int count) { return static_cast<int>(random() % static_cast<std::uint64_t>(count)); };
  // Three samples of the single level (not the unloaded one, not the last: full contact).
  const int K1 = static_cast<int>(table.h1.size());
  for (int trial = 0; trial < 3; ++trial) {
    const int k = 1 + draw(K1 - 2);
    const model::PeriodicState direct = reference::solve_scaled(table.s, std::pow(table.sample_v(k), table.s + 1),
                                                                std::numeric_limits<double>::infinity(), table.n);
    if (!agrees(table.h1[k], direct.h, kLoadAgreement, 1e-12) || !same_area(table.a11[k], direct.a1, table.n)) {
      return false;
    }
  }
  // One sample of every two-level row, and the row's level-2 share (the cell's geometry).
  for (int j = 0; j < table.J; ++j) {
    const int k = 1 + draw(table.K - 1);
    const double delta = table.sample_delta(j);
    const double xi = table.xi_star[j] + table.sample_excess(j, k);
    const model::PeriodicState direct = reference::solve_scaled(table.s, xi, delta, table.n);
    const std::size_t at = static_cast<std::size_t>(j) * table.K + k;
    if (!agrees(table.Q2[at], direct.Q2, kLoadAgreement, 1e-9 * xi) || !same_area(table.a1[at], direct.a1, table.n) ||
        !same_area(table.a2[at], direct.a2, table.n)) {
      return false;
    }
    if (std::abs(reference::level2_share(reference::scaled_cell(table.s, delta, table.n)) - table.share2[j]) > 1e-12) {
      return false;
    }
  }
  return true;
}

model::PeriodicTable build_periodic_table_with_progress(int s, int n, bool quiet,
                                                       const reference::PeriodicTableOptions& options,
                                                       const std::string& where) {
  reference::PeriodicTableOptions build = options;
  build.n = n;
  const auto start = std::chrono::steady_clock::now();
  int shown = -1;
  if (!quiet) {
    build.progress = [&, previous = options.progress](int done, int planned) {
      if (previous) previous(done, planned);
      const int percent = std::min(static_cast<int>(100.0 * done / std::max(planned, 1)), 99);
      if (percent / 10 != shown / 10) {
        shown = percent;
        std::fprintf(stderr, "\rpunchsweep: building the periodic tables of s = %d (grid %d): %3d%%", s, n, percent);
        std::fflush(stderr);
      }
    };
  }
  model::PeriodicTable table = reference::build_periodic_table(s, build);
  if (!quiet) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "\rpunchsweep: built the periodic tables of s = %d (grid %d) in %.0f s (%s)\n", s, n, seconds,
                 where.c_str());
  }
  return table;
}

std::shared_ptr<const model::PeriodicTable> periodic_table_for(int s, int n,
                                                              const std::optional<std::filesystem::path>& folder,
                                                              bool quiet,
                                                              const reference::PeriodicTableOptions& options,
                                                              TableOrigin* origin) {
  TableOrigin ignored;
  if (origin == nullptr) origin = &ignored;
  *origin = TableOrigin::shipped;
  if (std::optional<model::PeriodicTable> shipped = shipped_periodic_table(s, n)) {
    return std::make_shared<const model::PeriodicTable>(std::move(*shipped));
  }
  const std::string name = model::PeriodicTable::table_name(s, n);
  std::optional<FileLock> lock;
  if (folder && make_private_folder(*folder)) {
    lock.emplace(*folder / (name + ".lock"));
    // Under the lock: a builder before us has saved its tables by now.
    // A file read is one this engine wrote under the cache's key (read_tables checks its
    // signature), so it is not solved again.
    const std::filesystem::path file = *folder / name;
    if (std::optional<model::PeriodicTable> cached = model::PeriodicTable::from_tables(read_tables(file))) {
      if (cached->s == s && cached->n == n) {
        *origin = TableOrigin::cache;
        return std::make_shared<const model::PeriodicTable>(std::move(*cached));
      }
    }
    std::error_code ec;
    if (std::filesystem::exists(std::filesystem::symlink_status(file, ec))) {
      std::fprintf(stderr, "punchsweep: the cached periodic tables %s are not this cache's (damaged, edited, of an "
                           "older engine, or not signed by its key); building them again\n", file.c_str());
    }
  }
  *origin = TableOrigin::built;
  auto table = std::make_shared<const model::PeriodicTable>(
      build_periodic_table_with_progress(s, n, quiet, options, folder ? "kept in the table cache" : "no table cache: built again next time"));
  if (folder) write_tables(*folder / name, table->tables());
  return table;
}

std::optional<model::SmallSpotTable> shipped_small_spot_table(int s) {
  const std::span<const double> numbers = shipped_small_spot_numbers(s);
  if (numbers.empty()) return std::nullopt;
  return model::SmallSpotTable::from_tables(std::vector<double>(numbers.begin(), numbers.end()));
}

std::shared_ptr<const model::SmallSpotTable> small_spot_table_for(int s, bool quiet) {
  if (std::optional<model::SmallSpotTable> shipped = shipped_small_spot_table(s)) {
    return std::make_shared<const model::SmallSpotTable>(std::move(*shipped));
  }
  // Built in every process that needs it (0.1 s; 2 s more where the refined model's shell
  // sums are built too, which the cache keeps): said only when it took a while.
  const auto start = std::chrono::steady_clock::now();
  auto table = std::make_shared<const model::SmallSpotTable>(model::build_small_spot_table(s));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!quiet && seconds >= 1.0) std::fprintf(stderr, "punchsweep: built the small-spot table of s = %d in %.1f s\n", s, seconds);
  return table;
}

std::shared_ptr<const model::PeriodicSolution> periodic_solution_for(int s, const std::optional<std::filesystem::path>& folder,
                                                                    bool quiet) {
  return std::make_shared<const model::PeriodicSolution>(periodic_table_for(s, kPeriodicTableGrid, folder, quiet),
                                                         small_spot_table_for(s, quiet));
}

std::string periodic_table_source(const model::PeriodicTable& table, const std::string& provenance) {
  return numbers_source(table.tables(),
                        "The periodic model's tables of s = " + std::to_string(table.s) + " on a " +
                            std::to_string(table.n) + " x " + std::to_string(table.n) +
                            " grid (docs/model.md, section 14.3).",
                        provenance);
}

std::string small_spot_table_source(const model::SmallSpotTable& table, const std::string& provenance) {
  return numbers_source(table.tables(),
                        "The periodic model's small-spot table of s = " + std::to_string(table.s) +
                            " (docs/model.md, section 14.7).",
                        provenance);
}

void use_table_cache() {
  const TableCacheFolder cache = table_cache_folder();
  std::string refusal = cache.not_used;
  if (cache.folder && refusal.empty()) refusal = untrusted_folder(*cache.folder);
  if (!cache.folder || !refusal.empty()) {
    if (!refusal.empty()) std::fprintf(stderr, "punchsweep: %s; tables are built in memory\n", refusal.c_str());
    model::set_shell_sums_store({});
    model::set_periodic_solution_source([](int s) {
      sweep::use_reproducible_fft_plans();
      return periodic_solution_for(s, std::nullopt);
    });
    return;
  }
  const std::filesystem::path root = *cache.folder;
  model::set_periodic_solution_source([root](int s) {
    sweep::use_reproducible_fft_plans();
    return periodic_solution_for(s, root);
  });
  model::set_shell_sums_store({[root](const std::string& name) { return read_tables(root / name); },
                               [root](const std::string& name, const std::vector<double>& tables) {
                                 write_tables(root / name, tables);
                               }});
}

}  // namespace punchsweep::engine
