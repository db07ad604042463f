#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "map/grid.hpp"

namespace punchsweep::input {

/// Largest count linspace()/logspace() accept: an axis lives in memory and is printed in
/// the map's identity, and a count beyond this is almost surely a typo.
inline constexpr long kMaxAxisCount = 1'000'000;

/// Parses the text of one grid axis (also used for the snapshot times). Accepted forms,
/// with any whitespace around items and arguments (function names are case-sensitive):
///   - a list `0.5, 0.75, 1` (commas and/or whitespace between the values), or one value;
///   - `linspace(a, b, n)`: n values evenly spaced from a to b, both included;
///   - `logspace(a, b, n)`: n values geometrically spaced from the VALUES a to b (not
///     exponents), both included; needs a, b > 0; sets Axis::log_spaced.
/// n is an integer in [1, kMaxAxisCount]; n = 1 needs a == b and gives [a], so that a stop
/// value is never silently ignored. The endpoints are exactly a and b. Interior values are
/// rounded to 15 significant digits (a relative change below 5e-16), so that
/// linspace(0.5, 1.25, 16) holds the same doubles as the list 0.5, 0.55, ..., 1.25.
/// The values must be finite and strictly increasing; with `integers` (the s axis) each
/// must be a whole number. -0 is stored as 0. Axis::text is the trimmed input.
/// Throws std::invalid_argument with a message that does not name the key, e.g.
/// "linspace needs 3 arguments (start, stop, count), got 2".
map::Axis parse_axis(const std::string& text, bool integers);

/// Reads one value of an axis (a list item, or linspace's or logspace's start or stop) from
/// its text, e.g. a number with a unit into the axis's scaled unit; throws
/// std::invalid_argument with a message that does not name the key.
using ValueReader = std::function<double(const std::string& token)>;

/// The same with each value read by `read`. In a list, a word that starts with a letter
/// belongs to the number before it, so "1 um, 2 um" reads as "1 um" and "2 um".
map::Axis parse_axis(const std::string& text, bool integers, const ValueReader& read);

/// The default reader: a whole string as a finite double ("'x' is not a number").
double parse_axis_number(const std::string& token);

/// The shortest decimal text that reads back to exactly `value` ("0.1", not
/// "0.10000000000000001"); used wherever a value is printed for comparison.
std::string format_axis_value(double value);

/// The values as "v1, v2, ..." with format_axis_value: the canonical text of an axis.
std::string format_axis_values(const std::vector<double>& values);

}  // namespace punchsweep::input
