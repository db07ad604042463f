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
  /// The samples, M intervals in v and Z in zeta (0: the engine's, small_spot_samples).
  struct Samples {
    int v_intervals = 0;     ///< M
    int zeta_intervals = 0;  ///< Z
  } samples{};
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

/// The engine's samples of s: 64 in v and 32 across the height difference (eta = 1 - zeta^s)
/// up to s = 6; 64 and 128 beyond, where eta's range from 0 to 1/2 spans a few samples of
/// zeta (two at s = 16 with 32), so the two levels' radii between them were up to 3e-4 of
/// a1 off the localization (with 128: 2e-5).
SmallSpotOptions::Samples small_spot_samples(int s);

/// The table of shape exponent s (1 <= s <= 32). Throws std::runtime_error where a state
/// has no root (naming it) and Stopped on a stop request.
SmallSpotTable build_small_spot_table(int s, const SmallSpotOptions& options = {});

}  // namespace punchsweep::model
