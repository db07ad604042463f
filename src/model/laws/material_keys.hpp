#pragma once
/// @file
/// A material file's entries as the material and its law read them: identifiers (name, law,
/// units, shift kind) and numbers, by "section.key". The file's text is read into them by
/// src/input (input/material_file.hpp), which also names the file, the line and the value
/// in every message; the model reads no text.

#include <string>
#include <vector>

namespace punchsweep::model {

class MaterialKeys {
 public:
  virtual ~MaterialKeys() = default;

  /// The file's name, which starts every message.
  virtual const std::string& origin() const = 0;
  virtual bool has_section(const std::string& section) const = 0;
  virtual bool has(const std::string& id) const = 0;
  /// The identifier at "section.key" (a name, a law, a unit); MaterialError when missing.
  virtual const std::string& text(const std::string& id) const = 0;
  /// One number; a comma-separated list of numbers (MaterialError naming the value else).
  virtual double number(const std::string& id) const = 0;
  virtual std::vector<double> list(const std::string& id) const = 0;

  /// Refuses the first key given but never read by the law (or the shift) the file names,
  /// listing the keys that were: a stray `n = 0.3` in a Prony file is not silently dropped.
  virtual void refuse_unread(const std::string& material_what, const std::string& shift_what) const = 0;

  [[noreturn]] virtual void fail_key(const std::string& id, const std::string& what) const = 0;
  /// "FILE:LINE: [section] key = VALUE: what".
  [[noreturn]] virtual void fail_value(const std::string& id, const std::string& what) const = 0;

  /// One number > 0; else "outside its range: RANGE".
  double positive(const std::string& id, const std::string& range) const;
  /// Strictly increasing, positive times; every entry of `moduli` positive (`modulus_range`
  /// says so in messages); the same count.
  void check_terms(const std::string& moduli_key, const std::vector<double>& moduli, const std::string& times_key,
                   const std::vector<double>& times, const std::string& modulus_range) const;

 protected:
  MaterialKeys() = default;
  MaterialKeys(const MaterialKeys&) = default;
  MaterialKeys& operator=(const MaterialKeys&) = default;
};

}  // namespace punchsweep::model
