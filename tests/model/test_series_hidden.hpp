#pragma once
/// @file
/// A test helper the tests of several layers share: a creep law with its exponential series
/// hidden, so that whatever would use them (the BEM stepper's recursion, the load history's
/// term-by-term form, the settled panel) takes its general route instead.

#include <string>

#include "model/laws/creep_law.hpp"

namespace punchsweep::model::testing {

/// `law` without its relaxation and retardation series.
class SeriesHidden final : public CreepLaw {
 public:
  explicit SeriesHidden(const CreepLaw& law) : law_(law) {}
  double creep(double t) const override { return law_.creep(t); }
  double creep_rate(double t) const override { return law_.creep_rate(t); }
  double creep_integral(double u, double d) const override { return law_.creep_integral(u, d); }
  double relaxation(double t) const override { return law_.relaxation(t); }
  double relaxation_rate(double t) const override { return law_.relaxation_rate(t); }
  double creep_initial() const override { return law_.creep_initial(); }
  double creep_final() const override { return law_.creep_final(); }
  double time_at_creep(double J) const override { return law_.time_at_creep(J); }
  double relaxation_time_scale() const override { return law_.relaxation_time_scale(); }
  double creep_time_scale() const override { return law_.creep_time_scale(); }
  double relaxation_memory() const override { return law_.relaxation_memory(); }
  std::string describe() const override { return law_.describe() + " (series hidden)"; }

 private:
  const CreepLaw& law_;
};

}  // namespace punchsweep::model::testing
