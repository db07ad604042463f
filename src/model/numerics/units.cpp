#include "model/numerics/units.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "model/numerics/number_text.hpp"

namespace punchsweep::model {
namespace {

constexpr std::array<Unit, 4> kLength = {{{"m", 1.0}, {"mm", 1e-3}, {"um", 1e-6}, {"nm", 1e-9}}};
constexpr std::array<Unit, 4> kPressure = {{{"Pa", 1.0}, {"kPa", 1e3}, {"MPa", 1e6}, {"GPa", 1e9}}};
constexpr std::array<Unit, 4> kTime = {{{"s", 1.0}, {"ms", 1e-3}, {"min", 60.0}, {"h", 3600.0}}};

}  // namespace

std::span<const Unit> units_of(Dimension dimension) {
  switch (dimension) {
    case Dimension::length: return kLength;
    case Dimension::pressure: return kPressure;
    case Dimension::time: return kTime;
  }
  return {};
}

const Unit* find_unit(Dimension dimension, std::string_view name) {
  // Both micro signs: U+00B5 (the keyboard's) and U+03BC (Greek mu, as some software writes it).
  if (dimension == Dimension::length && (name == "\u00b5m" || name == "\u03bcm")) name = "um";
  for (const Unit& u : units_of(dimension)) {
    if (u.name == name) return &u;
  }
  return nullptr;
}

std::string unit_names(Dimension dimension) {
  const std::span<const Unit> all = units_of(dimension);
  std::string text;
  for (std::size_t k = 0; k < all.size(); ++k) {
    if (k > 0) text += k + 1 == all.size() ? " or " : ", ";
    text += all[k].name;
  }
  return text;
}

std::string_view dimension_name(Dimension dimension) {
  switch (dimension) {
    case Dimension::length: return "length";
    case Dimension::pressure: return "pressure";
    case Dimension::time: return "time";
  }
  return "";
}

std::optional<Physical> parse_physical(std::string_view text, Dimension dimension) {
  const std::string_view t = trim(text, " \t");
  double value = 0.0;
  const auto [end, error] = std::from_chars(t.data(), t.data() + t.size(), value);
  const std::string_view unit = trim(t.substr(static_cast<std::size_t>(end - t.data())), " \t");
  if (error != std::errc() || !std::isfinite(value)) {
    throw std::invalid_argument("'" + std::string(text) + "' is not a number, or a number and a " +
                                std::string(dimension_name(dimension)) + " unit (" + unit_names(dimension) + ")");
  }
  if (unit.empty()) return std::nullopt;
  const Unit* u = find_unit(dimension, unit);
  if (u == nullptr) {
    std::string what = "is not a " + std::string(dimension_name(dimension)) + " unit";
    for (const Dimension other : {Dimension::length, Dimension::pressure, Dimension::time}) {
      if (other != dimension && find_unit(other, unit) != nullptr) {
        what = "is a " + std::string(dimension_name(other)) + ", not a " + std::string(dimension_name(dimension));
      }
    }
    throw std::invalid_argument("'" + std::string(text) + "': '" + std::string(unit) + "' " + what +
                                "; valid: " + unit_names(dimension));
  }
  return Physical{value, u};
}

double in_units_of(const Physical& value, const Physical& scale) {
  // Both in the smaller of the two units, reached by multiplying by an integer (exact for
  // the usual numbers: 0.15 mm is 150 um, 0.05 mm is 50 um).
  if (value.unit->si >= scale.unit->si) return convert(value.number, *value.unit, *scale.unit) / scale.number;
  return value.number / convert(scale.number, *scale.unit, *value.unit);
}

double convert(double x, const Unit& from, const Unit& to) {
  if (from.si >= to.si) return x * std::round(from.si / to.si);
  return x / std::round(to.si / from.si);
}

}  // namespace punchsweep::model
