#include "input/value_parsing.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "input/usage_error.hpp"

namespace punchsweep::input {

double parse_real(const std::string& text, const std::string& option) {
  // Blanks around the number are no part of it (strtod skips leading ones only).
  const std::size_t first = text.find_first_not_of(" \t"), last = text.find_last_not_of(" \t");
  const std::string number = first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
  const char* begin = number.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  // The whole text: a NUL inside it (possible from Python, not from a shell) is no end. A
  // number too small for a normal double (1e-320) is still that number (ERANGE with a
  // result of magnitude below DBL_MIN); one too large is not finite.
  const bool underflow = errno == ERANGE && std::abs(value) < std::numeric_limits<double>::min();
  if (number.empty() || end != begin + number.size() || (errno == ERANGE && !underflow) || !std::isfinite(value)) {
    throw UsageError(option + " = '" + text + "' is not a finite number");
  }
  return value;
}

int parse_integer(const std::string& text, const std::string& option) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(begin, &end, 10);
  if (!text.empty() && end == begin + text.size() && errno == 0 && value >= std::numeric_limits<int>::min() &&
      value <= std::numeric_limits<int>::max()) {
    return static_cast<int>(value);
  }
  // A whole number written as a real ("2.0", "2e0": a map's s is float64, and Python's
  // repr of 2.0) is that integer.
  errno = 0;
  const double real = std::strtod(begin, &end);
  if (!text.empty() && end == begin + text.size() && errno == 0 && real == std::floor(real) &&
      real >= std::numeric_limits<int>::min() && real <= std::numeric_limits<int>::max()) {
    return static_cast<int>(real);
  }
  throw UsageError(option + " = '" + text + "' is not an integer");
}

std::optional<std::uint64_t> decimal_uint64(std::string_view text) {
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  // (from_chars takes neither a sign nor blanks for an unsigned type: digits alone.)
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

std::uint64_t parse_seed(const std::string& text, const std::string& option) {
  if (const std::optional<std::uint64_t> value = decimal_uint64(text)) return *value;
  throw UsageError(option + " = '" + text + "' is outside its range: an integer in [0, 2^64-1 = " +
                   std::to_string(std::numeric_limits<std::uint64_t>::max()) + "]");
}

std::vector<double> parse_real_list(const std::string& text, const std::string& option) {
  std::vector<double> values;
  std::string item;
  bool comma_pending = false;  // a comma that still needs a number after it
  auto flush = [&] {
    if (!item.empty()) values.push_back(parse_real(item, option));
    if (!item.empty()) comma_pending = false;
    item.clear();
  };
  for (const char c : text) {
    if (c == ',') {
      flush();
      if (comma_pending || values.empty()) {
        throw UsageError(option + " = '" + text + "' has an empty item (two commas in a row, or a comma at an end)");
      }
      comma_pending = true;
    } else if (c == ' ' || c == '\t') {
      flush();
    } else {
      item.push_back(c);
    }
  }
  flush();
  if (comma_pending) {
    throw UsageError(option + " = '" + text + "' has an empty item (two commas in a row, or a comma at an end)");
  }
  if (values.empty()) throw UsageError(option + " = '" + text + "' holds no number");
  return values;
}

}  // namespace punchsweep::input
