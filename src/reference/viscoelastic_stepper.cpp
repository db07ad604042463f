#include "reference/viscoelastic_stepper.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

#include "model/numerics/gauss_rules.hpp"

namespace punchsweep::reference {

namespace {

/// Points of the Gauss-Legendre rule for the step weights: exact for polynomials of degree
/// 15, so to round-off for an exponential J over steps up to its retardation time.
constexpr int kWeightQuadraturePoints = 8;

CreepHistoryForm natural_form(const model::CreepLaw& creep) {
  return creep.retardation_series() ? CreepHistoryForm::exponential : CreepHistoryForm::convolution;
}

}  // namespace

ViscoelasticStepper::ViscoelasticStepper(const PeriodicGrid& grid, std::vector<double> profile,
                                         double mean_pressure, const model::CreepLaw& creep,
                                         ContactSolverOptions options, model::LoadShape loading)
    : ViscoelasticStepper(grid, std::move(profile), mean_pressure, creep, options,
                          natural_form(creep), std::move(loading)) {}

ViscoelasticStepper::ViscoelasticStepper(const PeriodicGrid& grid, std::vector<double> profile,
                                         double mean_pressure, const model::CreepLaw& creep,
                                         ContactSolverOptions options, CreepHistoryForm form,
                                         model::LoadShape loading)
    : solver_(grid, options),
      profile_(std::move(profile)),
      pbar0_(mean_pressure),
      loading_(std::move(loading)),
      creep_(creep),
      form_(form),
      p_(grid.size(), mean_pressure),
      w_(grid.size()),
      u_(grid.size()),
      w_hist_(grid.size()),
      shifted_profile_(grid.size()),
      u_hist_(grid.size()) {
  if (profile_.size() != grid.size()) {
    throw std::invalid_argument("ViscoelasticStepper: profile size differs from the grid");
  }
  if (!(mean_pressure > 0.0)) throw std::invalid_argument("ViscoelasticStepper: pbar0 must be > 0");
  if (form_ == CreepHistoryForm::exponential) {
    std::optional<model::RetardationSeries> series = creep.retardation_series();
    if (!series || series->terms.empty()) {
      throw std::invalid_argument("ViscoelasticStepper: the exponential form needs a law with a retardation series");
    }
    series_ = std::move(*series);
  }
}

double ViscoelasticStepper::mean_creep(double t_end, double a, double b) const {
  const model::GaussRule& rule = model::gauss_legendre(kWeightQuadraturePoints);
  const double mid = 0.5 * (a + b);
  const double half = 0.5 * (b - a);
  double sum = 0.0;
  for (std::size_t k = 0; k < rule.nodes.size(); ++k) {
    sum += rule.weights[k] * creep_.creep(t_end - (mid + half * rule.nodes[k]));
  }
  return 0.5 * sum;
}

double ViscoelasticStepper::step_compliance(double dt) const {
  if (form_ == CreepHistoryForm::exponential) {
    double decayed = 0.0;  // sum_k J_k b_k
    for (const model::RetardationSeries::Term& term : series_.terms) {
      const double x = dt / term.lambda;
      decayed += term.J * (-std::expm1(-x) / x);
    }
    return series_.J_final - decayed;
  }
  return mean_creep(t_ + dt, t_, t_ + dt);
}

ContactStatus ViscoelasticStepper::start() {
  const double J0 = creep_.creep(0.0);
  const double p0 = mean_pressure(0.0);
  std::fill(p_.begin(), p_.end(), p0);
  ContactStatus status;
  if (p0 > 0.0) {
    status = solver_.solve(profile_, p0, J0, p_, u_);
  } else {
    // No load at once (a ramp): the unloaded surface, nothing in contact.
    std::fill(u_.begin(), u_.end(), 0.0);
    status.converged = true;
  }
  t_ = 0.0;
  approach_ = status.approach;
  for (std::size_t i = 0; i < p_.size(); ++i) w_[i] = J0 * p_[i];
  if (form_ == CreepHistoryForm::exponential) {
    q_.assign(series_.terms.size(), p_);  // q_k(0+) = p(0): the load is applied as a step at t = 0
  } else {
    times_.assign(1, 0.0);
    history_.assign(1, p_);
  }
  started_ = true;
  return status;
}

ContactStatus ViscoelasticStepper::advance(double t_next) {
  if (!started_) throw std::logic_error("ViscoelasticStepper::advance before start");
  const double dt = t_next - t_;
  if (!(dt > 0.0)) throw std::invalid_argument("ViscoelasticStepper::advance: t_next <= time()");
  const std::size_t n = p_.size();
  const double J_step = step_compliance(dt);

  // History part of w(t_next): everything but J_step p(t_next).
  const std::size_t terms = form_ == CreepHistoryForm::exponential ? series_.terms.size() : 0;
  std::vector<double> decay(terms);
  std::vector<double> ramp(terms);
  if (form_ == CreepHistoryForm::exponential) {
    for (std::size_t k = 0; k < terms; ++k) {
      const model::RetardationSeries::Term& term = series_.terms[k];
      const double x = dt / term.lambda;
      decay[k] = std::exp(-x);
      ramp[k] = -std::expm1(-x) / x;
      const std::vector<double>& q = q_[k];
      if (k == 0) {
        for (std::size_t i = 0; i < n; ++i) w_hist_[i] = term.J * (ramp[k] * p_[i] - decay[k] * q[i]);
      } else {
        for (std::size_t i = 0; i < n; ++i) w_hist_[i] += term.J * (ramp[k] * p_[i] - decay[k] * q[i]);
      }
    }
  } else {
    const double J_jump = creep_.creep(t_next);  // the step load p(t_0) at t_0 = 0
    const std::vector<double>& p0 = history_.front();
    for (std::size_t i = 0; i < n; ++i) w_hist_[i] = J_jump * p0[i] - J_step * p_[i];
    for (std::size_t k = 0; k + 1 < times_.size(); ++k) {
      const double c = mean_creep(t_next, times_[k], times_[k + 1]);
      const std::vector<double>& pa = history_[k];
      const std::vector<double>& pb = history_[k + 1];
      for (std::size_t i = 0; i < n; ++i) w_hist_[i] += c * (pb[i] - pa[i]);
    }
  }
  solver_.influence().apply(w_hist_, u_hist_);
  for (std::size_t i = 0; i < n; ++i) shifted_profile_[i] = profile_[i] + u_hist_[i];

  std::vector<double> p_next = p_;  // warm start from the present pressure
  const ContactStatus status = solver_.solve(shifted_profile_, mean_pressure(t_next), J_step, p_next, u_);
  for (std::size_t i = 0; i < n; ++i) {
    u_[i] += u_hist_[i];
    w_[i] = J_step * p_next[i] + w_hist_[i];
  }
  if (form_ == CreepHistoryForm::exponential) {
    for (std::size_t k = 0; k < terms; ++k) {
      std::vector<double>& q = q_[k];
      for (std::size_t i = 0; i < n; ++i) q[i] = decay[k] * q[i] + ramp[k] * (p_next[i] - p_[i]);
    }
  } else {
    times_.push_back(t_next);
    history_.push_back(p_next);
  }
  p_ = std::move(p_next);
  t_ = t_next;
  approach_ = status.approach;
  return status;
}

ViscoelasticStepper::Checkpoint ViscoelasticStepper::checkpoint() const {
  return Checkpoint{t_, p_, w_, u_, q_, approach_, times_.size()};
}

void ViscoelasticStepper::rewind(const Checkpoint& saved) {
  if (saved.history_length > times_.size() || saved.p.size() != p_.size()) {
    throw std::invalid_argument("ViscoelasticStepper::rewind: not a checkpoint of this history");
  }
  t_ = saved.t;
  p_ = saved.p;
  w_ = saved.w;
  u_ = saved.u;
  q_ = saved.q;
  approach_ = saved.approach;
  times_.resize(saved.history_length);
  history_.resize(saved.history_length);
}

}  // namespace punchsweep::reference
