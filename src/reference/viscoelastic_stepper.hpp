#pragma once
/// @file
/// Time stepping of the periodic contact on a linear viscoelastic half-space in the creep
/// form, one contact solve per step. Units: pressures in E0*, lengths in R, time in T_eps,
/// creep J in 1/E0*.

#include <cstddef>
#include <span>
#include <vector>

#include "model/laws/creep_law.hpp"
#include "model/problem/load_shape.hpp"
#include "reference/contact_solver.hpp"
#include "reference/periodic_grid.hpp"

namespace punchsweep::reference {

/// How the creep integral's history is carried.
enum class CreepHistoryForm {
  /// A law that is a retardation series (CreepLaw::retardation_series: the standard linear
  /// solid, Prony and Kelvin series): one exponential internal variable per term and node,
  /// updated exactly for a pressure history linear in each step (O(terms x nodes) memory
  /// and work per step).
  exponential,
  /// Any creep law: the convolution with J over the stored pressure history, with the
  /// exact weights int J(t - tau) dtau of each step by 8-point Gauss-Legendre
  /// (O(steps x nodes) memory, O(steps x nodes) work per step).
  convolution,
};

/// The surface response u(t) = K w(t), w(t) = int_0-^t J(t - tau) dp(tau) (K: the E* = 1
/// influence; the "creep-scaled pressure" w is Q of docs/model.md, node by node), under a
/// constant mean pressure pbar0 (the paper's constant nominal pressure).
///
/// The pressure history is taken piecewise linear in time, so each step is
///   w(t_n+1) = J_step p(t_n+1) + w_hist,   J_step = (1/dt) int_0^dt J(s) ds,
/// with w_hist known from the history: one elastic contact solve with compliance J_step
/// against the profile shifted by K w_hist. For a retardation series
/// J = J(inf) - sum_k J_k e^(-t/lambda_k) (the standard linear solid: J(inf) = T, one term
/// J_1 = T - 1, lambda_1 = 1), w_hist = sum_k J_k (b_k p_n - e^(-dt/lambda_k) q_k,n) with
/// b_k = (1 - e^(-x))/x, x = dt/lambda_k, and each internal variable
/// q_k = int e^-((t - tau)/lambda_k) dp(tau) steps as q_k,n+1 = e^(-x) q_k,n + b_k (p_n+1 - p_n).
/// The step is second order in dt where p(t) is smooth (measured: see the tests). Under a
/// constant mean pressure with a growing contact, w itself has no time-step error (its mean
/// is pbar0 J(t) exactly and it solves the elastic problem at J(t) on the contact set), so
/// the contact areas are exact in time; the pressures and loads carry the O(dt^2) error.
/// The creep law is held by reference and must outlive the stepper.
///
/// One instance owns its solver: not for concurrent use.
class ViscoelasticStepper {
 public:
  /// @param profile   initial separation at zero approach (grid.size() values, in R)
  /// @param mean_pressure  constant nominal pressure pbar0 > 0
  /// @param creep     the material; a law with a retardation series gets the exponential
  ///                  form unless `form` asks for the convolution (kept for cross-checks)
  /// `loading`: the mean pressure is pbar0 phi(t) (a step by default); without a jump at
  /// t = 0 the start is the unloaded surface. A caller steps onto the load's kinks (the
  /// pressure is taken linear within a step).
  ViscoelasticStepper(const PeriodicGrid& grid, std::vector<double> profile, double mean_pressure,
                      const model::CreepLaw& creep, ContactSolverOptions options = {}, model::LoadShape loading = {});
  ViscoelasticStepper(const PeriodicGrid& grid, std::vector<double> profile, double mean_pressure,
                      const model::CreepLaw& creep, ContactSolverOptions options,
                      CreepHistoryForm form, model::LoadShape loading = {});

  /// The instantaneous response at t = 0 (compliance J(0)); must be called first.
  ContactStatus start();
  /// One step from time() to t_next > time().
  ContactStatus advance(double t_next);

  /// What rewind() needs to return to the present state.
  struct Checkpoint {
    double t = 0.0;
    std::vector<double> p, w, u;
    std::vector<std::vector<double>> q;
    double approach = 0.0;
    std::size_t history_length = 0;
  };
  Checkpoint checkpoint() const;
  /// Returns to a state of this stepper saved by checkpoint() (refining a step).
  void rewind(const Checkpoint& saved);

  double time() const { return t_; }
  std::span<const double> pressure() const { return p_; }        ///< p(t), in E0*
  std::span<const double> creep_pressure() const { return w_; }  ///< w(t) = int J dp
  std::span<const double> displacement() const { return u_; }    ///< u(t) = K w, in R
  double approach() const { return approach_; }                  ///< delta(t), in R
  std::span<const double> profile() const { return profile_; }
  const PeriodicGrid& grid() const { return solver_.grid(); }
  CreepHistoryForm form() const { return form_; }
  bool started() const { return started_; }
  /// Compliance of a step of length dt starting now: (1/dt) int_0^dt J(s) ds.
  double step_compliance(double dt) const;

 private:
  /// Mean of J over [t_end - b, t_end - a] (the weight of a linear pressure ramp on [a, b]).
  double mean_creep(double t_end, double a, double b) const;

  ContactSolver solver_;
  std::vector<double> profile_;
  double pbar0_;
  model::LoadShape loading_;
  /// The mean pressure at t > 0 (at 0: what is applied at once).
  double mean_pressure(double t) const { return loading_.is_step() ? pbar0_ : pbar0_ * (t > 0.0 ? loading_.at(t) : loading_.jump()); }
  const model::CreepLaw& creep_;
  CreepHistoryForm form_;
  model::RetardationSeries series_;  ///< exponential form: the law's terms
  bool started_ = false;

  double t_ = 0.0;
  std::vector<double> p_, w_, u_;
  double approach_ = 0.0;
  std::vector<std::vector<double>> q_;        ///< exponential form, per term: int e^-((t-tau)/lambda_k) dp
  std::vector<double> times_;                 ///< convolution form: t_0 .. t_n
  std::vector<std::vector<double>> history_;  ///< convolution form: p(t_0) .. p(t_n)

  std::vector<double> w_hist_, shifted_profile_, u_hist_;
};

}  // namespace punchsweep::reference
