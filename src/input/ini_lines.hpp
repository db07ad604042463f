#pragma once
/// @file
/// A config file's lines by INI's rules as Boost.Program_options reads them: '#' starts a
/// comment anywhere, `[section]` headers, `key = value` lines, whitespace around names and
/// values dropped. The sweep's config (sweep_options) and a texture's map
/// (texture_sweep_options) read their files through it, so both name the file and the line
/// of every problem alike.

#include <functional>
#include <string>
#include <vector>

namespace punchsweep::input {

struct IniSetting {
  std::string section, name, value;
  int line = 0;
  std::string key() const { return section + "." + name; }  ///< "section.name"
};

struct IniScan {
  std::vector<IniSetting> settings;   ///< in file order, each key once
  std::vector<std::string> problems;  ///< "config file PATH, line N: ...", one a line
};

/// Scans `text`, the file at `path`. A header whose section `is_section` refuses, a line
/// that is neither a header nor `key = value`, a key before any section, a key that
/// `key_problem(section, name)` refuses (its sentence; "" accepts) and a key set twice are
/// problems; the settings are the rest.
IniScan scan_ini(const std::string& path, const std::string& text, const std::function<bool(const std::string&)>& is_section,
                 const std::string& sections, const std::function<std::string(const std::string&, const std::string&)>& key_problem);

}  // namespace punchsweep::input
