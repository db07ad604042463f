#pragma once

#include <cstdint>
#include <string_view>

namespace punchsweep::model {

/// Why a result may not be trusted (docs/model.md, section 7). The integer codes are a file
/// format contract (the regime map stores them); never renumber.
enum class Validity : std::int8_t {
  valid = 0,
  same_level_overlap = 1,   ///< 2 a_i >= l: spots of one level merge
  cross_level_overlap = 2,  ///< a1 + a2 >= l/sqrt(2): a level-1 and a level-2 spot merge
  no_solution = 3,          ///< the equations have no root in the admissible range
  /// A computed value breaks an invariant the model guarantees: P1 + P2 = pbar0 l^2, every
  /// value finite, 0 <= a2 <= a1. The numbers are not to be trusted (a point beyond what the
  /// numerics resolve, e.g. l = 1e308 R).
  inaccurate = 4,
  /// The periodic model's tables do not reach the point's two-level states (dh / (C l^s)
  /// above their top, where the level-2 spot is a sliver; docs/model.md, section 14).
  outside_table = 5,
  /// The contact may recede somewhere along the point's loads (a node's elastic pressure
  /// falls as X grows, or a level's load turns negative): the correspondence the periodic
  /// model rests on needs a contact set that only grows; the time-stepping `reference`
  /// answers such points.
  unloading = 6,
};

/// Every code, in order (for the map's flag_values and the summaries).
inline constexpr Validity kValidities[] = {Validity::valid, Validity::same_level_overlap,
                                           Validity::cross_level_overlap, Validity::no_solution,
                                           Validity::inaccurate, Validity::outside_table,
                                           Validity::unloading};

/// Short machine-readable name ("valid", "same_level_overlap", ...).
std::string_view validity_name(Validity v);

}  // namespace punchsweep::model
