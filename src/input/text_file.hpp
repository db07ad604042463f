#pragma once

#include <cstddef>
#include <string>

namespace punchsweep::input {

/// The largest config or material file read (a Prony series of a thousand terms is 40 kB).
inline constexpr std::size_t kMaxTextFileBytes = std::size_t{1} << 20;

/// The text of an input file (`what` names it in messages: "config file", "material file"),
/// or UsageError naming the file and the problem: missing or unreadable, a folder, not a
/// regular file (a device such as /dev/zero or a pipe would be read without end), larger
/// than kMaxTextFileBytes, or binary (its first control byte, with its line, is named rather
/// than echoed back). A UTF-8 byte-order mark is dropped.
std::string read_text_file(const std::string& path, const std::string& what);

}  // namespace punchsweep::input
