#include "model/problem/localization.hpp"

#include <charconv>
#include <stdexcept>

namespace punchsweep::model {

std::string Localization::spelling() const {
  if (periodic) return "periodic";
  if (is_paper()) return "paper";
  return std::string(distributed ? "shells:" : "point-shells:") + std::to_string(shells);
}

std::string localization_spellings() {
  return "periodic (the whole periodic cell's elastic solution, tabulated from the boundary elements and read at "
         "the creep-weighted load: exact where the contact only grows, merged spots included), paper (the paper's "
         "eqs 9.5-9.19, = point-shells:2), refined (= shells:" +
         std::to_string(Localization::kRefinedShells) +
         ", the localization closest to the periodic solution), shells:D (the punches of both levels within the D "
         "nearest distances, spread over their own spots) or point-shells:D (as point loads), 1 <= D <= " +
         std::to_string(Localization::kMaxShells);
}

Localization parse_localization(std::string_view text) {
  if (text == "paper") return {};
  if (text == "periodic") {
    Localization periodic;
    periodic.periodic = true;
    return periodic;
  }
  if (text == "refined") return Localization{Localization::kRefinedShells, true};
  for (const auto& [prefix, distributed] : {std::pair{std::string_view("shells:"), true},
                                            std::pair{std::string_view("point-shells:"), false}}) {
    if (text.substr(0, prefix.size()) != prefix) continue;
    const std::string_view number = text.substr(prefix.size());
    int D = 0;
    const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), D);
    if (error != std::errc() || end != number.data() + number.size() || D < 1 || D > Localization::kMaxShells) {
      break;
    }
    return Localization{D, distributed};
  }
  throw std::invalid_argument("localization '" + std::string(text) + "' is not one; valid: " +
                              localization_spellings());
}

std::string Localization::exponent_error(int s) const {
  if (!periodic || s <= kMaxPeriodicExponent) return {};
  return "s = " + std::to_string(s) + " is outside the periodic model's range: an integer in [1, " +
         std::to_string(kMaxPeriodicExponent) +
         "] (beyond, its tables' caps are too flat for their grid); --localization refined or paper answers s up to 32, "
         "and `punchsweep surface --curve cell` the cell's own boundary elements";
}

}  // namespace punchsweep::model
