#include "model/laws/creep_laws.hpp"

#include <array>
#include <stdexcept>
#include <string>

#include "model/laws/standard_linear_solid.hpp"

namespace punchsweep::model {
namespace {

std::span<const Parameter> sls_parameters() { return {&creep_ratio_parameter(), 1}; }

const std::array<CreepLawSpec, 1>& laws() {
  static const std::array<CreepLawSpec, 1> kLaws{{
      {"standard_linear_solid", "sls", "standard linear solid, J(t) = T - (T - 1) exp(-t) in 1/E0*, t in T_eps",
       sls_parameters(),
       [](std::span<const double> v) -> std::unique_ptr<CreepLaw> {
         return std::make_unique<StandardLinearSolid>(v[0]);
       }},
  }};
  return kLaws;
}

}  // namespace

std::span<const CreepLawSpec> creep_laws() { return laws(); }

const CreepLawSpec* find_creep_law(std::string_view name) {
  for (const CreepLawSpec& law : laws()) {
    if (name == law.name || (!law.alias.empty() && name == law.alias)) return &law;
  }
  return nullptr;
}

std::string creep_law_names() {
  std::string names;
  for (const CreepLawSpec& law : laws()) {
    names += (names.empty() ? "" : ", ") + std::string(law.name);
    if (!law.alias.empty()) names += " (alias " + std::string(law.alias) + ")";
  }
  return names;
}

std::unique_ptr<CreepLaw> make_creep_law(const CreepLawSpec& law, std::span<const double> values) {
  if (values.size() != law.parameters.size()) {
    throw std::invalid_argument(std::string(law.name) + " takes " + std::to_string(law.parameters.size()) +
                                " parameters, got " + std::to_string(values.size()));
  }
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (!law.parameters[k].admits(values[k])) throw std::invalid_argument(law.parameters[k].error(values[k]));
  }
  return law.make(values);
}

}  // namespace punchsweep::model
