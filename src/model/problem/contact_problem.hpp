#pragma once

#include <string>
#include <string_view>

#include "model/problem/load_shape.hpp"
#include "model/problem/localization.hpp"
#include "model/problem/shape.hpp"

namespace punchsweep::model {

/// One parameter point of the two-level punch system, without the material
/// (units: units.hpp). The creep law is passed beside it.
struct ContactProblem {
  double l = 0.75;      ///< lattice pitch, in R; l > 0
  double dh = 0.05;     ///< height difference of the two levels, in R; dh >= 0
  double pbar0 = 0.06;  ///< nominal pressure (held after the rise), in E0*; pbar0 > 0
  Shape shape{};
  LoadShape loading{};  ///< pbar(t) = pbar0 phi(t); the step by default
  /// Which localization model stands in for the lattice (docs/model.md, section 11); the
  /// paper's by default. The periodic reference (BEM) has no use for it.
  Localization localization{};
};

/// Empty when every field is in range, else one sentence naming the first bad field,
/// its value and its valid range.
std::string problem_error(const ContactProblem& problem);

/// The real-valued field of `problem` that parameter `name` sets (l, dh, pbar, C), or
/// nullptr (s, an integer, and names that are not the problem's).
double* problem_field(ContactProblem& problem, std::string_view name);

}  // namespace punchsweep::model
