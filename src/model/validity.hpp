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
};

/// Every code, in order (for the map's flag_values and the summaries).
inline constexpr Validity kValidities[] = {Validity::valid, Validity::same_level_overlap,
                                           Validity::cross_level_overlap, Validity::no_solution,
                                           Validity::inaccurate};

/// Short machine-readable name ("valid", "same_level_overlap", ...).
std::string_view validity_name(Validity v);

}  // namespace punchsweep::model
