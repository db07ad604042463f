#include "app/sweep_command.hpp"

#include <fcntl.h>
#include <mpi.h>
#include <sys/file.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
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

#include "app/progress.hpp"
#include "app/sweep_options.hpp"
#include "app/usage_error.hpp"
#include "app/version.hpp"
#include "io/map_variables.hpp"
#include "io/regime_map_writer.hpp"
#include "io/tile_encoder.hpp"
#include "io/tile_journal.hpp"
#include "sweep/scheduler.hpp"
#include "sweep/tile_evaluator.hpp"
#include "sweep/tiling.hpp"

namespace fs = std::filesystem;

namespace punchsweep::app {
namespace {

volatile std::sig_atomic_t g_stop_signal = 0;

extern "C" void on_stop_signal(int signal) { g_stop_signal = signal; }

/// MPI for the life of the command.
class MpiSession {
 public:
  MpiSession() {
#ifdef __linux__
    // Under Open MPI's launcher a rank must not outlive it: after `kill -9 mpirun` orphans
    // would go on writing the map that --resume is about to rebuild. (Only there: a
    // singleton run may well be meant to outlive its shell.)
    if (std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr) {
      prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (getppid() == 1) std::_Exit(1);  // the launcher died before prctl took effect
    }
#endif
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiSession() { MPI_Finalize(); }
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0;
  int size_ = 1;
};

/// The three files of a map: the final one, the one under construction, and the journal.
struct OutputPaths {
  std::string final_path;
  std::string partial;
  std::string journal;
  explicit OutputPaths(const std::string& file)
      : final_path(file), partial(file + ".partial"), journal(file + ".partial.journal") {}
};

std::string join(const std::vector<std::string>& lines, const char* separator) {
  std::string text;
  for (std::size_t i = 0; i < lines.size(); ++i) text += (i ? separator : "") + lines[i];
  return text;
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// What rank 0 decided before any work: start fresh, or resume from the journal.
enum class Start { fresh, resume, already_complete };

/// Checks the output paths (before anything is created). Returns "" or the refusal.
std::string preflight(const sweep::SweepConfig& config, const OutputPaths& paths, Start* start) {
  const fs::path final_path(paths.final_path);
  const fs::path dir = final_path.has_parent_path() ? final_path.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    return "output.file = " + paths.final_path + ": the folder " + dir.string() + " does not exist";
  }
  // Create-and-remove a probe: access() says yes to root even where nothing can be created.
  const std::string probe = (dir / (".punchsweep-probe-" + std::to_string(::getpid()))).string();
  const int probe_fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (probe_fd < 0) {
    return "output.file = " + paths.final_path + ": the folder " + dir.string() + " is not writable";
  }
  ::close(probe_fd);
  ::unlink(probe.c_str());
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
  const bool final_exists = fs::exists(final_path, ec);
  const bool journal_exists = fs::exists(paths.journal, ec);
  *start = Start::fresh;
  if (config.overwrite) return {};
  if (config.resume) {
    if (final_exists && !journal_exists) {
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

// The arguments as a shell would need them typed again (the resume hint is copy-pasted).
std::string command_line(const std::vector<std::string>& args) {
  std::string text = "punchsweep sweep";
  for (const std::string& a : args) {
    const bool plain = !a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                         "0123456789_./,=:+-@%") == std::string::npos;
    if (plain) {
      text += " " + a;
      continue;
    }
    std::string quoted = "'";
    for (const char c : a) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    text += " " + quoted + "'";
  }
  return text;
}

std::string utc_now() {
  char buf[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return buf;
}

/// The map's layout: grid, times, quantities, the tiling's chunks, and the reference that
/// `evaluator` computes (its grid, solver tolerance and sample).
io::MapLayout map_layout(const sweep::SweepConfig& config, const sweep::Tiling& tiling,
                         const sweep::TileEvaluator& evaluator) {
  io::MapLayout layout{config.grid, config.times, config.quantities, tiling.chunk(), std::nullopt};
  if (const auto& sample = evaluator.reference_sample()) {
    const reference::ReferenceOptions& options = evaluator.reference_options();
    layout.bem = io::BemSetup{options.n, options.solver.tolerance, static_cast<std::int64_t>(sample->size()),
                              static_cast<std::int64_t>(config.reference.seed),
                              "periodic BEM, FFT influence, Polonsky-Keer CG, SLS creep stepping"};
  }
  return layout;
}

/// Seconds per reference point at the configured BEM grid, measured on sampled points
/// spread over the sample: at least one, more while the measurement is under a second.
double calibrate_reference(const sweep::SweepConfig& config, const sweep::TileEvaluator& evaluator,
                           std::size_t* measured) {
  const sweep::ReferenceSample& sample = *evaluator.reference_sample();
  const auto shape = config.grid.shape();
  io::TileData data;
  const auto start = std::chrono::steady_clock::now();
  double elapsed = 0.0;
  constexpr std::uint64_t kMaxPoints = 5;
  const std::uint64_t tries = std::min<std::uint64_t>(kMaxPoints, sample.size());
  *measured = 0;
  for (std::uint64_t k = 0; k < tries && (k == 0 || elapsed < 1.0); ++k) {
    std::uint64_t rest = sample.at(sample.size() / tries * k);
    sweep::TileBox box;  // the one point, as a tile
    for (std::size_t a = sweep::kAxes; a-- > 0; rest /= shape[a]) {
      box.start[a] = static_cast<std::size_t>(rest % shape[a]);
      box.count[a] = 1;
    }
    evaluator.evaluate(box, &data);  // the model's share of it is microseconds
    ++*measured;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return elapsed / static_cast<double>(*measured);
}

void print_dry_run(const sweep::SweepConfig& config, const sweep::Tiling& tiling, int ranks) {
  const std::size_t points = config.grid.points();
  const bool full = config.quantities == sweep::Quantities::full;
  // The model is calibrated without the reference, which would swamp it; the reference is
  // calibrated on its own.
  const sweep::TileEvaluator evaluator(config.grid, config.C, config.times, config.quantities);
  const sweep::TileEvaluator with_reference(config.grid, config.C, config.times, config.quantities,
                                            config.reference);
  const io::MapLayout layout = map_layout(config, tiling, with_reference);
  std::printf("punchsweep sweep --dry-run\n");
  for (std::size_t a = 0; a < sweep::kAxes; ++a) {
    const auto& axis = config.grid.axes[a];
    std::printf("  %-4s %4zu values  %-28s [%g .. %g]\n", sweep::kAxisNames[a], axis.values.size(),
                axis.text.c_str(), axis.values.front(), axis.values.back());
  }
  const auto& chunk = tiling.chunk();
  std::printf("  points: %zu in %zu tiles (chunk %zu x %zu x %zu x %zu x %zu)\n", points, tiling.tiles(),
              chunk[0], chunk[1], chunk[2], chunk[3], chunk[4]);
  std::printf("  quantities: %s", full ? "full" : "regime");
  if (full) std::printf(" (%zu snapshot times)", config.times.size());
  if (layout.bem) {
    std::printf("\n  reference: periodic BEM on a %d x %d grid at %lld of %zu points (sample %s, seed %lld)",
                layout.bem->grid, layout.bem->grid, static_cast<long long>(layout.bem->sample), points,
                config.reference.sample ? "random" : "all", static_cast<long long>(layout.bem->seed));
  }
  const double bytes = static_cast<double>(points) * static_cast<double>(io::uncompressed_bytes_per_point(layout));
  std::printf("\n  output: %s, %.3g MiB uncompressed (shuffle + deflate shrink it, typically 3-10x)\n",
              config.output.c_str(), bytes / (1024.0 * 1024.0));
  // Calibration: whole tiles (so the per-tile reuse is measured too), picked at random.
  std::mt19937_64 rng(12345);
  std::uniform_int_distribution<std::size_t> pick(0, tiling.tiles() - 1);
  io::TileData data;
  std::size_t sampled = 0;
  const auto start = std::chrono::steady_clock::now();
  double elapsed = 0.0;
  for (int i = 0; i < 64 && elapsed < 1.0; ++i) {
    const sweep::TileBox box = tiling.box(pick(rng));
    evaluator.evaluate(box, &data);
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
    const double per_bem = calibrate_reference(config, with_reference, &measured);
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

/// Rank 0's part of the run: files, journal replay, sink, finish. Returns the exit code.
int manage(const sweep::SweepConfig& config, const std::vector<std::string>& args, Start start,
           const sweep::Tiling& tiling, const sweep::TileEvaluator& evaluator, io::TileEncoder& encoder,
           int ranks) {
  const OutputPaths paths(config.output);
  io::MapAttributes attributes;
  attributes.title = "punchsweep regime map: two-level punch system on a viscoelastic half-space";
  attributes.source = std::string("punchsweep ") + kVersion + " (git " + kGitRevision + ")";
  attributes.history = utc_now() + " " + command_line(args);
  attributes.config_text = config.resolved_text;
  attributes.creep_law = config.creep_law;
  attributes.C = config.C;

  // The HDF5 file is always rebuilt: after kill -9 it may be damaged, the journal not.
  io::RegimeMapWriter writer(paths.partial, encoder.layout(), attributes);
  const std::size_t bem_points = encoder.layout().bem ? static_cast<std::size_t>(encoder.layout().bem->sample) : 0;
  Progress progress(std::cerr, config.grid.points(), bem_points, config.quiet);
  std::vector<bool> done(tiling.tiles(), false);
  std::optional<io::TileJournal> journal;
  if (start == Start::resume) {
    const std::size_t good_end = io::TileJournal::replay(paths.journal, [&](const io::EncodedTile& tile) {
      if (tile.tile >= done.size() || done[tile.tile]) return;
      writer.write_encoded(tiling.box(tile.tile), tile);
      done[tile.tile] = true;
      progress.restored(tile);
    });
    journal = io::TileJournal::open_for_append(paths.journal, good_end);
    if (!config.quiet) {
      std::fprintf(stderr, "punchsweep sweep: resuming %s: %zu of %zu points already done\n",
                   paths.final_path.c_str(), progress.points_done(), config.grid.points());
    }
  } else {
    journal = io::TileJournal::create(paths.journal, join(config.identity, "\n"));
  }
  std::vector<std::size_t> pending;
  for (std::size_t t = 0; t < tiling.tiles(); ++t) {
    if (!done[t]) pending.push_back(t);
  }

  auto last_flush = std::chrono::steady_clock::now();
  const sweep::TileSink sink = [&](const io::EncodedTile& tile) {
    journal->append(tile);
    writer.write_encoded(tiling.box(tile.tile), tile);
    progress.computed(tile);
    const auto now = std::chrono::steady_clock::now();
    if (now - last_flush > std::chrono::seconds(30)) {
      writer.flush();  // lets a user peek at the .partial file; the journal is what resume trusts
      last_flush = now;
    }
  };
  const sweep::ScheduleResult result =
      sweep::run_schedule(MPI_COMM_WORLD, tiling, evaluator, encoder, pending, sink, &g_stop_signal);

  if (result.interrupted) {
    writer.flush();
    std::string resume = command_line(args);
    if (!config.resume) resume += " --resume";
    std::fprintf(stderr,
                 "punchsweep sweep: stopped by signal %d with %zu of %zu points done; the finished tiles "
                 "are kept in %s.\n  Resume with: %s\n",
                 static_cast<int>(g_stop_signal), progress.points_done(), config.grid.points(),
                 paths.journal.c_str(), resume.c_str());
    return kInterruptedExitCode;
  }
  writer.finish(ranks, progress.seconds(), progress.rate());
  fs::rename(paths.partial, paths.final_path);
  fs::remove(paths.journal);
  progress.print_summary(ranks);
  if (!config.quiet) std::fprintf(stderr, "punchsweep sweep: map written to %s\n", paths.final_path.c_str());
  return 0;
}

}  // namespace

int run_sweep_command(const std::vector<std::string>& args) {
  MpiSession mpi;
  const bool root = mpi.rank() == 0;
  std::ostringstream discard;
  sweep::SweepConfig config;
  bool help = false;
  try {
    config = parse_sweep_options(args, root ? static_cast<std::ostream&>(std::cout) : discard, &help);
  } catch (const UsageError& e) {
    if (root) {
      for (const std::string& line : split_lines(e.what())) std::cerr << "punchsweep sweep: " << line << "\n";
    }
    return kUsageExitCode;
  }
  if (help) return 0;

  const sweep::Tiling tiling(config.grid.shape(), config.chunk);
  if (config.dry_run) {
    if (root) print_dry_run(config, tiling, mpi.size());
    return 0;
  }

  // Rank 0 checks the file system; every rank learns the verdict.
  Start start = Start::fresh;
  std::string refusal;
  if (root) refusal = preflight(config, OutputPaths(config.output), &start);
  int verdict[2] = {refusal.empty() ? 0 : 1, static_cast<int>(start)};
  MPI_Bcast(verdict, 2, MPI_INT, 0, MPI_COMM_WORLD);
  if (verdict[0] != 0) {
    if (root) {
      for (const std::string& line : split_lines(refusal)) std::cerr << "punchsweep sweep: " << line << "\n";
    }
    return kUsageExitCode;
  }
  start = static_cast<Start>(verdict[1]);
  if (start == Start::already_complete) {
    if (root && !config.quiet) {
      std::cerr << "punchsweep sweep: " << config.output << " is already complete; nothing to resume\n";
    }
    return 0;
  }

  for (const int signal : {SIGTERM, SIGUSR1, SIGINT}) std::signal(signal, on_stop_signal);
  int code = 0;
  try {
    const sweep::TileEvaluator evaluator(config.grid, config.C, config.times, config.quantities, config.reference);
    // Every rank encodes the tiles it computes into the map's chunks.
    io::TileEncoder encoder(map_layout(config, tiling, evaluator));
    if (root) {
      code = manage(config, args, start, tiling, evaluator, encoder, mpi.size());
    } else {
      sweep::run_schedule(MPI_COMM_WORLD, tiling, evaluator, encoder, {}, {}, &g_stop_signal);
    }
  } catch (const std::exception& e) {
    std::cerr << "punchsweep sweep: rank " << mpi.rank() << ": " << e.what() << "\n";
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  return code;
}

}  // namespace punchsweep::app
