#include "model/localization.hpp"

#include <charconv>
#include <stdexcept>

namespace punchsweep::model {

std::string Localization::spelling() const {
  if (periodic) return "periodic";
  if (is_paper()) return "paper";
  return std::string(distributed ? "shells:" : "point-shells:") + std::to_string(shells);
}

Localization parse_localization(std::string_view text) {
  const std::string valid = "valid: periodic (the whole cell's elastic solution, tabulated), paper (= point-shells:2), refined (= shells:" +
                            std::to_string(Localization::kRefinedShells) + "), shells:D (the neighbours within the D nearest "
                            "distances, spread over their spots) or point-shells:D (as point loads), 1 <= D <= " +
                            std::to_string(Localization::kMaxShells);
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
  throw std::invalid_argument("localization '" + std::string(text) + "' is not one; " + valid);
}

}  // namespace punchsweep::model
