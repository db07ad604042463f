#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace punchsweep::input {

/// Parses a whole string as a finite double; throws UsageError naming `option` otherwise.
double parse_real(const std::string& text, const std::string& option);

/// Parses a whole string as an integer (no fraction, no exponent); throws UsageError.
int parse_integer(const std::string& text, const std::string& option);

/// A whole string of decimal digits as a number below 2^64 ("4096"); nothing for an empty
/// string, a sign, any other character, or a number that does not fit.
std::optional<std::uint64_t> decimal_uint64(std::string_view text);

/// Parses a seed of a random generator: a whole number in [0, 2^64-1], in decimal digits
/// (no sign, fraction or exponent: "-1" would wrap round to 2^64-1); throws UsageError
/// naming `option` and the range otherwise.
std::uint64_t parse_seed(const std::string& text, const std::string& option);

/// Parses "0, 0.5, 1" (commas and/or spaces) into finite doubles; throws UsageError.
std::vector<double> parse_real_list(const std::string& text, const std::string& option);

}  // namespace punchsweep::input
