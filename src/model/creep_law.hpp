#pragma once

#include <string>

namespace punchsweep::model {

/// A linear viscoelastic material given by its creep function J(t) and the matching
/// relaxation function E(t) (interconverted: int_0-^t E(t - tau) dJ(tau) = 1).
/// Time in T_eps, J in 1/E0*, E in E0* (see units.hpp). J must be non-decreasing.
class CreepLaw {
 public:
  virtual ~CreepLaw() = default;

  /// Creep function J(t) for t >= 0.
  virtual double creep(double t) const = 0;
  /// Relaxation function E(t) for t >= 0.
  virtual double relaxation(double t) const = 0;
  /// dE/dt at t >= 0 (the kernel of the load history integral).
  virtual double relaxation_rate(double t) const = 0;
  /// J(0): instantaneous compliance.
  virtual double creep_initial() const = 0;
  /// J(inf): long-term compliance; +infinity for unlimited creep.
  virtual double creep_final() const = 0;
  /// The t with J(t) = J for J in [J(0), J(inf)); the inverse creep function.
  virtual double time_at_creep(double J) const = 0;
  /// Shortest time over which E(t) changes appreciably (sets the history quadrature step).
  virtual double relaxation_time_scale() const = 0;
  /// Age beyond which dE/dt is below 1e-17 of its scale, so older history can be
  /// skipped; +infinity for a law with long memory.
  virtual double relaxation_memory() const = 0;
  /// Name and parameters, e.g. "standard linear solid, T = 2.5".
  virtual std::string describe() const = 0;
};

}  // namespace punchsweep::model
