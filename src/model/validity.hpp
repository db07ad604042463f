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
};

/// Short machine-readable name ("valid", "same_level_overlap", ...).
std::string_view validity_name(Validity v);

}  // namespace punchsweep::model
