#pragma once

#include <array>
#include <chrono>
#include <cstddef>
#include <iosfwd>

#include "io/encoded_tile.hpp"

namespace punchsweep::run {

/// Progress and end-of-run summary of a sweep, printed by rank 0 to a stream (stderr):
/// lines with points done / total, percent, points/s and ETA, and with a BEM reference the
/// reference points done / total. To a terminal at most one a second; to a log (a file, a
/// batch job's output) one each 5% of the points, and at least one every 10 minutes.
///
/// The ETA counts grid points, although a BEM point costs a thousand model points or more:
/// the reference sample is uniform over the grid, so the BEM work comes in proportion to
/// the points done, and the points' rate already includes it.
class Progress {
 public:
  /// `total_bem`: the number of reference points of the sweep (0 without a reference).
  enum class Pace { terminal, log };
  Progress(std::ostream& out, std::size_t total_points, std::size_t total_bem, bool quiet, Pace pace = Pace::terminal);

  /// Counts a tile restored from the journal (not computed by this run), from its summary.
  void restored(const io::EncodedTile& tile);
  /// Counts a tile computed by this run, from its summary, and prints a line when its pace
  /// says.
  void computed(const io::EncodedTile& tile);

  std::size_t points_done() const { return restored_points_ + computed_points_; }
  std::size_t points_computed() const { return computed_points_; }
  double seconds() const;
  /// Points computed per second of this run.
  double rate() const;
  /// Counts per regime (immediate, delayed, never), invalid points and per validity code,
  /// and with a reference its points per regime and their agreement with the model.
  void print_summary(int ranks) const;

 private:
  void count(const io::TileSummary& summary);

  std::ostream& out_;
  std::size_t total_;
  std::size_t total_bem_;
  bool quiet_;
  Pace pace_;
  std::size_t next_step_ = 0;  ///< Pace::log: the next 5% step (in twentieths) that prints
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
  std::size_t restored_points_ = 0;
  std::size_t computed_points_ = 0;
  std::array<std::size_t, 3> regimes_{};
  std::array<std::size_t, std::size(model::kValidities)> validity_{};
  std::array<std::size_t, 3> bem_regimes_{};
  std::size_t bem_agreeing_ = 0;
};

}  // namespace punchsweep::run
