#include "app/tables_command.hpp"

#include <boost/program_options.hpp>

#include <chrono>
#include <cmath>
#include <ostream>
#include <stdexcept>

#include "engine/periodic_tables.hpp"
#include "engine/table_cache.hpp"
#include "input/command_options.hpp"
#include "input/usage_error.hpp"
#include "input/value_parsing.hpp"
#include "io/output_file.hpp"
#include "engine/version.hpp"
#include "model/problem/localization.hpp"
#include "model/problem/shape.hpp"
#include "model/periodic/small_spot_builder.hpp"
#include "sweep/reproducible_fft.hpp"

namespace po = boost::program_options;

namespace punchsweep::app {
namespace {

/// A table's C++ source written whole, under the rule for every written file.
void write_source(const std::string& path, const std::string& text) {
  try {
    io::write_file_whole(path, text);
  } catch (const std::runtime_error& e) {
    throw input::UsageError(std::string("--write-source: ") + e.what());
  }
}

po::options_description tables_options() {
  po::options_description opts(
      "punchsweep tables: the periodic model's tables (docs/model.md, section 14): the\n"
      "elastic solution of the whole periodic two-level cell by the boundary elements, per\n"
      "shape exponent s, in its scaled variables. s = 1, 2, 3 ship with the engine; others\n"
      "are built once (about a minute each on one core) and kept in the table cache\n"
      "($PUNCHSWEEP_CACHE, else $XDG_CACHE_HOME/punchsweep or ~/.cache/punchsweep).\n\n"
      "Options");
  opts.add_options()
      ("help,h", "this text")
      ("s", po::value<std::string>()->value_name("S")->default_value("1,2,3"),
       "shape exponents: integers in [1, 32], separated by commas")
      ("grid", po::value<std::string>()->value_name("N")->default_value(std::to_string(engine::kPeriodicTableGrid)),
       "boundary-element grid per side; the engine reads 512 (others are for convergence studies)")
      ("write-source", po::value<std::string>()->value_name("DIR"),
       "build afresh (not from the cache or the shipped ones) and write periodic-s<S>-n<N>.inc and "
       "small_spot-s<S>.inc, the source text the engine ships, into DIR")
      ("small-spot-only", po::bool_switch(),
       "with --write-source: the small-spot tables alone (docs/model.md, section 14.7; seconds, "
       "where the boundary elements' take minutes)")
      ("quiet", po::bool_switch(), "no progress");
  return opts;
}

}  // namespace

int run_tables_command(const std::vector<std::string>& args, std::ostream& out) {
  const po::options_description opts = tables_options();
  po::variables_map vm;
  try {
    po::store(po::command_line_parser(args).options(opts).run(), vm);
    po::notify(vm);
  } catch (const po::error& e) {
    throw input::UsageError(e.what());
  }
  if (vm.count("help")) {
    out << opts;
    return 0;
  }
  std::vector<int> exponents;
  for (const double s : input::parse_real_list(vm["s"].as<std::string>(), "--s")) {
    if (s != std::floor(s) || s < model::Shape::kMinExponent || s > model::Localization::kMaxPeriodicExponent) {
      throw input::UsageError("--s: " + input::json_number(s) + " is not an integer in [1, " +
                              std::to_string(model::Localization::kMaxPeriodicExponent) + "] (the periodic model's exponents)");
    }
    exponents.push_back(static_cast<int>(s));
  }
  const int n = input::parse_integer(vm["grid"].as<std::string>(), "--grid");
  if (n < 16 || n > 2048 || n % 2 != 0) throw input::UsageError("--grid: " + std::to_string(n) + " is not an even integer in [16, 2048]");
  const bool quiet = vm["quiet"].as<bool>();
  sweep::use_reproducible_fft_plans();

  if (vm.count("write-source")) {
    const std::filesystem::path dir = vm["write-source"].as<std::string>();
    if (!std::filesystem::is_directory(dir)) throw input::UsageError("--write-source: " + dir.string() + " is not a folder");
    const bool small_only = vm["small-spot-only"].as<bool>();
    for (const int s : exponents) {
      const auto small_start = std::chrono::steady_clock::now();
      const model::SmallSpotTable small = model::build_small_spot_table(s);
      const double small_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - small_start).count();
      char small_provenance[600];
      std::snprintf(small_provenance, sizeof small_provenance,
                    "Made by `punchsweep tables --s %d --write-source DIR%s` (punchsweep %s, git %s) in %.1f s on one "
                    "core.\nThe refined localization (D = %d), its far field corrected by %.9e to the lattice's.\n"
                    "Samples: %d + 1 in v up to %.9g (hand-over from %.9g), %d + 1 in zeta. Numbers in order of "
                    "model::SmallSpotTable::tables().",
                    s, small_only ? " --small-spot-only" : "", engine::kVersion, engine::kGitRevision, small_seconds, small.shells,
                    small.far_field_correction, small.M, small.v_top, small.v_hand, small.Z);
      const std::filesystem::path small_file = dir / (model::SmallSpotTable::table_name(s) + ".inc");
      write_source(small_file.string(), engine::small_spot_table_source(small, small_provenance));
      out << "s = " << s << ": wrote " << small_file.string() << " (" << small_seconds << " s)\n";
      if (small_only) continue;
      const auto start = std::chrono::steady_clock::now();
      const std::shared_ptr<const model::PeriodicTable> table = std::make_shared<const model::PeriodicTable>(
          engine::build_periodic_table_with_progress(s, n, quiet, {}, "written as source"));
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      char provenance[400];
      std::snprintf(provenance, sizeof provenance,
                    "Made by `punchsweep tables --s %d --grid %d --write-source DIR` (punchsweep %s, git %s) in "
                    "%.0f s on one core.\nSamples: %zu in v, %d x %d in (delta, r). Numbers in order of "
                    "model::PeriodicTable::tables().",
                    s, n, engine::kVersion, engine::kGitRevision, seconds, table->h1.size(), table->J, table->K);
      const std::filesystem::path file = dir / (model::PeriodicTable::table_name(s, n) + ".inc");
      write_source(file.string(), engine::periodic_table_source(*table, provenance));
      out << "s = " << s << ": wrote " << file.string() << " (" << seconds << " s)\n";
    }
    return 0;
  }

