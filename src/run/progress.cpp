#include "run/progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

namespace punchsweep::run {
namespace {

std::string duration(double seconds) {
  char buf[64];
  if (!std::isfinite(seconds)) return "?";
  if (seconds < 90) std::snprintf(buf, sizeof buf, "%.0f s", seconds);
  else if (seconds < 5400) std::snprintf(buf, sizeof buf, "%.0f min %02.0f s", std::floor(seconds / 60), std::fmod(seconds, 60));
  else std::snprintf(buf, sizeof buf, "%.0f h %02.0f min", std::floor(seconds / 3600), std::fmod(seconds / 60, 60));
  return buf;
}

std::size_t sum(const std::array<std::size_t, 3>& counts) { return counts[0] + counts[1] + counts[2]; }

}  // namespace

Progress::Progress(std::ostream& out, std::size_t total_points, std::size_t total_bem, bool quiet, Pace pace)
    : out_(out), total_(total_points), total_bem_(total_bem), quiet_(quiet), pace_(pace),
      start_(std::chrono::steady_clock::now()), last_print_(start_) {}

void Progress::count(const io::TileSummary& summary) {
  for (std::size_t r = 0; r < regimes_.size(); ++r) regimes_[r] += summary.regimes[r];
  for (std::size_t v = 0; v < validity_.size(); ++v) validity_[v] += summary.validity[v];
  for (std::size_t r = 0; r < bem_regimes_.size(); ++r) bem_regimes_[r] += summary.bem_regimes[r];
  bem_agreeing_ += summary.bem_agreeing;
}

void Progress::restored(const io::EncodedTile& tile) {
  count(tile.summary);
  restored_points_ += tile.summary.points;
}

void Progress::computed(const io::EncodedTile& tile) {
  count(tile.summary);
  computed_points_ += tile.summary.points;
  if (quiet_) return;
  const auto now = std::chrono::steady_clock::now();
  if (pace_ == Pace::terminal) {
    if (now - last_print_ < std::chrono::seconds(1)) return;
  } else {
    // The twentieths of the points done: a line as each is passed (one line for several
    // passed at once, as a resumed run's first tiles pass them), else every 10 minutes.
    const std::size_t step = total_ > 0 ? 20 * points_done() / total_ : 20;
    const bool passed = step >= next_step_ && next_step_ <= 20;
    if (!passed && now - last_print_ < std::chrono::minutes(10)) return;
    if (passed) next_step_ = step + 1;
  }
  last_print_ = now;
  const double done = static_cast<double>(points_done());
  const double left = static_cast<double>(total_) - done;
  char bem[64] = "";
  if (total_bem_ > 0) std::snprintf(bem, sizeof bem, ", bem %zu / %zu", sum(bem_regimes_), total_bem_);
  char line[256];
  std::snprintf(line, sizeof line, "punchsweep sweep: %zu / %zu points (%.1f%%)%s, %.3g points/s, ETA %s\n",
                points_done(), total_, 100.0 * done / static_cast<double>(total_), bem, rate(),
                duration(left / rate()).c_str());
  out_ << line << std::flush;
}

double Progress::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

double Progress::rate() const { return static_cast<double>(computed_points_) / std::max(seconds(), 1e-9); }

void Progress::print_summary(int ranks) const {
  if (quiet_) return;
  std::size_t invalid = 0;
  std::string kinds;
  for (std::size_t v = 1; v < validity_.size(); ++v) {
    invalid += validity_[v];
    if (v > 1) kinds += ", ";
    kinds += std::string(model::validity_name(model::kValidities[v])) + " " + std::to_string(validity_[v]);
  }
  char line[600];
  std::snprintf(line, sizeof line,
                "punchsweep sweep: %zu points (%zu computed now in %s, %.3g points/s on %d rank%s)\n"
                "  regimes: immediate %zu, delayed %zu, never %zu\n"
                "  invalid: %zu (%s)\n",
                points_done(), computed_points_, duration(seconds()).c_str(), rate(), ranks,
                ranks == 1 ? "" : "s", regimes_[0], regimes_[1], regimes_[2], invalid, kinds.c_str());
  out_ << line;
  if (total_bem_ > 0) {
    const std::size_t bem = sum(bem_regimes_);
    std::snprintf(line, sizeof line,
                  "  bem: %zu points (immediate %zu, delayed %zu, never %zu; regime agreement with the model "
                  "%.1f%%)\n",
                  bem, bem_regimes_[0], bem_regimes_[1], bem_regimes_[2],
                  100.0 * static_cast<double>(bem_agreeing_) / static_cast<double>(std::max<std::size_t>(bem, 1)));
    out_ << line;
  }
  out_ << std::flush;
}

}  // namespace punchsweep::run
