#include "run/resume_policy.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "run/text_lines.hpp"

namespace punchsweep::run {
namespace {

// "section.key = value" as (key, value), both trimmed; a line without '=' has no value.
std::pair<std::string, std::string> split_identity_line(const std::string& line) {
  const std::size_t equals = line.find('=');
  return {trim(line.substr(0, equals)), equals == std::string::npos ? std::string() : trim(line.substr(equals + 1))};
}

}  // namespace

std::optional<std::string> identity_value(const std::vector<std::string>& lines, const std::string& key) {
  for (const std::string& line : lines) {
    auto [k, value] = split_identity_line(line);
    if (k == key) return value;
  }
  return std::nullopt;
}

std::vector<std::string> identity_differences(const std::vector<std::string>& existing,
                                              const std::vector<std::string>& requested) {
  // Key order: as the existing map lists them, then keys only this run has.
  const auto split = [](const std::vector<std::string>& lines, std::vector<std::string>& order) {
    std::map<std::string, std::string> values;
    for (const std::string& line : lines) {
      const auto [key, value] = split_identity_line(line);
      if (values.emplace(key, value).second && std::find(order.begin(), order.end(), key) == order.end()) {
        order.push_back(key);
      }
    }
    return values;
  };
  std::vector<std::string> order;
  const std::map<std::string, std::string> old_values = split(existing, order);
  const std::map<std::string, std::string> new_values = split(requested, order);

  std::vector<std::string> differences;
  for (const std::string& key : order) {
    const auto old_it = old_values.find(key);
    const auto new_it = new_values.find(key);
    if (old_it == old_values.end()) {
      differences.push_back(key + ": the existing map does not record it; this run asks for " + new_it->second);
    } else if (new_it == new_values.end()) {
      differences.push_back(key + ": the existing map has " + old_it->second + "; this run does not set it");
    } else if (old_it->second != new_it->second) {
      differences.push_back(key + ": the existing map has " + old_it->second + "; this run asks for " +
                            new_it->second);
    }
  }
  return differences;
}

}  // namespace punchsweep::run
