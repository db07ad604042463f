#pragma once
/// @file
/// The text of a material file (docs/materials.md, "Material files") as sections of
/// `key = value` lines, read key by key by the material (material.cpp) and by its law's
/// reader (material_laws.hpp). Every message names the file, the line, the section, the key
/// and the value. The keys a file may hold are the common [material] ones, those of every
/// law of material_laws(), and the [shift] ones; a key the law does not read is refused by
/// name (refuse_unread).

#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace punchsweep::model {

class MaterialFile {
 public:
  /// Splits `text` into sections and keys; throws MaterialError for a line that is no
  /// section header or `key = value`, an unknown section or key, or a key given twice.
  MaterialFile(std::string_view text, std::string origin);

  bool has_section(const std::string& section) const { return sections_.count(section) > 0; }
  bool has(const std::string& id) const { return values_.count(id) > 0; }
  /// The value of "section.key"; MaterialError when it is missing.
  const std::string& text(const std::string& id) const;
  /// One number; a comma-separated list of numbers.
  double number(const std::string& id) const;
  std::vector<double> list(const std::string& id) const;
  /// One number > 0; else "outside its range: RANGE".
  double positive(const std::string& id, const std::string& range) const;

  /// Refuses the first key given but never read by the law (or the shift) the file names,
  /// listing the keys that were: a stray `n = 0.3` in a Prony file is not silently dropped.
  void refuse_unread(const std::string& material_what, const std::string& shift_what) const;

  [[noreturn]] void fail(std::size_t line, const std::string& what) const;
  [[noreturn]] void fail_key(const std::string& id, const std::string& what) const;
  /// "FILE:LINE: [section] key = VALUE: what".
  [[noreturn]] void fail_value(const std::string& id, const std::string& what) const;

  /// Strictly increasing, positive times; every entry of `moduli` positive (`modulus_range`
  /// says so in messages); the same count.
  void check_terms(const std::string& moduli_key, const std::vector<double>& moduli, const std::string& times_key,
                   const std::vector<double>& times, const std::string& modulus_range) const;

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

}  // namespace punchsweep::model
