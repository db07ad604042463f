#pragma once

#include <stdexcept>
#include <string>

namespace punchsweep::input {

/// Bad command-line input. main() prints what() as one line and exits with kUsageExitCode.
class UsageError : public std::runtime_error {
 public:
  explicit UsageError(const std::string& message) : std::runtime_error(message) {}
};

inline constexpr int kUsageExitCode = 2;

}  // namespace punchsweep::input
