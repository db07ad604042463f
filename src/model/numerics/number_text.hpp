#pragma once

#include <sstream>
#include <string>
#include <string_view>

namespace punchsweep::model {

/// `v` as the model's messages print it: at most `digits` significant digits, in the
/// stream's shortest form ("53.4", "1e-05").
inline std::string number_text(double v, int digits) {
  std::ostringstream out;
  out.precision(digits);
  out << v;
  return out.str();
}

/// `s` without the `blanks` at either end (empty when it is all blanks): what the model's
/// readers of text (material files, values with units) strip around a key or a value.
inline std::string_view trim(std::string_view s, std::string_view blanks = " \t\r") {
  const auto b = s.find_first_not_of(blanks);
  if (b == std::string_view::npos) return {};
  return s.substr(b, s.find_last_not_of(blanks) - b + 1);
}

}  // namespace punchsweep::model
