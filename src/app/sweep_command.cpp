#include "app/sweep_command.hpp"

#include "input/axis_parser.hpp"

#ifdef __linux__
#endif

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <numeric>
#include <optional>
#include <random>
#include <sstream>

#include <unistd.h>

#include "input/sweep_options.hpp"
#include "input/texture_sweep_options.hpp"
#include "engine/texture_map.hpp"
#include "app/texture_map_run.hpp"
#include "input/usage_error.hpp"
#include "engine/version.hpp"
#include "io/map_variables.hpp"
#include "io/regime_map_writer.hpp"
#include "io/tile_encoder.hpp"
#include "io/tile_journal.hpp"
#include "input/axis_parser.hpp"
#include "map/tiling.hpp"
#include "run/disk_space.hpp"
#include "run/exit_codes.hpp"
#include "run/map_run.hpp"
#include "run/output_lock.hpp"
#include "run/preflight.hpp"
#include "run/text_lines.hpp"
#include "sweep/mpi_session.hpp"
#include "sweep/scheduler.hpp"
#include "sweep/tile_evaluator.hpp"

namespace fs = std::filesystem;

namespace punchsweep::app {
namespace {

volatile std::sig_atomic_t g_stop_signal = 0;

extern "C" void on_stop_signal(int signal) { g_stop_signal = signal; }

// The arguments as a shell would need them typed again (the resume hint is copy-pasted).
std::string command_line(const std::vector<std::string>& args) { return run::shell_command("punchsweep sweep", args); }

std::string utc_now() {
  char buf[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return buf;
}

/// The map's layout with the reference the evaluator computes.
io::MapLayout layout_of(const sweep::SweepConfig& config, const map::Tiling& tiling,
                        const sweep::TileEvaluator& evaluator) {
  std::optional<std::uint64_t> reference_points;
  if (const auto& sample = evaluator.reference_sample()) reference_points = sample->size();
  return run::map_layout(config, tiling, reference_points, evaluator.reference_options().solver.tolerance);
}

/// Seconds per reference point at the configured BEM grid, measured on sampled points
/// spread over the sample: at least one, more while the measurement is under a second.
double calibrate_reference(const sweep::SweepConfig& config, const sweep::TileEvaluator& evaluator,
                           std::size_t* measured) {
  const sweep::ReferenceSample& sample = *evaluator.reference_sample();
  map::TileData data;
  const auto start = std::chrono::steady_clock::now();
  double elapsed = 0.0;
  constexpr std::uint64_t kMaxPoints = 5;
  const std::uint64_t tries = std::min<std::uint64_t>(kMaxPoints, sample.size());
  *measured = 0;
  if (tries == 0) return 0.0;  // an empty sample (no point the rule picks)
  for (std::uint64_t k = 0; k < tries && (k == 0 || elapsed < 1.0); ++k) {
    // The one point, as a tile.
    const map::TileBox box = map::TileBox::point(config.grid.position(sample.at(sample.size() / tries * k)));
    evaluator.evaluate(box, &data);  // the model's share of it is microseconds
    ++*measured;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return elapsed / static_cast<double>(*measured);
}

void print_dry_run(const sweep::SweepConfig& config, const map::Tiling& tiling, int ranks) {
  const std::size_t points = config.grid.points();
  const bool full = config.quantities == map::Quantities::full;
  // The model is calibrated without the reference, which would swamp it; the reference is
  // calibrated on its own.
  const sweep::TileEvaluator evaluator(config.grid, *config.creep_law, config.C, config.times, config.quantities,
                                       config.reference, config.loading, config.localization, config.tolerance);
  const io::MapLayout layout = layout_of(config, tiling, evaluator);
  std::printf("punchsweep sweep --dry-run\n");
  for (const map::Axis& axis : config.grid.axes) {
    std::printf("  %-4s %4zu values  %-28s [%g .. %g]\n", axis.name.c_str(), axis.values.size(), axis.text.c_str(),
                axis.values.front(), axis.values.back());
  }
  std::string chunk;
  for (const std::size_t c : tiling.chunk()) chunk += (chunk.empty() ? "" : " x ") + std::to_string(c);
  std::printf("  points: %zu in %zu tiles (chunk %s)\n", points, tiling.tiles(), chunk.c_str());
  std::printf("  quantities: %s", full ? "full" : "regime");
  if (full) std::printf(" (%zu snapshot times)", config.times.size());
  if (layout.bem) {
    std::printf("\n  reference: periodic BEM on a %d x %d grid at %lld of %zu points (sample %s, seed %lld)",
                layout.bem->grid, layout.bem->grid, static_cast<long long>(layout.bem->sample), points,
                layout.bem->sample_rule.c_str(), static_cast<long long>(layout.bem->seed));
  }
  const double bytes = static_cast<double>(points) * static_cast<double>(io::uncompressed_bytes_per_point(layout));
  const run::DiskEstimate disk = run::estimate_disk(tiling, evaluator, layout, 0.5);
  const double free = run::free_bytes(config.output);
  std::printf("\n  output: %s, %s uncompressed\n", config.output.c_str(), run::format_bytes(bytes).c_str());
  std::printf("  disk: measured on %llu points, the map takes about %s and its journal %s while it runs (%s free "
              "there)\n",
              static_cast<unsigned long long>(disk.sampled_points), run::format_bytes(disk.map_bytes).c_str(),
              run::format_bytes(disk.journal_bytes).c_str(), free < 0 ? "unknown" : run::format_bytes(free).c_str());
  if (const std::string problem = run::disk_space_problem(run::OutputPaths(config.output), disk);
      !problem.empty()) {
    std::printf("  disk: a run would be refused at its start: %s\n", problem.c_str());
  }
  // Calibration: whole tiles (so the per-tile reuse is measured too), picked at random.
  std::mt19937_64 rng(12345);
  std::uniform_int_distribution<std::size_t> pick(0, tiling.tiles() - 1);
  map::TileData data;
  std::size_t sampled = 0;
  const auto start = std::chrono::steady_clock::now();
  double elapsed = 0.0;
  for (int i = 0; i < 64 && elapsed < 1.0; ++i) {
    const map::TileBox box = tiling.box(pick(rng));
    evaluator.evaluate(box, &data, sweep::TileEvaluator::Reference::skipped);
    sampled += box.points();
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  const double per_point = elapsed / static_cast<double>(sampled);
  // A tile is computed by one rank: with fewer tiles than ranks the others stay idle.
  const double busy = static_cast<double>(std::min<std::size_t>(static_cast<std::size_t>(ranks), tiling.tiles()));
  double estimate = per_point * static_cast<double>(points) / busy;
  std::printf("  calibration: %zu points in %.2f s (%.3g points/s per rank)\n", sampled, elapsed, 1.0 / per_point);
  if (layout.bem) {
    std::size_t measured = 0;
    const double per_bem = calibrate_reference(config, evaluator, &measured);
    const double bem_estimate = per_bem * static_cast<double>(layout.bem->sample) / busy;
    std::printf("  reference calibration: %zu point%s, %.3g s per point at grid %d (%.3g s for the sample on %d "
                "rank%s)\n",
                measured, measured == 1 ? "" : "s", per_bem, layout.bem->grid, bem_estimate, ranks,
                ranks == 1 ? "" : "s");
    estimate += bem_estimate;
  }
  std::printf("  estimated time: %.3g s on %d rank%s (compute only)\n", estimate, ranks, ranks == 1 ? "" : "s");
  if (busy < ranks) {
    std::printf("  only %zu tile%s for %d ranks: a smaller --chunk lets every rank work\n", tiling.tiles(),
                tiling.tiles() == 1 ? "" : "s", ranks);
  }
}

/// What every rank computes: a tile evaluated and encoded into the map's chunks, packed;
/// nothing (an empty buffer) for a tile given up on a stop signal.
sweep::TileWork tile_work(const map::Tiling& tiling, const sweep::TileEvaluator& evaluator, io::TileEncoder& encoder) {
  return [&tiling, &evaluator, &encoder, data = map::TileData()](std::uint64_t tile) mutable {
    const map::TileBox box = tiling.box(tile);
    try {
      evaluator.evaluate(box, &data, sweep::TileEvaluator::Reference::evaluated, model::StopRequest(&g_stop_signal));
    } catch (const model::Stopped&) {
      return std::vector<std::byte>{};
    }
    return io::pack_encoded_tile(encoder.encode(tile, box, data));
  };
}

/// Rank 0's part of the run: the map, its journal, the schedule, the finish. Returns the exit code.
int manage(const sweep::SweepConfig& config, const std::vector<std::string>& args, run::Start start,
           const map::Tiling& tiling, const sweep::TileWork& work, const io::MapLayout& layout, int ranks) {
  io::MapAttributes attributes;
  attributes.title = "punchsweep regime map: two-level punch system on a viscoelastic half-space";
  attributes.source = std::string("punchsweep ") + engine::kVersion + " (git " + engine::kGitRevision + ")";
  attributes.history = utc_now() + " " + command_line(args);
  attributes.config_text = config.resolved_text;
  attributes.identity = run::join(config.identity, "\n");
  attributes.creep_law = std::string(config.creep_law->name);
  attributes.C = config.C;
  attributes.localization = config.localization.spelling();
  attributes.time_unit = config.time_unit();
  if (config.R) {
    attributes.R = input::format_axis_value(config.R->number) + " " + std::string(config.R->unit->name);
    attributes.R_m = config.R->si();
  }
  if (config.material) {
    attributes.material = {config.material->name(), config.material->text(), config.material->instantaneous_modulus_Pa(),
                           config.material->plane_strain_modulus_Pa(), config.material->poisson()};
  } else if (!config.materials.empty()) {
    // Several: their names and texts, one after the other in the material axis's order; the
    // pressure scale differs between them, so no single E0.
    for (std::size_t k = 0; k < config.materials.size(); ++k) {
      const model::Material& m = *config.materials[k];
      attributes.material.name += (k ? "\n" : "") + config.material_labels[k] + ": " + m.name();
      attributes.material.text += (k ? "\n" : "") + std::string("# ---- material ") + config.material_labels[k] +
                                  " ----\n" + m.text();
    }
  }

  run::MapRun map_run(config, layout, attributes, start, tiling, std::cerr);
  const sweep::ScheduleResult result =
      sweep::run_world_schedule(map_run.pending(), work,
                                [&](std::span<const std::byte> bytes) { map_run.accept(bytes); }, &g_stop_signal);
  if (result.interrupted) {
    map_run.interrupt();
    const int signal = result.stop_signal != 0 ? result.stop_signal : static_cast<int>(g_stop_signal);
    std::string resume = command_line(args);
    if (!config.resume) resume += " --resume";
    std::fprintf(stderr,
                 "punchsweep sweep: stopped by signal %d (received by rank %d) with %zu of %zu points done; the "
                 "finished tiles are kept in %s.\n  Resume with: %s\n",
                 signal, result.stop_rank, map_run.progress().points_done(), config.grid.points(),
                 map_run.paths().journal.c_str(), resume.c_str());
    return run::kInterruptedExitCode;
  }
  map_run.finish(ranks);
  if (!config.quiet) std::fprintf(stderr, "punchsweep sweep: map written to %s\n", config.output.c_str());
  return 0;
}


/// `punchsweep sweep` of a texture ([texture] in the config, or --texture.KEY): the texture
/// map's run (app/texture_map_run.hpp) with the sweep's lock, journal and resume.
int run_texture_sweep(const std::vector<std::string>& args, const sweep::MpiSession& mpi) {
  const bool root = mpi.rank() == 0;
  TextureMapJob job;
  job.program = "punchsweep sweep";
  job.command = command_line(args);
  try {
    const input::TextureSweepOptions options = input::parse_texture_sweep_options(args);
    if (options.help) {
      if (root) std::cout << input::kTextureSweepHelp;
      return 0;
    }
    engine::check_texture_keywords(options.keywords, options.origins);
    job.keywords = options.keywords;
    job.output = options.output;
    job.resume = options.resume;
    job.overwrite = options.overwrite;
    job.quiet = options.quiet;
    job.dry_run = options.dry_run;
    if (!options.config_path.empty()) job.input_files.push_back(options.config_path);
  } catch (const input::UsageError& e) {
    if (root) {
      for (const std::string& line : run::split_lines(e.what())) std::cerr << "punchsweep sweep: " << line << "\n";
    }
    return input::kUsageExitCode;
  }
  return run_texture_map(job, mpi.rank(), mpi.size());
}

}  // namespace

int run_sweep_command(const std::vector<std::string>& args) {
  sweep::MpiSession mpi;
  const bool root = mpi.rank() == 0;
  if (input::is_texture_sweep(args)) return run_texture_sweep(args, mpi);
  std::ostringstream discard;
  sweep::SweepConfig config;
  bool help = false;
  try {
    config = input::parse_sweep_options(args, root ? static_cast<std::ostream&>(std::cout) : discard, &help);
  } catch (const input::UsageError& e) {
    if (root) {
      for (const std::string& line : run::split_lines(e.what())) std::cerr << "punchsweep sweep: " << line << "\n";
    }
    return input::kUsageExitCode;
  }
  if (help) return 0;
  config.progress_to_terminal = isatty(STDERR_FILENO) == 1;  // else a log: a line each 5%

  // Rank 0 claims the map's name before it looks at any of its files (a second run into
  // the same output is refused here, naming the first); every rank learns the verdict.
  std::optional<run::OutputLock> lock;  // rank 0's, while the run lasts
  if (!config.dry_run) {
    std::string refusal;
    if (root) {
      const run::OutputPaths paths(config.output);
      refusal = run::output_folder_problem(paths);
      if (refusal.empty()) {
        if (auto taken = run::OutputLock::take(paths, command_line(args), &refusal)) lock.emplace(std::move(*taken));
      }
    }
    const int refused = sweep::share_from_root(root && !lock ? 1 : 0);
    if (refused != 0) {
      if (root) std::cerr << "punchsweep sweep: " << refusal << "\n";
      return input::kUsageExitCode;
    }
  }

  // run.chunk = auto: rank 0 decides (from the journal when resuming), every rank follows.
  std::uint64_t chunk = config.chunk;
  if (root) {
    run::resolve_chunk(config, run::OutputPaths(config.output), mpi.size());
    chunk = config.chunk;
  }
  chunk = sweep::share_from_root(chunk);
  sweep::set_chunk(config, static_cast<std::size_t>(chunk));

  const map::Tiling tiling(config.grid.shape(), config.tile_points());
  if (config.dry_run) {
    // With --resume the dry run also says whether the map would resume: a job script asks it
    // before it writes anything into a run folder (jobs/local.sh).
    if (config.resume && !config.overwrite) {
      run::Start start = run::Start::fresh;
      std::string refusal;
      if (root) refusal = run::preflight(config, run::OutputPaths(config.output), &start);
      if (sweep::share_from_root(refusal.empty() ? 0 : 1) != 0) {
        if (root) {
          for (const std::string& line : run::split_lines(refusal)) std::cerr << "punchsweep sweep: " << line << "\n";
        }
        return input::kUsageExitCode;
      }
    }
    if (root) print_dry_run(config, tiling, mpi.size());
    return 0;
  }

  // Rank 0 checks the file system; every rank learns the verdict.
  run::Start start = run::Start::fresh;
  std::string refusal;
  if (root) refusal = run::preflight(config, run::OutputPaths(config.output), &start);
  const int refused_start = sweep::share_from_root(refusal.empty() ? 0 : 1);
  if (refused_start != 0) {
    if (root) {
      for (const std::string& line : run::split_lines(refusal)) std::cerr << "punchsweep sweep: " << line << "\n";
    }
    return input::kUsageExitCode;
  }
  start = static_cast<run::Start>(sweep::share_from_root(static_cast<int>(start)));
  if (start == run::Start::already_complete) {
    if (root && !config.quiet) {
      std::cerr << "punchsweep sweep: " << config.output << " is already complete; nothing to resume\n";
    }
    return 0;
  }
  int code = 0;
  try {
    const sweep::TileEvaluator evaluator(config.grid, *config.creep_law, config.C, config.times, config.quantities,
                                         config.reference, config.loading, config.localization, config.tolerance);
    const io::MapLayout layout = layout_of(config, tiling, evaluator);
    // Rank 0 measures what the map and its journal will take (with the run's own evaluator,
    // whose caches the run then keeps) and refuses a run whose file system cannot hold them,
    // before any work.
    if (root) {
      const run::DiskEstimate disk = run::estimate_disk(tiling, evaluator, layout, 0.3);
      refusal = run::disk_space_problem(run::OutputPaths(config.output), disk);
      if (refusal.empty() && !config.quiet) {
        const double free = run::free_bytes(config.output);
        std::cerr << "punchsweep sweep: " << config.grid.points() << " points in " << tiling.tiles()
                  << " tiles; the map will take about " << run::format_bytes(disk.map_bytes) << " and its journal "
                  << run::format_bytes(disk.journal_bytes) << " until the map is complete ("
                  << (free < 0 ? std::string("free space unknown") : run::format_bytes(free) + " free") << ")\n";
      }
    }
    const int room = sweep::share_from_root(refusal.empty() ? 0 : 1);
    if (room != 0) {
      if (root) std::cerr << "punchsweep sweep: " << refusal << "\n";
      return input::kUsageExitCode;
    }

    for (const int signal : {SIGTERM, SIGUSR1, SIGINT}) std::signal(signal, on_stop_signal);
    // Every rank encodes the tiles it computes into the map's chunks.
    io::TileEncoder encoder(layout);
    const sweep::TileWork work = tile_work(tiling, evaluator, encoder);
    if (root) {
      code = manage(config, args, start, tiling, work, layout, mpi.size());
    } else {
      sweep::run_world_schedule({}, work, {}, &g_stop_signal);
    }
  } catch (const std::exception& e) {
    std::cerr << "punchsweep sweep: rank " << mpi.rank() << ": " << e.what() << "\n";
    sweep::abort_all_ranks(1);
  }
  return code;
}

}  // namespace punchsweep::app
