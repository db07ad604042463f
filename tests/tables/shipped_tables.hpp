#pragma once
// The tables tests' model reads the shipped periodic tables, as `punchsweep` and the Python
// module do (without a cache, which would keep what another test built).
#include <optional>

#include "engine/periodic_tables.hpp"
#include "model/periodic/periodic_solution.hpp"

namespace punchsweep::test {

inline void use_shipped_tables() {
  model::set_periodic_solution_source([](int s) { return engine::periodic_solution_for(s, std::nullopt); });
}

}  // namespace punchsweep::test
