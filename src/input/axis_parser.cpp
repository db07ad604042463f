#include "input/axis_parser.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cctype>
#include <cstdlib>
#include <stdexcept>

namespace punchsweep::input {
namespace {

constexpr const char* kWhitespace = " \t\r\n\f\v";

std::string trim(const std::string& text) {
  const std::size_t first = text.find_first_not_of(kWhitespace);
  if (first == std::string::npos) return {};
  const std::size_t last = text.find_last_not_of(kWhitespace);
  return text.substr(first, last - first + 1);
}

}  // namespace

double parse_axis_number(const std::string& token) {
  const char* begin = token.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  if (token.empty() || end == begin || *end != '\0') {
    throw std::invalid_argument("'" + token + "' is not a number");
  }
  // ERANGE also flags underflow, which would turn e.g. 1e-400 silently into 0.
  if (errno == ERANGE) throw std::invalid_argument("'" + token + "' is out of the range of a double");
  if (!std::isfinite(value)) throw std::invalid_argument("'" + token + "' is not a finite number");
  return value;
}

namespace {

long parse_count(const std::string& function, const std::string& token) {
  const char* begin = token.c_str();
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(begin, &end, 10);
  if (token.empty() || end == begin || *end != '\0' || errno == ERANGE || value < 1 ||
      value > kMaxAxisCount) {
    throw std::invalid_argument(function + " count must be an integer in [1, " +
                                std::to_string(kMaxAxisCount) + "], got '" + token + "'");
  }
  return value;
}

// Splits at every comma; an empty piece is an error unless the whole text is empty.
std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> pieces;
  std::size_t from = 0;
  while (true) {
    const std::size_t comma = text.find(',', from);
    pieces.push_back(trim(text.substr(from, comma == std::string::npos ? std::string::npos : comma - from)));
    if (comma == std::string::npos) break;
    from = comma + 1;
  }
  return pieces;
}

std::vector<double> parse_list(const std::string& text, const ValueReader& read) {
  std::vector<double> values;
  for (const std::string& piece : split_commas(text)) {
    if (piece.empty()) {
      throw std::invalid_argument("the list has an empty entry (two commas in a row, or a comma at an end)");
    }
    std::vector<std::string> tokens;
    std::size_t from = 0;
    while (from < piece.size()) {
      const std::size_t end = std::min(piece.find_first_of(kWhitespace, from), piece.size());
      std::string token = piece.substr(from, end - from);
      // A unit written apart ("2 um") belongs to its number.
      if (!tokens.empty() && std::isalpha(static_cast<unsigned char>(token.front()))) {
        tokens.back() += " " + token;
      } else {
        tokens.push_back(std::move(token));
      }
      from = piece.find_first_not_of(kWhitespace, end);
      if (from == std::string::npos) break;
    }
    for (const std::string& token : tokens) values.push_back(read(token));
  }
  return values;
}

// Rounding to 15 significant digits removes the last-bit noise of the interpolation, so a
// generated value equals the double nearest to its short decimal (0.55, not 0.55000000000000004).
double snap(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.15g", value);
  const double snapped = std::strtod(buf, nullptr);
  return std::isfinite(snapped) ? snapped : value;
}

// Shared by linspace and logspace: n points at fractions i/(n-1), exact endpoints.
template <class Interpolate>
std::vector<double> generate(const std::string& function, double a, double b, long n, Interpolate at) {
  if (n == 1) {
    if (a != b) {
      throw std::invalid_argument(function +
                                  " with count 1 needs start == stop (it gives the single value start), got " +
                                  format_axis_value(a) + " and " + format_axis_value(b));
    }
    return {a};
  }
  if (!(a < b)) {
    throw std::invalid_argument(function + " values must increase: start " + format_axis_value(a) +
                                " is not below stop " + format_axis_value(b));
  }
  std::vector<double> values(static_cast<std::size_t>(n));
  const double last = static_cast<double>(n - 1);
  for (long i = 1; i + 1 < n; ++i) values[static_cast<std::size_t>(i)] = snap(at(static_cast<double>(i) / last));
  values.front() = a;
  values.back() = b;
  return values;
}

std::vector<double> parse_function(const std::string& name, const std::string& inside, const ValueReader& read) {
  std::vector<std::string> args;
  if (!trim(inside).empty()) args = split_commas(inside);
  if (args.size() != 3) {
    throw std::invalid_argument(name + " needs 3 arguments (start, stop, count), got " + std::to_string(args.size()));
  }
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i].empty()) throw std::invalid_argument(name + " argument " + std::to_string(i + 1) + " is empty");
  }
  const double a = read(args[0]);
  const double b = read(args[1]);
  const long n = parse_count(name, args[2]);
  if (name == "linspace") {
    return generate(name, a, b, n, [a, b](double t) { return std::lerp(a, b, t); });
  }
  if (!(a > 0.0 && b > 0.0)) {
    throw std::invalid_argument("logspace needs start and stop > 0 (they are the values, not exponents), got " +
                                format_axis_value(a) + " and " + format_axis_value(b));
  }
  const double log_a = std::log(a);
  const double log_b = std::log(b);
  return generate(name, a, b, n, [log_a, log_b](double t) { return std::exp(std::lerp(log_a, log_b, t)); });
}

}  // namespace

map::Axis parse_axis(const std::string& text, bool integers) { return parse_axis(text, integers, parse_axis_number); }

map::Axis parse_axis(const std::string& text, bool integers, const ValueReader& read) {
  map::Axis axis;
  axis.text = trim(text);
  if (axis.text.empty()) throw std::invalid_argument("no value given");

  const std::size_t open = axis.text.find('(');
  if (open == std::string::npos) {
    axis.values = parse_list(axis.text, read);
  } else {
    const std::string name = trim(axis.text.substr(0, open));
    if (name != "linspace" && name != "logspace") {
      throw std::invalid_argument("unknown function '" + name +
                                  "' (use a list, linspace(start, stop, count) or logspace(start, stop, count))");
    }
    if (axis.text.back() != ')') throw std::invalid_argument(name + "( is missing its closing ')'");
    axis.values = parse_function(name, axis.text.substr(open + 1, axis.text.size() - open - 2), read);
    axis.log_spaced = name == "logspace";
  }

  for (std::size_t i = 0; i < axis.values.size(); ++i) {
    if (axis.values[i] == 0.0) axis.values[i] = 0.0;  // -0 is 0: a coordinate must not print as -0
    const double v = axis.values[i];
    if (!std::isfinite(v)) throw std::invalid_argument("value " + format_axis_value(v) + " is not finite");
    if (integers && v != std::floor(v)) throw std::invalid_argument(format_axis_value(v) + " is not an integer");
    if (i > 0 && !(v > axis.values[i - 1])) {
      throw std::invalid_argument("values must be strictly increasing (" + format_axis_value(v) + " follows " +
                                  format_axis_value(axis.values[i - 1]) + ")");
    }
  }
  return axis;
}

std::string format_axis_value(double value) {
  char buf[32];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, value);
    if (std::strtod(buf, nullptr) == value) break;
  }
  return buf;
}

std::string format_axis_values(const std::vector<double>& values) {
  std::string text;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) text += ", ";
    text += format_axis_value(values[i]);
  }
  return text;
}

}  // namespace punchsweep::input
