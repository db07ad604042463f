#include "input/material_file.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "model/laws/material.hpp"
#include "model/laws/material_laws.hpp"
#include "model/numerics/number_text.hpp"

namespace punchsweep::input {
namespace {

/// The [material] keys of every file, whatever its law.
constexpr std::string_view kCommonKeys[] = {"name", "law", "modulus_unit", "time_unit", "poisson"};
/// The [shift] keys (TemperatureShift's).
constexpr std::string_view kShiftKeys[] = {"kind", "C1", "C2", "T_ref", "E_a", "E_a_below", "T_min", "T_max"};

/// The keys section `section` may hold: the common ones, then each law's in registry order.
std::vector<std::string_view> section_keys(const std::string& section) {
  std::vector<std::string_view> keys;
  const auto add = [&](std::string_view key) {
    for (const std::string_view k : keys) {
      if (k == key) return;
    }
    keys.push_back(key);
  };
  if (section == "shift") {
    for (const std::string_view k : kShiftKeys) add(k);
    return keys;
  }
  for (const std::string_view k : kCommonKeys) add(k);
  for (const model::MaterialLaw& law : model::material_laws()) {
    for (const model::MaterialKey& k : law.keys) add(k.key);
  }
  return keys;
}

std::string joined(const std::vector<std::string_view>& keys) {
  std::string out;
  for (const std::string_view k : keys) out += (out.empty() ? "" : ", ") + std::string(k);
  return out;
}

}  // namespace

MaterialFile::MaterialFile(std::string_view text, std::string origin) : origin_(std::move(origin)) {
  std::string section;
  std::size_t line_number = 0;
  std::size_t start = 0;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") start = 3;  // a UTF-8 byte-order mark
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    ++line_number;
    std::string line(text.substr(start, end - start));
    start = end + 1;
    if (const auto hash = line.find_first_of("#;"); hash != std::string::npos) line.erase(hash);
    line = std::string(model::trim(line));
    if (line.empty()) continue;
    if (line.front() == '[') {
      if (line.back() != ']') fail(line_number, "'" + line + "' is not a section header; valid: [material] or [shift]");
      section = std::string(model::trim(std::string_view(line).substr(1, line.size() - 2)));
      if (section != "material" && section != "shift") {
        fail(line_number, "unknown section [" + section + "]; valid: [material] and an optional [shift]");
      }
      if (!sections_.insert(section).second) fail(line_number, "section [" + section + "] appears twice");
      continue;
    }
    const auto eq = line.find('=');
    if (eq == std::string::npos) fail(line_number, "'" + line + "' is not 'key = value'");
    if (section.empty()) fail(line_number, "'" + line + "' comes before any section; valid: [material] first");
    const std::string key(model::trim(std::string_view(line).substr(0, eq)));
    const std::string value(model::trim(std::string_view(line).substr(eq + 1)));
    const std::vector<std::string_view> valid = section_keys(section);
    bool known = false;
    for (const std::string_view k : valid) known = known || k == key;
    if (!known) fail(line_number, "[" + section + "] has no key '" + key + "'; valid: " + joined(valid));
    const std::string id = section + "." + key;
    if (values_.count(id)) fail(line_number, "[" + section + "] " + key + " is given twice");
    if (value.empty()) fail(line_number, "[" + section + "] " + key + " has no value");
    values_[id] = {value, line_number};
  }
}

const std::string& MaterialFile::text(const std::string& id) const {
  const auto it = values_.find(id);
  if (it == values_.end()) fail_key(id, "is missing");
  read_.insert(id);
  return it->second.value;
}

void MaterialFile::refuse_unread(const std::string& material_what, const std::string& shift_what) const {
  for (const auto& [id, entry] : values_) {
    if (read_.count(id)) continue;
    const std::string section = id.substr(0, id.find('.'));
    const std::string& what = section == "material" ? material_what : shift_what;
    std::string used;
    for (const std::string& r : read_) {
      if (r.substr(0, r.find('.')) != section) continue;
      used += (used.empty() ? "" : ", ") + r.substr(r.find('.') + 1);
    }
    fail_value(id, "not a key of " + what + " (the keys it reads here: " + used + ")");
  }
}

double MaterialFile::number(const std::string& id) const {
  const std::vector<double> v = parse_numbers(id);
  if (v.size() != 1) fail_value(id, "must be one number");
  return v.front();
}

std::vector<double> MaterialFile::list(const std::string& id) const { return parse_numbers(id); }

void MaterialFile::fail(std::size_t line, const std::string& what) const {
  throw model::MaterialError(origin_ + ":" + std::to_string(line) + ": " + what);
}

void MaterialFile::fail_key(const std::string& id, const std::string& what) const {
  const auto dot = id.find('.');
  throw model::MaterialError(origin_ + ": [" + id.substr(0, dot) + "] " + id.substr(dot + 1) + " " + what);
}

void MaterialFile::fail_value(const std::string& id, const std::string& what) const {
  const auto dot = id.find('.');
  const Entry& e = values_.at(id);
  throw model::MaterialError(origin_ + ":" + std::to_string(e.line) + ": [" + id.substr(0, dot) + "] " + id.substr(dot + 1) +
                      " = " + e.value + ": " + what);
}

std::vector<double> MaterialFile::parse_numbers(const std::string& id) const {
  const std::string& value = text(id);
  std::vector<double> out;
  std::string item;
  std::istringstream in(value);
  while (std::getline(in, item, ',')) {
    item = std::string(model::trim(item));
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size()) fail_value(id, "'" + item + "' is not a number");
    if (!std::isfinite(v)) fail_value(id, "'" + item + "' is not finite");
    out.push_back(v);
  }
  return out;
}

}  // namespace punchsweep::input

namespace punchsweep::input {

model::Material read_material_text(std::string_view text, const std::string& origin) {
  return model::Material::read(MaterialFile(text, origin), std::string(text));
}

}  // namespace punchsweep::input
