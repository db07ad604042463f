#pragma once

#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

#include "model/laws/creep_law.hpp"
#include "model/problem/load_shape.hpp"

namespace punchsweep::model {

/// The creep-weighted load X(t) = int_0-^t J(t - tau) dpbar(tau) (docs/model.md, section
/// 10), through which time enters every phase of the model: the single-level radius and h,
/// the touchdown time t*, the two-level state, the pressure and the load history all depend
/// on t only through X(t) (extended correspondence principle, valid while contact does not
/// recede). It is written X(t) = pbar0 g(t) with g the response to the unit-shaped load
/// pbar(t)/pbar0 = phi(t) (LoadShape):
///   g(t) = phi(0+) J(t) + sum over the linear pieces [t_a, t_b] of phi, slope k:
///          k int_{t_a}^{min(t, t_b)} J(t - tau) dtau = k int_{t - min(t, t_b)}^{t - t_a} J(u) du;
/// for the step phi = 1 it is g = J.
/// Units: X in E0*, g in 1/E0*, t in the law's time unit. Holds references to the law and
/// copies the shape.
class CreepWeightedLoad {
 public:
  /// Nominal pressure pbar0 (> 0) applied with `shape` (a step by default) on a material of
  /// creep function J.
  CreepWeightedLoad(const CreepLaw& creep, double pbar0, const LoadShape& shape = {});

  /// The final nominal pressure pbar0, in E0*.
  double pbar0() const { return pbar0_; }
  /// The material.
  const CreepLaw& creep() const { return creep_; }
  /// The shape of the load.
  const LoadShape& shape() const { return shape_; }

  /// g(t) = X(t)/pbar0, the response to the unit-shaped load.
  double response(double t) const;
  /// dg/dt.
  double response_rate(double t) const;
  /// g(0+).
  double response_initial() const {
    return shape_.is_step() ? creep_.creep_initial() : shape_.jump() * creep_.creep_initial();
  }
  /// g(inf) = J(inf) (phi ends at 1); +infinity for unlimited creep.
  double response_final() const { return creep_.creep_final(); }
  /// A time after which g(t) = g(inf) to rounding: the end of the load's rise plus
  /// kForgetting of the law's longest retardation time; +infinity for a law that is not
  /// a retardation series (unlimited creep, a power law).
  double settled_time() const;
  /// The t > 0 with g(t) = g for g in (g(0+), g(inf)); non-decreasing g makes it a root.
  double time_at_response(double g) const;

  /// X(t), in E0*.
  double operator()(double t) const { return pbar0_ * response(t); }
  /// X(0+): what the load gives at once.
  double initial() const { return pbar0_ * response_initial(); }
  /// X(inf); +infinity for unlimited creep.
  double final() const { return pbar0_ * response_final(); }
  /// X by time t as a requirement reads it ("touch within t"): X(0+) at t = 0 (at once),
  /// X(inf) at t = +infinity (ever), X(t) otherwise.
  double by(double t) const { return t == 0.0 ? initial() : t == std::numeric_limits<double>::infinity() ? final() : (*this)(t); }

  /// The nominal pressure pbar(t) = pbar0 phi(t) at t > 0, in E0*.
  double nominal_pressure(double t) const { return shape_.is_step() ? pbar0_ : pbar0_ * shape_.at(t); }

 private:
  /// A load table of more than kDirectPieces pieces on a law with a retardation series
  /// (J(u) = J(inf) - sum_k J_k exp(-u/lambda_k)): the completed pieces' sums per piece end
  /// T_n, so that g(t) and g'(t) cost O(terms) instead of O(pieces x terms) (a history
  /// evaluates them O(pieces) times: a 400-point table took 34 s). With
  ///   S_k(T_n) = sum_{s <= n} k_s [exp(-(T_n - t_b,s)/lambda_k) - exp(-(T_n - t_a,s)/lambda_k)],
  /// by the recursion S_k(T_n) = exp(-(T_n - T_(n-1))/lambda_k) S_k(T_(n-1))
  /// - k_n expm1(-(t_b,n - t_a,n)/lambda_k) (every exponent <= 0), the completed pieces add
  ///   J(inf) sum_s k_s (t_b - t_a) - sum_k J_k lambda_k exp(-(t - T_n)/lambda_k) S_k(T_n)
  /// to g(t), and sum_k J_k exp(-(t - T_n)/lambda_k) S_k(T_n) to g'(t).
  struct CompletedPieces {
    RetardationSeries series;
    std::vector<double> ends;  ///< T_n = t_b of piece n
    std::vector<double> load;  ///< sum_{s <= n} k_s (t_b,s - t_a,s)
    std::vector<double> S;     ///< S_k(T_n) at [n * terms + k]
  };
  /// Up to this many pieces (a ramp has one) the sums over the pieces are taken directly.
  static constexpr std::size_t kDirectPieces = 4;
  /// Adds what the pieces completed by t (their ends <= t) contribute to *g (g(t)) and to
  /// *rate (g'(t)), either may be null, and returns how many they are (0 without
  /// CompletedPieces: the direct sums then start from piece 0).
  std::size_t add_completed(double t, double* g, double* rate) const;

  const CreepLaw& creep_;
  double pbar0_;
  LoadShape shape_;
  std::shared_ptr<const CompletedPieces> completed_;  ///< null: the direct sums
};

}  // namespace punchsweep::model
