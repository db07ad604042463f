#pragma once
// The tables tests' model reads the shipped periodic tables, as `punchsweep` and the Python
// module do (without a cache, which would keep what another test built); and the paper's
// lattice as a periodic problem.
#include <optional>

#include "engine/periodic_tables.hpp"
#include "model/periodic/periodic_solution.hpp"
#include "model/problem/contact_problem.hpp"

namespace punchsweep::test {

inline void use_shipped_tables() {
  model::set_periodic_solution_source([](int s) { return engine::periodic_solution_for(s, std::nullopt); });
}

/// The paper's two-level square lattice of pitch l, drop dh and Hertz-like caps of exponent
/// s (C = 1/2), under the periodic model: the problem the tables tests hold answers to.
inline model::ContactProblem periodic_lattice(double l, double dh, int s) {
  model::ContactProblem p;
  p.l = l;
  p.dh = dh;
  p.shape = model::Shape{s, 0.5};
  p.localization = model::Localization{.periodic = true};
  return p;
}

}  // namespace punchsweep::test
