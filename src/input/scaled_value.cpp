#include "input/scaled_value.hpp"

#include <cctype>
#include <stdexcept>

#include "input/usage_error.hpp"
#include "model/laws/material.hpp"

namespace punchsweep::input {

PhysicalScales scales_of(const model::Material* material, std::optional<model::Physical> R) {
  PhysicalScales scales;
  scales.R = R;
  if (material == nullptr) return scales;
  scales.E0_star = model::Physical{material->plane_strain_modulus_Pa(), model::find_unit(model::Dimension::pressure, "Pa")};
  if (const model::Unit* unit = model::find_unit(model::Dimension::time, material->time_unit())) {
    scales.time = model::Physical{1.0, unit};
  }
  return scales;
}

model::Physical read_length_scale(const std::string& text) {
  const std::string valid = "valid: a length > 0 with its unit (" + model::unit_names(model::Dimension::length) +
                            "), e.g. 50um";
  const std::optional<model::Physical> R = model::parse_physical(text, model::Dimension::length);
  if (!R) throw std::invalid_argument("'" + text + "' has no unit; " + valid);
  if (!(R->number > 0.0)) throw std::invalid_argument("'" + text + "' is not > 0; " + valid);
  return *R;
}

std::optional<Scale> scale_of(std::string_view scaled_unit, const PhysicalScales& scales) {
  if (scaled_unit == "R") {
    return Scale{model::Dimension::length, scaled_unit, scales.R,
                 "R, the punch's radius of curvature with its unit (--R 50um, model.R = 50um)"};
  }
  if (scaled_unit == "E0/(1-nu^2)") {
    return Scale{model::Dimension::pressure, scaled_unit, scales.E0_star, "a material (its E0* in Pa)"};
  }
  if (scaled_unit == "T_eps") {
    return Scale{model::Dimension::time, scaled_unit, scales.time,
                 "a material (its time_unit; without one, times are in T_eps)"};
  }
  return std::nullopt;
}

std::optional<PhysicalUnit> physical_unit(std::string_view scaled_unit, const PhysicalScales& scales) {
  if (scaled_unit == "R" && scales.R) return PhysicalUnit{scales.R->number, std::string(scales.R->unit->name)};
  if (scaled_unit == "E0/(1-nu^2)" && scales.E0_star) return PhysicalUnit{scales.E0_star->si(), "Pa"};
  if (scaled_unit == "R^2 E0/(1-nu^2)" && scales.R && scales.E0_star) {
    return PhysicalUnit{scales.R->si() * scales.R->si() * scales.E0_star->si(), "N"};
  }
  if (scaled_unit == "T_eps" && scales.time) return PhysicalUnit{scales.time->number, std::string(scales.time->unit->name)};
  return std::nullopt;
}

PhysicalUnit physical_unit_or_scaled(std::string_view scaled_unit, const PhysicalScales& scales) {
  return physical_unit(scaled_unit, scales).value_or(PhysicalUnit{1.0, std::string(scaled_unit)});
}

double read_scaled(const std::string& text, const Scale& scale) {
  const std::optional<model::Physical> physical = model::parse_physical(text, scale.dimension);
  if (!physical) return input::parse_axis_number(text);
  if (!scale.value) {
    throw std::invalid_argument("'" + text + "': a " + std::string(model::dimension_name(scale.dimension)) +
                                " with a unit needs " + std::string(scale.needs) + "; or give it in " +
                                std::string(scale.scaled_unit));
  }
  return model::in_units_of(*physical, *scale.value);
}

double read_length(const std::string& text, const PhysicalScales& scales, const std::string& what) {
  try {
    return read_scaled(text, *scale_of("R", scales));
  } catch (const std::invalid_argument& e) {
    throw UsageError(what + " = " + e.what());
  }
}

bool has_unit(const std::string& text) {
  for (const char c : text) {
    if (std::isalpha(static_cast<unsigned char>(c)) && c != 'e' && c != 'E') return true;
  }
  return false;
}

map::Axis read_scaled_axis(const std::string& text, bool integers, const Scale& scale, bool required) {
  int with = 0;
  int without = 0;
  map::Axis axis = input::parse_axis(text, integers, [&](const std::string& token) {
    const double value = read_scaled(token, scale);
    if (has_unit(token)) {
      ++with;
    } else if (value != 0.0) {  // 0 is 0 in every unit
      ++without;
    }
    if (required && !has_unit(token)) {
      throw std::invalid_argument("'" + token + "' has no unit; valid: a number and a " +
                                  std::string(model::dimension_name(scale.dimension)) + " unit (" +
                                  model::unit_names(scale.dimension) + ")");
    }
    return value;
  });
  if (with > 0 && without > 0) {
    throw std::invalid_argument("it mixes values with and without a unit; give every value with a unit, or "
                                "every value in " + std::string(scale.scaled_unit));
  }
  return axis;
}

}  // namespace punchsweep::input
