#pragma once
/// @file
/// The few text operations the run's messages and identity lines need, shared with the
/// command line's config reading.

#include <sstream>
#include <string>
#include <vector>

namespace punchsweep::run {

/// `text` without leading and trailing whitespace.
inline std::string trim(const std::string& text) {
  constexpr const char* kWhitespace = " \t\r\n\f\v";
  const std::size_t first = text.find_first_not_of(kWhitespace);
  if (first == std::string::npos) return {};
  const std::size_t last = text.find_last_not_of(kWhitespace);
  return text.substr(first, last - first + 1);
}

/// The lines joined with `separator` between them.
inline std::string join(const std::vector<std::string>& lines, const char* separator) {
  std::string text;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (i > 0) text += separator;
    text += lines[i];
  }
  return text;
}

/// The lines of `text` (without their line breaks).
inline std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// `program` and its arguments as a shell would need them typed again (a resume hint is
/// copy-pasted): plain words as they are, others in single quotes.
inline std::string shell_command(const std::string& program, const std::vector<std::string>& args) {
  std::string text = program;
  for (const std::string& a : args) {
    const bool plain = !a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                         "0123456789_./,=:+-@%") == std::string::npos;
    if (plain) {
      text += " " + a;
      continue;
    }
    std::string quoted = "'";
    for (const char c : a) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    text += " " + quoted + "'";
  }
  return text;
}

}  // namespace punchsweep::run
