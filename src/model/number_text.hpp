#pragma once

#include <sstream>
#include <string>

namespace punchsweep::model {

/// `v` as the model's messages print it: at most `digits` significant digits, in the
/// stream's shortest form ("53.4", "1e-05").
inline std::string number_text(double v, int digits) {
  std::ostringstream out;
  out.precision(digits);
  out << v;
  return out.str();
}

}  // namespace punchsweep::model
