#pragma once
/// @file
/// Fills model::SmallSpotTable (small_spot_table.hpp) with the refined
/// localization's states, its far field made the lattice's exact one (docs/model.md,
/// section 14.7): the periodic solution where its spots are small.

#include <functional>
#include <utility>

#include "model/periodic/small_spot_table.hpp"
#include "model/numerics/stop_request.hpp"

namespace punchsweep::model {

/// The samples and the hand-over. The defaults are what the engine uses (their accuracy:
/// docs/model.md, section 14.7).
struct SmallSpotOptions {
  int v_intervals = 64;     ///< M
  int zeta_intervals = 32;  ///< Z
  /// The hand-over bands, by the single level's contact radius a1 / l (0: the engine's,
  /// hand_over_radii): the gap h, and the rest (radii, loads, the two levels).
  struct Bands {
    double gap_from = 0.0, gap_to = 0.0;
    double from = 0.0, to = 0.0;
  } bands{};
  /// The localization: the neighbours within this many distances (the refined model's).
  int shells = 200;
  StopRequest stop{};
  /// Called after every v sample with (samples done, samples planned).
  std::function<void(int, int)> progress;
};

/// The engine's hand-over bands of s, by a1 / l: where both tables meet the boundary
/// elements at N = 2048 (docs/model.md, section 14.7). The gap: from 0.08-0.14 (s = 1) to
/// 0.12-0.18 (s >= 3), where both give h within 5e-6 (the small-spot table's own error grows
/// beyond, as the refined localization's does where spots are large; the boundary elements'
/// below, where spots span few nodes). The rest: 0.22-0.28 for s = 1, 0.30-0.35 for s = 2,
/// 0.34-0.40 from s = 3, where both give the loads within 1e-4 of the load (s = 3: 7e-4) and
/// the radii within 1e-3 (the boundary elements' surface is least accurate at small height
/// differences, the more so the larger s; the small spots' where spots are large). Narrow:
/// in a band a point reads both tables.
SmallSpotOptions::Bands hand_over_radii(int s);

/// The table of shape exponent s (1 <= s <= 32). Throws std::runtime_error where a state
/// has no root (naming it) and Stopped on a stop request.
SmallSpotTable build_small_spot_table(int s, const SmallSpotOptions& options = {});

}  // namespace punchsweep::model
