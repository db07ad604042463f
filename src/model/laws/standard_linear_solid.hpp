#pragma once

#include "model/laws/creep_law.hpp"

namespace punchsweep::model {

/// Standard linear solid (eq 9.11, docs/model.md, section 4):
///   J(t) = T - (T - 1) exp(-t),   E(t) = 1/T + (1 - 1/T) exp(-T t),
/// with T = T_eps / T_sigma >= 1 (T = 1 is an elastic material).
class StandardLinearSolid final : public CreepLaw {
 public:
  /// Smallest admissible creep ratio.
  static constexpr double kMinCreepRatio = 1.0;

  /// @param creep_ratio T = T_eps / T_sigma; must be finite and >= 1 (creep_ratio_parameter).
  explicit StandardLinearSolid(double creep_ratio);

  double creep(double t) const override;
  double creep_rate(double t) const override;
  double creep_integral(double u, double d) const override;
  double relaxation(double t) const override;
  double relaxation_rate(double t) const override;
  double creep_initial() const override { return 1.0; }
  double creep_final() const override { return T_; }
  double time_at_creep(double J) const override;
  double relaxation_time_scale() const override { return 1.0 / T_; }
  /// The one retardation time, T_eps (the unit of time).
  double creep_time_scale() const override { return 1.0; }
  /// J(t) = T - (T - 1) exp(-t): one term, J_1 = T - 1, lambda_1 = 1 (T_eps).
  std::optional<RetardationSeries> retardation_series() const override;
  /// dE/dt is negligible after kForgetting relaxation times T_sigma = 1/T.
  double relaxation_memory() const override { return kForgetting / T_; }
  std::string describe() const override;

  double creep_ratio() const { return T_; }

 private:
  double T_;
};

struct Parameter;
/// T, the standard linear solid's one parameter (model/problem/parameter.hpp).
const Parameter& creep_ratio_parameter();

}  // namespace punchsweep::model
