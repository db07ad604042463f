#include "run/map_run.hpp"

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <unordered_set>

#include "io/encoded_tile.hpp"
#include "io/tile_encoder.hpp"
#include "run/text_lines.hpp"

namespace punchsweep::run {

MapRun::MapRun(const sweep::SweepConfig& config, const io::MapLayout& layout, const io::MapAttributes& attributes,
               Start start, const map::Tiling& tiling, std::ostream& log)
    : paths_(config.output),
      tiling_(tiling),
      writer_(paths_.partial, layout, attributes),
      progress_(log, config.grid.points(), layout.bem ? static_cast<std::size_t>(layout.bem->sample) : 0,
                config.quiet, config.progress_to_terminal ? Progress::Pace::terminal : Progress::Pace::log),
      last_flush_(std::chrono::steady_clock::now()) {
  // The tiles the journal holds: memory in proportion to the work done, not to the grid.
  std::unordered_set<std::uint64_t> done;
  if (start == Start::resume) {
    // Every record is checked before it is trusted: its tile must be one of the tiling's
    // and its chunks must decode to that tile's box (a record that passes its CRC but does
    // not would make the map unreadable); the first that fails ends the replay, and it and
    // what follows are computed again.
    const io::TileEncoder checker(layout);
    const std::size_t good_end = io::TileJournal::replay(paths_.journal, [&](const io::EncodedTile& tile) {
      if (tile.tile >= tiling.tiles() || !checker.decodes(tile, tiling.box(tile.tile))) return false;
      if (!done.insert(tile.tile).second) return true;
      writer_.write_encoded(tiling.box(tile.tile), tile);
      progress_.restored(tile);
      return true;
    });
    // A damaged record hides every later one (they cannot be framed): say how much is lost.
    const io::TileJournal::Tail tail = io::TileJournal::inspect_tail(paths_.journal, good_end);
    if (tail.bytes > 0) {
      log << "punchsweep sweep: the journal " << paths_.journal << " is damaged or torn after byte " << good_end
          << ": its last " << tail.bytes << " bytes (about " << tail.records << " tile record"
          << (tail.records == 1 ? "" : "s") << ") cannot be read; those tiles are computed again\n";
    }
    journal_ = io::TileJournal::open_for_append(paths_.journal, good_end);
    if (!config.quiet) {
      log << "punchsweep sweep: resuming " << paths_.final_path << ": " << progress_.points_done() << " of "
          << config.grid.points() << " points already done\n";
    }
  } else {
    journal_ = io::TileJournal::create(paths_.journal, join(config.identity, "\n"));
  }
  std::vector<std::uint64_t> sorted(done.begin(), done.end());
  std::sort(sorted.begin(), sorted.end());
  std::uint64_t next = 0;
  for (const std::uint64_t t : sorted) {
    pending_.add(next, t);
    next = t + 1;
  }
  pending_.add(next, tiling.tiles());
}

void MapRun::accept(std::span<const std::byte> bytes) {
  const io::EncodedTile tile = io::unpack_encoded_tile(bytes.data(), bytes.size());
  journal_->append_packed(bytes);
  writer_.write_encoded(tiling_.box(tile.tile), tile);
  progress_.computed(tile);
  const auto now = std::chrono::steady_clock::now();
  if (now - last_flush_ > std::chrono::seconds(30)) {
    writer_.flush();  // lets a user peek at the .partial file; the journal is what resume trusts
    last_flush_ = now;
  }
}

void MapRun::interrupt() { writer_.flush(); }

void MapRun::finish(int ranks) {
  writer_.finish(ranks, progress_.seconds(), progress_.rate());
  std::filesystem::rename(paths_.partial, paths_.final_path);
  journal_.reset();
  std::filesystem::remove(paths_.journal);
  progress_.print_summary(ranks);
}

namespace {

/// How the reference's points were picked, as the map names it.
std::string sample_rule(const sweep::ReferenceConfig& reference) {
  switch (reference.rule) {
    case sweep::ReferenceConfig::SampleRule::invalid: return "invalid";
    case sweep::ReferenceConfig::SampleRule::boundary: return "boundary";
    case sweep::ReferenceConfig::SampleRule::count: break;
  }
  return reference.sample ? "random" : "all";
}

}  // namespace

io::MapLayout map_layout(const sweep::SweepConfig& config, const map::Tiling& tiling,
                         const std::optional<std::uint64_t>& reference_points, double reference_tolerance) {
  io::MapLayout layout{config.grid, config.times, config.quantities, tiling.chunk(), std::nullopt, config.tolerance_text};
  if (reference_points) {
    layout.bem = io::BemSetup{config.reference.grid, reference_tolerance, static_cast<std::int64_t>(*reference_points),
                              static_cast<std::int64_t>(config.reference.seed),
                              "periodic BEM, FFT influence, Polonsky-Keer CG, viscoelastic creep stepping",
                              sample_rule(config.reference)};
  }
  return layout;
}

}  // namespace punchsweep::run
