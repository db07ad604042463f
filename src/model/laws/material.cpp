#include "model/laws/material.hpp"

#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>

#include "model/laws/material_laws.hpp"
#include "model/numerics/number_text.hpp"
#include "model/numerics/units.hpp"

namespace punchsweep::model {
const Parameter& temperature_parameter() {
  static const Parameter kTemperature{"temperature",
                                      "degC",
                                      "temperature",
                                      "temperature, in degC (a material with a [shift] only)",
                                      "temperature > -273.15 (in degC) and in the material's shift range",
                                      [](double v) { return v > -kZeroCelsius; },
                                      false,
                                      {},
                                      "20",
                                      "the material's reference temperature (its [shift] T_ref)"};
  return kTemperature;
}

const Parameter& material_parameter() {
  static const Parameter kMaterial{"material",
                                   "1",
                                   "material",
                                   "the material, one of the sweep's material files",
                                   "one of the material files given",
                                   [](double v) { return v >= 0.0; },
                                   true,
                                   {},
                                   {}};
  return kMaterial;
}

CreepLawSpec material_choice(std::vector<std::shared_ptr<const Material>> materials) {
  if (materials.empty()) throw std::invalid_argument("material_choice: no materials");
  const Material& first = *materials.front();
  for (const auto& m : materials) {
    if (m->time_unit() != first.time_unit()) {
      throw std::invalid_argument("the materials' time units differ (" + first.time_unit() + " and " + m->time_unit() +
                                  "); valid: one time_unit for every material of a map");
    }
    if (m->shift().has_value() != first.shift().has_value()) {
      throw std::invalid_argument("some materials have a [shift] and some do not; valid: all or none (a map has one "
                                  "temperature axis or none)");
    }
  }
  struct Held {
    std::vector<std::shared_ptr<const Material>> materials;
    std::vector<Parameter> parameters;
  };
  auto held = std::make_shared<Held>();
  held->materials = std::move(materials);
  held->parameters.push_back(material_parameter());
  if (first.shift()) held->parameters.push_back(temperature_parameter());
  const std::span<const Parameter> parameters(held->parameters);
  return CreepLawSpec{"material", {}, "one of several material files", parameters,
                      [held](std::span<const double> values) {
                        const auto k = static_cast<std::size_t>(values[0]);
                        if (k >= held->materials.size()) {
                          throw std::invalid_argument("material index " + std::to_string(k) + " is outside its range");
                        }
                        return held->materials[k]->make(values.subspan(1));
                      }};
}

Material Material::read(const MaterialKeys& f, std::string text) {
  const std::string& origin = f.origin();
  Material m;
  m.text_ = std::move(text);
  if (!f.has_section("material")) throw MaterialError(origin + ": no [material] section");
  m.name_ = f.text("material.name");
  m.law_ = f.text("material.law");
  const Unit* modulus = find_unit(Dimension::pressure, f.text("material.modulus_unit"));
  if (!modulus) f.fail_value("material.modulus_unit", "unknown unit; valid: " + unit_names(Dimension::pressure));
  m.time_unit_ = f.text("material.time_unit");
  if (!find_unit(Dimension::time, m.time_unit_)) f.fail_value("material.time_unit", "unknown unit; valid: " + unit_names(Dimension::time));
  m.nu_ = f.number("material.poisson");
  if (!(m.nu_ > -1.0 && m.nu_ <= 0.5)) f.fail_value("material.poisson", "outside its range: -1 < poisson <= 0.5");

  m.file_law_ = find_material_law(m.law_);
  if (m.file_law_ == nullptr) f.fail_value("material.law", "unknown law; valid: " + material_law_names());
  m.terms_ = m.file_law_->read(f);
  m.E0_Pa_ = m.terms_.E0 * modulus->si;

  if (f.has_section("shift")) {
    TemperatureShift shift;
    const std::string kind = f.text("shift.kind");
    shift.T_ref = f.number("shift.T_ref");
    if (kind == "wlf") {
      if (f.has("shift.E_a")) f.fail_value("shift.E_a", "not a key of kind = wlf (it is kind = arrhenius's)");
      shift.kind = TemperatureShift::Kind::wlf;
      shift.C1 = f.number("shift.C1");
      shift.C2 = f.number("shift.C2");
      if (f.has("shift.E_a_below")) shift.E_a_below = f.number("shift.E_a_below");
    } else if (kind == "arrhenius") {
      for (const char* key : {"shift.C1", "shift.C2", "shift.E_a_below"}) {
        if (f.has(key)) f.fail_value(key, "not a key of kind = arrhenius (it is kind = wlf's)");
      }
      shift.kind = TemperatureShift::Kind::arrhenius;
      shift.E_a = f.number("shift.E_a");
    } else {
      f.fail_value("shift.kind", "unknown kind; valid: wlf, arrhenius");
    }
    if (f.has("shift.T_min")) shift.T_min = f.number("shift.T_min");
    if (f.has("shift.T_max")) shift.T_max = f.number("shift.T_max");
    if (std::string e = shift.error(); !e.empty()) throw MaterialError(origin + ": [shift] " + e);
    m.shift_ = shift;
    auto temperature = std::make_shared<Temperature>(Temperature{f.text("shift.T_ref"), temperature_parameter()});
    temperature->parameter.point_default = temperature->reference;
    temperature->parameter.sweep_default = temperature->reference;
    m.temperature_ = std::move(temperature);
  }
  f.refuse_unread("law = " + m.law_, m.shift_ ? "kind = " + f.text("shift.kind") : std::string("[shift]"));
  // Build once, so that what the law's own checks refuse is refused here, with the file named.
  try {
    m.make(m.shift_ ? std::vector<double>{m.shift_->T_ref} : std::vector<double>{});
  } catch (const std::invalid_argument& e) {
    throw MaterialError(origin + ": " + e.what());
  }
  return m;
}

std::span<const Parameter> Material::parameters() const {
  if (!shift_) return {};
  return {&temperature_->parameter, 1};
}

std::unique_ptr<CreepLaw> Material::make(std::span<const double> values) const {
  std::unique_ptr<CreepLaw> law = file_law_->make(terms_);
  if (!shift_) return law;
  const double th = values[0];
  if (!shift_->admits(th)) {
    throw std::invalid_argument("temperature = " + number_text(th, 10) + " is outside its range: " + shift_->range());
  }
  const double a_T = std::pow(10.0, shift_->log10_factor(th));
  return std::make_unique<TimeShiftedLaw>(std::move(law), a_T);
}

CreepLawSpec Material::spec() const {
  return CreepLawSpec{law_, {}, name_, parameters(), [this](std::span<const double> values) { return make(values); }};
}

std::string Material::describe() const {
  std::ostringstream out;
  out.precision(6);
  out << name_ << "; " << law_ << ", " << file_law_->describe(terms_);
  out << ", E_0 = " << E0_Pa_ << " Pa, nu = " << nu_
      << ", time in " << time_unit_;
  if (shift_) out << "; " << shift_->describe();
  return out.str();
}

}  // namespace punchsweep::model
