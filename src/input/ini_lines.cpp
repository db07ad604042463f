#include "input/ini_lines.hpp"

#include <map>
#include <sstream>

#include "run/text_lines.hpp"

namespace punchsweep::input {

IniScan scan_ini(const std::string& path, const std::string& text, const std::function<bool(const std::string&)>& is_section,
                 const std::string& sections, const std::function<std::string(const std::string&, const std::string&)>& key_problem) {
  IniScan out;
  std::map<std::string, int> first_line;
  std::string section;
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (const std::size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    line = run::trim(line);
    if (line.empty()) continue;
    const std::string where = "config file " + path + ", line " + std::to_string(number) + ": ";
    if (line.front() == '[' && line.back() == ']') {
      section = line.substr(1, line.size() - 2);
      if (!is_section(section)) out.problems.push_back(where + "unknown section [" + section + "] (" + sections + ")");
      continue;
    }
    const std::size_t equals = line.find('=');
    if (equals == std::string::npos) {
      out.problems.push_back(where + "expected '[section]' or 'key = value', got '" + line + "'");
      continue;
    }
    const std::string name = run::trim(line.substr(0, equals));
    if (section.empty()) {
      out.problems.push_back(where + "key '" + name + "' comes before any [section]");
      continue;
    }
    if (!is_section(section)) continue;  // its section is already reported
    const std::string key = section + "." + name;
    if (const std::string problem = key_problem(section, name); !problem.empty()) {
      out.problems.push_back(where + problem);
    } else if (const auto [it, inserted] = first_line.emplace(key, number); !inserted) {
      out.problems.push_back(where + key + " is set again (first on line " + std::to_string(it->second) + ")");
    } else {
      out.settings.push_back({section, name, run::trim(line.substr(equals + 1)), number});
    }
  }
  return out;
}

}  // namespace punchsweep::input
