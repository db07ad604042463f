#pragma once
/// @file
/// A material as users bring it: a file `materials/NAME.ini` (docs/materials.md, "Material files";
/// docs/model.md, section 10) with a creep or relaxation law in physical units and an
/// optional time-temperature shift. Parsed here into the model's units: moduli in the
/// instantaneous modulus E_0 (so pressures in E0* = E_0/(1 - nu^2)), time in the file's
/// time unit. The file's text is kept, so a map can store it and `--resume` compare it.

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "model/laws/creep_law.hpp"
#include "model/laws/creep_laws.hpp"
#include "model/laws/material_keys.hpp"
#include "model/laws/material_laws.hpp"
#include "model/problem/parameter.hpp"
#include "model/laws/time_shift.hpp"

namespace punchsweep::model {

/// A material file that cannot be used: the message names the file, the section and key,
/// the value and the valid range.
class MaterialError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// temperature, the parameter a material with a [shift] takes (in degC; sweepable).
const Parameter& temperature_parameter();

/// material, the categorical parameter of a sweep over several material files: the index of
/// the material (its label is the file's name).
const Parameter& material_parameter();

class Material;
/// Several materials as one creep law for a sweep: parameters material (the index into
/// `materials`) and, when every material has a [shift], temperature. Throws
/// std::invalid_argument when the materials differ in time unit or in having a shift (a
/// map has one time axis and one set of axes).
CreepLawSpec material_choice(std::vector<std::shared_ptr<const Material>> materials);

class Material {
 public:
  /// The material of a file's entries (input::read_material_text reads them from its text,
  /// which `text` keeps verbatim for the map and --resume). Throws MaterialError (through
  /// `keys`, naming the file, line, key and value) for a missing or unknown key, an unknown
  /// law or unit, a modulus <= 0, sum g_i >= 1, unsorted or repeated times, lists of
  /// different lengths, or bad shift constants.
  static Material read(const MaterialKeys& keys, std::string text);

  /// "[material] name": the material and the published source of its numbers.
  const std::string& name() const { return name_; }
  /// The law's name, one of material_laws(): "prony", "kelvin", "power_law".
  const std::string& law() const { return law_; }
  /// The unit of time of every t, tau_i, t* ("s", "ms", "min" or "h"): UDUNITS reads each.
  const std::string& time_unit() const { return time_unit_; }
  /// The instantaneous Young's modulus E_0, in Pa.
  double instantaneous_modulus_Pa() const { return E0_Pa_; }
  double poisson() const { return nu_; }
  /// E0* = E_0/(1 - nu^2), in Pa: the unit of every pressure.
  double plane_strain_modulus_Pa() const { return E0_Pa_ / (1.0 - nu_ * nu_); }
  const std::optional<TemperatureShift>& shift() const { return shift_; }
  /// The file as read.
  const std::string& text() const { return text_; }

  /// The law's parameters: temperature when the file has a [shift], else none.
  std::span<const Parameter> parameters() const;
  /// The law at `values` (parameters() order): at the reference temperature without a shift,
  /// else shifted by a_T(temperature). Throws std::invalid_argument naming a temperature
  /// outside the shift's range.
  std::unique_ptr<CreepLaw> make(std::span<const double> values) const;
  /// The material as a creep law the sweep and the point commands take: name law(), the
  /// parameters() and make(). Refers to this material, which must outlive it.
  CreepLawSpec spec() const;
  /// One line: "NAME; prony, 10 terms, E_0 = 2.91e6 Pa, nu = 0.45, time in s[; WLF ...]".
  std::string describe() const;

 private:
  std::string name_, law_, time_unit_, text_;
  double E0_Pa_ = 0.0;
  double nu_ = 0.0;
  std::optional<TemperatureShift> shift_;
  /// temperature_parameter() with the point default T_ref; on the heap, so that views into
  /// it survive a move of the material.
  struct Temperature {
    std::string reference;
    Parameter parameter;
  };
  std::shared_ptr<const Temperature> temperature_;
  /// The file's law (material_laws.hpp) and its data in E_0 = 1.
  const MaterialLaw* file_law_ = nullptr;
  MaterialTerms terms_;
};

}  // namespace punchsweep::model
