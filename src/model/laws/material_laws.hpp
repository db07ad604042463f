#pragma once
/// @file
/// The laws a material file may name (`law = NAME`), declared once: each with the
/// [material] keys it reads (their units and ranges as messages and docs/materials.md state
/// them), its reader, its builder and a valid example. material.cpp reads a file through
/// this registry; a key the law does not read is refused by name; the conformance test
/// (tests/model/creep_law_conformance_test.cpp) runs over every entry. Adding a file law is
/// its class and one entry in material_laws.cpp.

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "model/laws/creep_law.hpp"
#include "model/laws/material_keys.hpp"

namespace punchsweep::model {

/// A law's data in the model's units: moduli relative to E_0, times in the file's unit.
struct MaterialTerms {
  double E0 = 0.0;        ///< the instantaneous modulus E_0, in the file's modulus_unit
  double final = 0.0;     ///< prony: E_inf/E_0; kelvin: E_0/eta (0: no dashpot); power_law: n; sls: T
  std::vector<double> moduli, times;
};

/// One [material] key of a law, for the key check, messages and docs.
struct MaterialKey {
  std::string_view key;
  std::string_view meaning;  ///< with its unit and range: "E_0 > 0, in modulus_unit"
};

struct MaterialLaw {
  std::string_view name;         ///< law = NAME
  std::string_view description;  ///< one line: the law's function with its units
  std::span<const MaterialKey> keys;
  /// Reads and checks the law's keys of `file` (MaterialError naming the key otherwise).
  MaterialTerms (*read)(const MaterialKeys& file);
  /// The law from its terms (E_0 = 1: creep in 1/E_0, time in the file's unit).
  std::unique_ptr<CreepLaw> (*make)(const MaterialTerms& terms);
  /// Its terms in a few words, for Material::describe: "10 terms", "n = 0.3, t_1 = 2".
  std::string (*describe)(const MaterialTerms& terms);
  /// A valid set of its [material] keys, one `key = value` per line (tests, docs).
  std::string_view example;
};

/// Every law a material file may name, in the order docs/materials.md lists them; each law
/// of creep_laws() (a law of parameter values) has an entry of the same name, its form in
/// physical units (tested).
std::span<const MaterialLaw> material_laws();

/// The law called `name`, or nullptr.
const MaterialLaw* find_material_law(std::string_view name);

/// "prony, kelvin, power_law", for messages.
std::string material_law_names();

}  // namespace punchsweep::model
