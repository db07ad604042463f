#pragma once
/// @file
/// The text of a material file (docs/materials.md, "Material files") read into the entries
/// the model's material and law registry ask for (model/laws/material_keys.hpp): sections of
/// `key = value` lines, numbers parsed here, and every message naming the file, the line,
/// the section, the key and the value. The keys a file may hold are the common [material]
/// ones, those of every law of model::material_laws(), and the [shift] ones.

#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "model/laws/material.hpp"
#include "model/laws/material_keys.hpp"

namespace punchsweep::input {

class MaterialFile final : public model::MaterialKeys {
 public:
  /// Splits `text` into sections and keys; throws MaterialError for a line that is no
  /// section header or `key = value`, an unknown section or key, or a key given twice.
  MaterialFile(std::string_view text, std::string origin);

  const std::string& origin() const override { return origin_; }
  bool has_section(const std::string& section) const override { return sections_.count(section) > 0; }
  bool has(const std::string& id) const override { return values_.count(id) > 0; }
  /// The value of "section.key"; MaterialError when it is missing.
  const std::string& text(const std::string& id) const override;
  /// One number; a comma-separated list of numbers.
  double number(const std::string& id) const override;
  std::vector<double> list(const std::string& id) const override;

  /// Refuses the first key given but never read by the law (or the shift) the file names,
  /// listing the keys that were: a stray `n = 0.3` in a Prony file is not silently dropped.
  void refuse_unread(const std::string& material_what, const std::string& shift_what) const override;

  [[noreturn]] void fail(std::size_t line, const std::string& what) const;
  [[noreturn]] void fail_key(const std::string& id, const std::string& what) const override;
  /// "FILE:LINE: [section] key = VALUE: what".
  [[noreturn]] void fail_value(const std::string& id, const std::string& what) const override;


 private:
  struct Entry {
    std::string value;
    std::size_t line = 0;
  };
  std::vector<double> parse_numbers(const std::string& id) const;

  std::string origin_;
  std::set<std::string> sections_;
  std::map<std::string, Entry> values_;
  mutable std::set<std::string> read_;  ///< the keys asked for
};

/// The material of a file's text; `origin` (the file name) starts every message. Throws
/// model::MaterialError naming the file, line, key, value and valid range.
model::Material read_material_text(std::string_view text, const std::string& origin);

}  // namespace punchsweep::input
