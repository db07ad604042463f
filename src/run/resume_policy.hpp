#pragma once

#include <optional>
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

/// The value of `key` ("section.key") in identity lines; empty if no line has it.
std::optional<std::string> identity_value(const std::vector<std::string>& lines, const std::string& key);

}  // namespace punchsweep::run
