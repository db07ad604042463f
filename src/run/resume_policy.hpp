#pragma once

#include <string>
#include <vector>

namespace punchsweep::run {

/// One sentence per key whose identity line differs between an existing map and this
/// run, e.g. "grid.T: the existing map has 2, 5, 10; this run asks for 2, 5". Empty when
/// the two describe the same map. Lines are "section.key = value", as in
/// sweep::SweepConfig::identity; keys are listed in the existing map's order, then those
/// only this run has.
std::vector<std::string> identity_differences(const std::vector<std::string>& existing,
                                              const std::vector<std::string>& requested);

}  // namespace punchsweep::run
