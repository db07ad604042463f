#include "model/laws/standard_linear_solid.hpp"

#include "model/problem/parameter.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace punchsweep::model {

const Parameter& creep_ratio_parameter() {
  static const Parameter kCreepRatio{
      "T",
      "1",
      "creep ratio T_eps/T_sigma",
      "creep ratio T = T_eps/T_sigma of the standard linear solid (dimensionless; J(inf) = T/E0*; T = 1 is "
      "elastic)",
      "T >= 1 (T = T_eps/T_sigma)",
      [](double T) { return T >= StandardLinearSolid::kMinCreepRatio; },
      false,
      {},
      "linspace(2, 10, 9)"};
  return kCreepRatio;
}

StandardLinearSolid::StandardLinearSolid(double creep_ratio) : T_(creep_ratio) {}

double StandardLinearSolid::creep(double t) const { return T_ - (T_ - 1.0) * std::exp(-t); }

double StandardLinearSolid::creep_rate(double t) const { return (T_ - 1.0) * std::exp(-t); }

double StandardLinearSolid::creep_integral(double u, double d) const {
  // T d - (T - 1) (e^-u - e^-(u+d)), the difference written with expm1.
  return T_ * d + (T_ - 1.0) * std::exp(-u) * std::expm1(-d);
}

double StandardLinearSolid::relaxation(double t) const {
  return 1.0 / T_ + (1.0 - 1.0 / T_) * std::exp(-T_ * t);
}

double StandardLinearSolid::relaxation_rate(double t) const {
  return -(T_ - 1.0) * std::exp(-T_ * t);
}

double StandardLinearSolid::time_at_creep(double J) const {
  if (J <= 1.0) return 0.0;
  if (J >= T_) return std::numeric_limits<double>::infinity();
  // J = T - (T-1) e^{-t}  =>  t = -log((T - J)/(T - 1)); log1p keeps digits for J near 1.
  return -std::log1p((1.0 - J) / (T_ - 1.0));
}

std::optional<RetardationSeries> StandardLinearSolid::retardation_series() const {
  return RetardationSeries{T_, {{T_ - 1.0, 1.0}}};
}

std::string StandardLinearSolid::describe() const {
  std::ostringstream out;
  out.precision(17);
  out << "standard linear solid, T = " << T_;
  return out.str();
}

}  // namespace punchsweep::model
