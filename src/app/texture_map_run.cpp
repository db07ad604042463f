#include "app/texture_map_run.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "engine/surface_evaluation.hpp"
#include "app/surface_map_command.hpp"
#include "engine/texture_map.hpp"
#include "input/usage_error.hpp"
#include "io/encoded_tile.hpp"
#include "io/tile_journal.hpp"
#include "run/exit_codes.hpp"
#include "run/output_lock.hpp"
#include "run/preflight.hpp"
#include "run/text_lines.hpp"
#include "sweep/mpi_session.hpp"
#include "sweep/scheduler.hpp"
#include "sweep/tile_ranges.hpp"

namespace punchsweep::app {
namespace {

volatile std::sig_atomic_t g_stop_signal = 0;

extern "C" void on_texture_stop_signal(int signal) { g_stop_signal = signal; }

// A block's values as a journal chunk, and back (native endianness, as the journal's).
std::vector<std::byte> as_bytes(const std::vector<double>& values) {
  std::vector<std::byte> bytes(values.size() * sizeof(double));
  if (!values.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
  return bytes;
}

std::vector<double> as_values(const std::vector<std::byte>& bytes) {
  if (bytes.size() % sizeof(double) != 0) throw std::invalid_argument("a geometry's chunk is not whole values");
  std::vector<double> values(bytes.size() / sizeof(double));
  if (!values.empty()) std::memcpy(values.data(), bytes.data(), bytes.size());
  return values;
}

std::string bytes_text(double bytes) {
  std::ostringstream out;
  out.precision(3);
  if (bytes >= 1e9) {
    out << bytes / 1e9 << " GB";
  } else {
    out << bytes / 1e6 << " MB";
  }
  return out.str();
}

/// --dry-run: the map's axes, and what each geometry's curve asks (its grids, memory,
/// whether the cache holds it, its estimated time), summed up for the run's ranks. The
/// geometries are listed one a line up to kListed, else grouped by their grids.
void print_dry_run(const engine::TextureMapPlan& plan, const TextureMapJob& job, int ranks, std::ostream& out) {
  constexpr std::size_t kListed = 24;
  const engine::SurfaceMap& map = plan.header();
  const std::size_t G = plan.geometries(), P = map.load_points();
  out << job.program << " --dry-run (a texture's map)\n";
  out << "  texture: " << map.texture << "\n";
  // Lengths in R's own unit where the map has one ("60 um"), as the progress lines give them.
  const auto [per_R, length_unit] = map.length_unit();
  for (const auto* axes : {&map.geometry, &map.load}) {
    for (const engine::SurfaceMapAxis& a : *axes) {
      const bool length = a.scale == "R";
      const double scale = length ? per_R : 1.0;
      out << "  " << a.name << ": " << a.values.size() << " value" << (a.values.size() == 1 ? "" : "s") << " in ["
          << a.values.front() * scale;
      if (a.values.size() > 1) out << " .. " << *std::max_element(a.values.begin(), a.values.end()) * scale;
      const std::string unit = length ? length_unit : a.scale;
      out << "]" << (unit == "1" ? "" : " " + unit) << (axes == &map.geometry ? " (geometry: a load curve each)" : "") << "\n";
    }
  }
  out << "  points: " << G << " geometr" << (G == 1 ? "y" : "ies") << " x " << P << " load points";
  if (const std::size_t per = map.tiles_per_geometry(); per > 1) {
    out << " in " << plan.tiles() << " tiles (" << per << " a geometry, up to " << map.tile_rows * map.points_per_row()
        << " load points each)";
  }
  out << "\n";
  double seconds = 0.0, largest = 0.0, bytes = 0.0, reading = 0.0;
  std::size_t cached = 0, tables = 0, built = 0, continued = 0;
  std::map<std::string, std::size_t> groups;  // grids -> geometries
  for (std::size_t g = 0; g < G; ++g) {
    const engine::CurveCost cost = engine::curve_cost(plan.keywords_of(g), plan.load_points());
    std::ostringstream what;
    double mine = 0.0;
    if (cost.source != "cell") {
      ++tables;
      what << "off the periodic tables";
    } else {
      bool all_cached = true, any_continued = false;
      for (std::size_t k = 0; k < cost.grids.size(); ++k) {
        const engine::CurveCost::Grid& grid = cost.grids[k];
        what << (k ? ", then " : "") << grid.nx << " x " << grid.ny << " nodes";
        if (grid.nodes_per_pitch > 0) what << " (" << grid.nodes_per_pitch << " a pitch)";
        what << (grid.cached ? " cached" : grid.continued_from > 0.0 ? " continued from the cache" : "");
        mine += grid.seconds;
        bytes = std::max(bytes, grid.bytes);
        all_cached = all_cached && grid.cached;
        any_continued = any_continued || grid.continued_from > 0.0;
      }
      what << ", " << cost.caps << " caps, " << cost.levels << " levels";
      if (cost.auto_grid) what << " (--grid auto: at least these grids)";
      if (all_cached) {
        ++cached;
      } else if (any_continued) {
        ++continued;
      } else {
        ++built;
      }
    }
    seconds += mine;
    largest = std::max(largest, mine);
    reading += engine::estimated_reading_seconds(P, cost.levels, plan.times(), map.full);
    if (G <= kListed) {
      out << "  geometry " << g + 1 << " (" << plan.describe(g) << "): " << what.str();
      if (mine > 0.0) out << "; about " << engine::seconds_text(mine);
      out << "\n";
    } else {
      ++groups[what.str()];
    }
  }
  for (const auto& [what, count] : groups) out << "  " << count << " geometr" << (count == 1 ? "y" : "ies") << ": " << what << "\n";
  out << "  curves: " << built << " to build, " << cached << " in the cache, ";
  if (continued > 0) out << continued << " continued from the cache (its beginning saved), ";
  out << tables << " off the periodic tables\n";
  if (bytes > 0.0) {
    const double machine = engine::machine_bytes();
    out << "  memory: about " << bytes_text(bytes) << " a rank for the largest curve (" << ranks << " rank"
        << (ranks == 1 ? "" : "s") << " on one node: " << bytes_text(bytes * ranks) << " of this machine's " << bytes_text(machine) << ")\n";
  }
  // Dealt one at a time, the costliest first, the readings in tiles: the run takes about
  // the larger of the share of a rank and the largest curve.
  const double wall = std::max((seconds + reading) / ranks, largest);
  out << "  estimated time: about " << engine::seconds_text(wall) << " on " << ranks << " rank" << (ranks == 1 ? "" : "s") << " ("
      << engine::seconds_text(seconds) << " of curves on one core, each estimate within a factor of " << engine::kCurveSecondsSpread
      << " on this machine's measurements; " << engine::seconds_text(reading) << " of reading the load points off them, "
      << "within 25%)\n";
  out << "  output: " << job.output << " (nothing written by a dry run)\n";
}

}  // namespace

int run_texture_map(const TextureMapJob& job, int rank, int ranks) {
  const bool root = rank == 0;
  const auto say = [&job](const std::string& text) {
    for (const std::string& line : run::split_lines(text)) std::cerr << job.program << ": " << line << "\n";
  };

  // The plan, on every rank alike (the same keywords give every rank the same verdict).
  std::unique_ptr<const engine::TextureMapPlan> plan;
  try {
    plan = std::make_unique<const engine::TextureMapPlan>(job.keywords);
  } catch (const input::UsageError& e) {
    if (root) say(e.what());
    return input::kUsageExitCode;
  }
  const std::size_t G = plan->geometries(), P = plan->header().load_points(), U = plan->tiles();
  const std::size_t per = plan->header().tiles_per_geometry();
  const run::OutputPaths paths(job.output);
  const std::vector<std::string> identity = engine::texture_map_identity(job.keywords);
  const std::string identity_text = run::join(identity, "\n");  // the journal's header, the map's attribute
  sweep::SweepConfig policy;  // the sweep's resume policy, for this map
  policy.overwrite = job.overwrite;
  policy.resume = job.resume;
  policy.identity = identity;
  policy.input_files = job.input_files;
  for (const std::string& file : engine::texture_input_files(job.keywords)) policy.input_files.push_back(file);
  if (job.dry_run) {
    // With --resume the dry run also says whether the map would resume (a job script asks
    // it before it writes anything into a run folder): another configuration is refused.
    std::string refusal;
    if (root && job.resume && !job.overwrite) {
      run::Start start = run::Start::fresh;
      refusal = run::preflight(policy, paths, &start);
    }
    if (sweep::share_from_root(refusal.empty() ? 0 : 1) != 0) {
      if (root) say(refusal);
      return input::kUsageExitCode;
    }
    if (root) print_dry_run(*plan, job, ranks, std::cout);
    return 0;
  }
  const std::vector<std::size_t> order = plan->dealing_order(ranks);

  // Rank 0 claims the map's name, then applies the sweep's resume policy; every rank
  // learns the verdict.
  std::optional<run::OutputLock> lock;
  run::Start start = run::Start::fresh;
  std::string refusal;
  if (root) {
    refusal = run::output_folder_problem(paths);
    if (refusal.empty()) {
      if (auto taken = run::OutputLock::take(paths, job.command, &refusal)) lock.emplace(std::move(*taken));
    }
    if (refusal.empty()) refusal = run::preflight(policy, paths, &start);
  }
  if (sweep::share_from_root(refusal.empty() ? 0 : 1) != 0) {
    if (root) say(refusal);
    return input::kUsageExitCode;
  }
  start = static_cast<run::Start>(sweep::share_from_root(static_cast<int>(start)));
  if (start == run::Start::already_complete) {
    if (root && !job.quiet) say(job.output + " is already complete; nothing to resume");
    return 0;
  }

  // Rank 0: the map's writer, and its journal (replayed into the map on resume).
  engine::SurfaceMap header = plan->header();
  header.identity = identity_text;
  header.layout_version = map::kTextureLayoutVersion;
  std::optional<engine::TextureMapWriter> writer;
  std::optional<io::TileJournal> journal;
  sweep::TileRanges pending;
  std::size_t resumed = 0;
  if (root) {
    try {
      // (The resume policy has decided about an existing map: overwrite here.)
      writer.emplace(job.output, std::move(header), true, job.keywords);
      std::vector<bool> done(U, false);
      if (start == run::Start::resume) {
        const std::size_t good = io::TileJournal::replay(paths.journal, [&](const io::EncodedTile& tile) {
          if (tile.tile >= U || tile.chunks.size() != 1 || done[tile.tile]) return false;
          try {
            writer->write(tile.tile, as_values(tile.chunks.front()));
          } catch (const std::exception&) {
            return false;  // computed again
          }
          done[tile.tile] = true;
          return true;
        });
        journal.emplace(io::TileJournal::open_for_append(paths.journal, good));
      } else {
        journal.emplace(io::TileJournal::create(paths.journal, identity_text));
      }
      // The scheduler deals positions in the dealing order (the costliest curve first).
      for (std::size_t k = 0; k < U; ++k) {
        if (done[order[k]]) {
          ++resumed;
        } else {
          pending.add(k);
        }
      }
    } catch (const std::exception& e) {  // input::UsageError included
      refusal = e.what();
    }
  }
  if (sweep::share_from_root(refusal.empty() ? 0 : 1) != 0) {
    if (root) say(refusal);
    return 1;
  }
  if (root && !job.quiet) {
    std::ostringstream line;
    line << G << " geometr" << (G == 1 ? "y" : "ies") << " (a load curve each) x " << P << " load points";
    if (per > 1) line << " in " << U << " tiles" << (G > 1 ? " (" + std::to_string(per) + " a geometry)" : "");
    line << " on " << ranks << " rank" << (ranks == 1 ? "" : "s");
    if (resumed > 0) line << "; " << resumed << " already done (from " << paths.journal << ")";
    say(line.str());
  }

  for (const int signal : {SIGTERM, SIGUSR1, SIGINT}) std::signal(signal, on_texture_stop_signal);
  // Every rank: a tile computed into its block, as one journal record. A geometry that
  // fails stops every rank (said by the rank that met it, with the geometry).
  const sweep::TileWork work = [&](std::uint64_t k) {
    const std::size_t u = order.at(k), g = plan->header().tile(u).geometry;
    std::vector<double> block;
    try {
      block = plan->evaluate(u);
    } catch (const input::UsageError& e) {
      say("geometry " + std::to_string(g + 1) + " (" + plan->describe(g) + "): " + e.what());
      sweep::abort_all_ranks(input::kUsageExitCode);
    } catch (const std::exception& e) {
      say("rank " + std::to_string(rank) + ", geometry " + std::to_string(g + 1) + " (" + plan->describe(g) + "): " + e.what());
      sweep::abort_all_ranks(1);
    }
    io::EncodedTile tile;
    tile.tile = u;
    tile.chunks.push_back(as_bytes(block));
    tile.summary.points = plan->header().tile(u).count;
    return io::pack_encoded_tile(tile);
  };
  // Rank 0: each tile journalled first, then placed, then a progress line.
  std::size_t done = resumed, last_step = 20 * resumed / std::max<std::size_t>(U, 1);
  const auto begun = std::chrono::steady_clock::now();
  const sweep::TileSink sink = [&](std::span<const std::byte> bytes) {
    journal->append_packed(bytes);
    const io::EncodedTile tile = io::unpack_encoded_tile(bytes.data(), bytes.size());
    const std::vector<double> block = as_values(tile.chunks.at(0));
    writer->write(tile.tile, block);
    ++done;
    if (job.quiet) return;
    const engine::GeometryCost cost = engine::geometry_cost(block);
    // A line for every tile that opened its curve (built, read from the cache or the
    // tables); of the tiles that read a curve the rank held, one at each 5% of the map and
    // the last: a map of many tiles does not flood the log.
    const std::size_t step = 20 * done / U;
    if (cost.held && step == last_step && done < U) return;
    last_step = step;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - begun).count();
    const double left = elapsed / static_cast<double>(done - resumed) * static_cast<double>(U - done);
    const engine::SurfaceMap::Tile at = plan->header().tile(tile.tile);
    std::ostringstream line;
    line << "geometry " << at.geometry + 1 << " (" << plan->describe(at.geometry) << ")";
    if (per > 1) line << ", load points " << at.first + 1 << " to " << at.first + at.count << " of " << P;
    line << ": curve " << cost.source;
    if (!cost.held) line << " in " << engine::seconds_text(cost.seconds);
    line << "; " << done << " of " << U << " done (" << (100 * done) / U << "%)";
    if (done < U) line << ", about " << engine::seconds_text(left) << " left";
    say(line.str());
  };
  int code = 0;
  try {
    const sweep::ScheduleResult result =
        sweep::run_world_schedule(root ? pending : sweep::TileRanges{}, work, root ? sink : sweep::TileSink{}, &g_stop_signal,
                                   per > 1 ? sweep::Pace::readings : sweep::Pace::units);
    if (root && result.interrupted) {
      const int signal = result.stop_signal != 0 ? result.stop_signal : static_cast<int>(g_stop_signal);
      std::string resume = job.command;
      if (!job.resume) resume += " --resume";
      say("stopped by signal " + std::to_string(signal) + " (received by rank " + std::to_string(result.stop_rank) +
          ") with " + std::to_string(done) + " of " + std::to_string(U) + (per > 1 ? " tiles" : " geometries") +
          " done; the finished ones are kept in " +
          paths.journal + ".\n  Resume with: " + resume);
      code = run::kInterruptedExitCode;
    } else if (root) {
      writer->finish();
      journal.reset();
      std::filesystem::remove(paths.journal);
      if (!job.quiet) {
        say("wrote " + job.output + " (" + std::to_string(G) + " geometr" + (G == 1 ? "y" : "ies") + " x " +
            std::to_string(P) + " load points x " + std::to_string(writer->levels()) + " levels, " +
            std::to_string(writer->times()) + " times)");
      }
    }
  } catch (const input::UsageError& e) {
    say(e.what());
    sweep::abort_all_ranks(input::kUsageExitCode);
  } catch (const std::exception& e) {
    say("rank " + std::to_string(rank) + ": " + e.what());
    sweep::abort_all_ranks(1);
  }
  return ranks > 1 ? sweep::share_from_root(code) : code;
}

int run_surface_map_command(const std::vector<std::string>& args) {
  sweep::MpiSession mpi;
  const bool root = mpi.rank() == 0;
  TextureMapJob job;
  job.program = "punchsweep surface-map";
  job.command = run::shell_command("punchsweep surface-map", args);
  try {
    SurfaceMapArgs read = read_surface_map_args(args);
    if (!read.help.empty()) {
      if (root) std::cout << read.help;
      return 0;
    }
    job.keywords = std::move(read.keywords);
    job.output = read.output;
    job.overwrite = read.overwrite;
    job.resume = read.resume;
    job.quiet = read.quiet;
  } catch (const input::UsageError& e) {
    if (root) std::cerr << "punchsweep surface-map: " << e.what() << "\n";
    return input::kUsageExitCode;
  }
  return run_texture_map(job, mpi.rank(), mpi.size());
}

}  // namespace punchsweep::app
