#include "model/laws/material_keys.hpp"

#include "model/numerics/number_text.hpp"

namespace punchsweep::model {

double MaterialKeys::positive(const std::string& id, const std::string& range) const {
  const double value = number(id);
  if (!(value > 0.0)) fail_value(id, "outside its range: " + range);
  return value;
}

void MaterialKeys::check_terms(const std::string& moduli_key, const std::vector<double>& moduli,
                               const std::string& times_key, const std::vector<double>& times,
                               const std::string& modulus_range) const {
  if (moduli.size() != times.size()) {
    fail_value(times_key, std::to_string(times.size()) + " times for " + std::to_string(moduli.size()) +
                              " values of " + moduli_key.substr(moduli_key.find('.') + 1) +
                              "; valid: one time per term");
  }
  for (std::size_t i = 0; i < moduli.size(); ++i) {
    if (!(moduli[i] > 0.0)) {
      fail_value(moduli_key, "term " + std::to_string(i + 1) + " = " + number_text(moduli[i], 10) +
                                 " is outside its range: " + modulus_range);
    }
    if (!(times[i] > 0.0)) {
      fail_value(times_key, "term " + std::to_string(i + 1) + " = " + number_text(times[i], 10) +
                                " is outside its range: times > 0");
    }
    if (i > 0 && !(times[i] > times[i - 1])) {
      fail_value(times_key, "term " + std::to_string(i + 1) + " = " + number_text(times[i], 10) +
                                " does not exceed the one before it (" + number_text(times[i - 1], 10) +
                                "); valid: strictly increasing times (a repeated time is one term)");
    }
  }
}

}  // namespace punchsweep::model