  const engine::TableCacheFolder cache = engine::table_cache_folder();
  std::optional<std::filesystem::path> folder = cache.folder;
  if (folder && !engine::untrusted_folder(*folder).empty()) folder.reset();
  for (const int s : exponents) {
    const auto start = std::chrono::steady_clock::now();
    engine::TableOrigin origin{};
    const std::shared_ptr<const model::PeriodicTable> table = engine::periodic_table_for(s, n, folder, quiet, {}, &origin);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out << "s = " << s << ", grid " << n << ": " << (origin == engine::TableOrigin::shipped ? std::string("shipped with the engine")
            : origin == engine::TableOrigin::cache ? "read from the table cache " + folder->string()
            : folder ? "built and kept in the table cache " + folder->string()
                     : std::string("built (no table cache: built again next time)"))
        << "; single level to xi = " << table->xi_full_single() << " (full contact), two levels for dh/(C l^s) up to "
        << table->delta_top << " (" << seconds << " s)\n";
    const bool small_shipped = engine::shipped_small_spot_table(s).has_value();
    const std::shared_ptr<const model::SmallSpotTable> small = engine::small_spot_table_for(s, quiet);
    out << "s = " << s << ": small-spot table " << (small_shipped ? "shipped with the engine" : "built") << ", below xi = "
        << small->xi_top() << " (the hand-over from xi = " << small->xi_hand() << ")\n";
  }
  return 0;
}

}  // namespace punchsweep::app
