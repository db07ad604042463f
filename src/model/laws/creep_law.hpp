#pragma once

#include <optional>
#include <string>
#include <vector>

namespace punchsweep::model {

/// A creep function written as a generalized Kelvin (retardation) series,
///   J(t) = J(inf) - sum_k J_k exp(-t / lambda_k),   J(0) = J(inf) - sum_k J_k,
/// which lets a time stepper carry one recursive history variable per term instead of the
/// whole history (the BEM reference does so).
struct RetardationSeries {
  struct Term {
    double J = 0.0;       ///< J_k, in 1/E0*
    double lambda = 0.0;  ///< retardation time lambda_k, in T_eps
  };
  double J_final = 0.0;     ///< J(inf), finite, in 1/E0*
  std::vector<Term> terms;  ///< at least one
};

/// An exponential term exp(-t/tau) is forgotten from t = kForgetting tau on: exp(-40) < 1e-17
/// of its weight (a law's relaxation memory, the time a load settles), and 1 - exp(-40) is
/// 1 in double precision (exp(-40) < 2^-54).
inline constexpr double kForgetting = 40.0;
/// From t = kNegligibleDecay tau on a term is left out of E and E' altogether (exp(-50) <
/// 2e-22): history integrals evaluate them at every age, and libm's exp is slowest where it
/// underflows.
inline constexpr double kNegligibleDecay = 50.0;

/// A relaxation function written as a generalized Maxwell (Prony) series,
///   E(t) = E(inf) + sum_k E_k exp(-t / tau_k),
/// which lets a load-history integral treat each term by itself: a term that relaxes
/// within a stretch of smooth history is a Gauss-Laguerre sum at t (LoadHistory).
struct RelaxationSeries {
  struct Term {
    double E = 0.0;    ///< E_k, in E0*
    double tau = 0.0;  ///< relaxation time tau_k, in T_eps
  };
  double E_final = 0.0;     ///< E(inf), in E0* (0 with a dashpot)
  std::vector<Term> terms;  ///< at least one, tau ascending
};

/// A linear viscoelastic material given by its creep function J(t) and the matching
/// relaxation function E(t) (interconverted: int_0-^t E(t - tau) dJ(tau) = 1).
/// Time in T_eps, J in 1/E0*, E in E0* (see units.hpp). J must be non-decreasing.
class CreepLaw {
 public:
  virtual ~CreepLaw() = default;

  /// Creep function J(t) for t >= 0.
  virtual double creep(double t) const = 0;
  /// dJ/dt at t >= 0 (the rate of the creep-weighted load under a jump).
  virtual double creep_rate(double t) const = 0;
  /// int_u^(u+d) J(v) dv for u >= 0, d >= 0, without cancellation when d is small against
  /// u (the creep-weighted load of a ramp, docs/model.md, section 10).
  virtual double creep_integral(double u, double d) const = 0;
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
  /// Shortest time over which J(t) changes appreciably (the shortest retardation time;
  /// bounds the quadrature pieces of history integrals together with the relaxation scale).
  virtual double creep_time_scale() const = 0;
  /// The law as a retardation series when it is one (finite J(inf), exponential terms);
  /// empty otherwise, and then history integrals use the law's J(t) directly.
  virtual std::optional<RetardationSeries> retardation_series() const { return std::nullopt; }
  /// The law as a relaxation series when its load histories are to be integrated term by
  /// term; empty otherwise, and then they integrate E' as a whole.
  virtual std::optional<RelaxationSeries> relaxation_series() const { return std::nullopt; }
  /// Whether J' and E' are infinite at t = 0 (a power law: J ~ t^n, E' ~ -t^(n-1)), so that
  /// history integrals grade their ends at 0 geometrically.
  virtual bool singular_at_zero() const { return false; }
  /// Age beyond which dE/dt is below 1e-17 of its scale, so older history can be
  /// skipped; +infinity for a law with long memory.
  virtual double relaxation_memory() const = 0;
  /// Name and parameters, e.g. "standard linear solid, T = 2.5".
  virtual std::string describe() const = 0;
};

}  // namespace punchsweep::model
