#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace punchsweep::input {

/// Parses a whole string as a finite double; throws UsageError naming `option` otherwise.
double parse_real(const std::string& text, const std::string& option);

/// Parses a whole string as an integer (no fraction, no exponent); throws UsageError.
int parse_integer(const std::string& text, const std::string& option);

/// Parses a seed of a random generator: a whole number in [0, 2^64-1], in decimal digits
/// (no sign, fraction or exponent: "-1" would wrap round to 2^64-1); throws UsageError
/// naming `option` and the range otherwise.
std::uint64_t parse_seed(const std::string& text, const std::string& option);

/// Parses "0, 0.5, 1" (commas and/or spaces) into finite doubles; throws UsageError.
std::vector<double> parse_real_list(const std::string& text, const std::string& option);

}  // namespace punchsweep::input
