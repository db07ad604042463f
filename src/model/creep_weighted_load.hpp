#pragma once

#include "model/creep_law.hpp"

namespace punchsweep::model {

/// The creep-weighted load X(t) = int_0-^t J(t - tau) dpbar(tau) (docs/model.md, section
/// 10), through which time enters every phase of the model: the single-level radius and h,
/// the touchdown time t*, the two-level state, the pressure and the load history all depend
/// on t only through X(t) (extended correspondence principle, valid while contact does not
/// recede). It is written X(t) = pbar0 g(t) with g the response to the unit-shaped load
/// pbar(t)/pbar0; for today's step load pbar(t) = pbar0 (t > 0), g = J.
/// Units: X in E0*, g in 1/E0*, t in T_eps. Holds a reference to the law.
class CreepWeightedLoad {
 public:
  /// A step of nominal pressure pbar0 (> 0) at t = 0 on a material of creep function J.
  CreepWeightedLoad(const CreepLaw& creep, double pbar0) : creep_(creep), pbar0_(pbar0) {}

  /// The final nominal pressure pbar0, in E0*.
  double pbar0() const { return pbar0_; }
  /// The material.
  const CreepLaw& creep() const { return creep_; }

  /// g(t) = X(t)/pbar0, the response to the unit-shaped load.
  double response(double t) const { return creep_.creep(t); }
  /// g(0+).
  double response_initial() const { return creep_.creep_initial(); }
  /// g(inf); +infinity for unlimited creep.
  double response_final() const { return creep_.creep_final(); }
  /// The t > 0 with g(t) = g for g in (g(0+), g(inf)); non-decreasing g makes it a root.
  double time_at_response(double g) const { return creep_.time_at_creep(g); }

  /// X(t), in E0*.
  double operator()(double t) const { return pbar0_ * response(t); }
  /// X(0+): what the load gives at once.
  double initial() const { return pbar0_ * response_initial(); }
  /// X(inf); +infinity for unlimited creep.
  double final() const { return pbar0_ * response_final(); }

  /// The nominal pressure pbar(t) at t > 0, in E0*. A step: pbar0.
  double nominal_pressure(double /*t*/) const { return pbar0_; }

 private:
  const CreepLaw& creep_;
  double pbar0_;
};

}  // namespace punchsweep::model
