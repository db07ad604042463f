#pragma once

#include "model/creep_law.hpp"

namespace punchsweep::model {

/// Standard linear solid (eq 9.11, model notes section 4):
///   J(t) = T - (T - 1) exp(-t),   E(t) = 1/T + (1 - 1/T) exp(-T t),
/// with T = T_eps / T_sigma >= 1 (T = 1 is an elastic material).
class StandardLinearSolid final : public CreepLaw {
 public:
  /// Smallest admissible creep ratio.
  static constexpr double kMinCreepRatio = 1.0;

  /// @param creep_ratio T = T_eps / T_sigma; must be finite and >= 1 (see creep_ratio_error).
  explicit StandardLinearSolid(double creep_ratio);

  double creep(double t) const override;
  double relaxation(double t) const override;
  double relaxation_rate(double t) const override;
  double creep_initial() const override { return 1.0; }
  double creep_final() const override { return T_; }
  double time_at_creep(double J) const override;
  double relaxation_time_scale() const override { return 1.0 / T_; }
  /// exp(-40) < 1e-17: dE/dt is negligible after 40 relaxation times T_sigma = 1/T.
  double relaxation_memory() const override { return 40.0 / T_; }
  std::string describe() const override;

  double creep_ratio() const { return T_; }

 private:
  double T_;
};

/// Empty when T is admissible, else a sentence naming T and its range.
std::string creep_ratio_error(double creep_ratio);

}  // namespace punchsweep::model
