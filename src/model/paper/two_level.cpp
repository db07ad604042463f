#include "model/paper/two_level.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <Eigen/Dense>

#include "model/numerics/integer_power.hpp"

#include "model/numerics/lattice.hpp"
#include "model/contact/regime.hpp"
#include "model/numerics/ring_loads.hpp"
#include "model/numerics/root_finding.hpp"
#include "model/paper/single_level.hpp"

namespace punchsweep::model {
namespace {

constexpr double kPi = std::numbers::pi;

// d(a^p)/dz for a = z^(1/zp): 0.5 p a^(p-2) when z = a^2, p a^(p-1) when z = a.
double power_rate(double a, int p, int zp) {
  return zp == 2 ? 0.5 * p * ipow(a, p - 2) : p * ipow(a, p - 1);
}

}  // namespace

TwoLevelSystem::TwoLevelSystem(const ContactProblem& problem, NominalRadii radii)
    : problem_(problem),
      radii_(radii),
      K_P_(load_coefficient(problem.shape)),
      K_d_(depth_coefficient(problem.shape)),
      z_power_(problem.shape.s == 1 ? 1 : 2),
      l2_(problem.l / std::numbers::sqrt2),
      inv_l_(1.0 / problem.l),
      inv_l2_(std::numbers::sqrt2 / problem.l),
      inv_A1_(1.0 / radii.A1),
      inv_A2_(1.0 / radii.A2) {}

// Eq (9.16) for Q (linear once a is fixed), then eqs (9.19) and (9.17) as residuals.
// Written for few divisions (reciprocals computed once, here or in the constructor): the
// Newton solves of a regime map spend most of their time in this function.
TwoLevelSystem::Evaluation TwoLevelSystem::evaluate(double a1, double a2, double X, RadiiRates* radii_rates) const {
  Evaluation e;
  double* r = e.r;
  double* J = e.J;
  const double l = problem_.l;
  const int s = problem_.shape.s;
  const double A1 = radii_.A1;
  const double A2 = radii_.A2;

  // Ring quantities of a_i against the ring at l (same level) and at l2 (other level).
  const Ring R11 = ring(a1, l, inv_l_);
  const Ring R12 = ring(a1, l2_, inv_l2_);
  const Ring R21 = ring(a2, l2_, inv_l2_);
  const Ring R22 = ring(a2, l, inv_l_);
  const double S1 = std::sqrt(A1 * A1 - a1 * a1);
  const double S2 = std::sqrt(A2 * A2 - a2 * a2);
  const double inv_S1 = 1.0 / S1;
  const double inv_S2 = 1.0 / S2;

  const double M00 = 1.0 - 4.0 * R11.share;
  const double M01 = -4.0 * R12.share;
  const double M10 = -4.0 * R21.share;
  const double M11 = 1.0 - 4.0 * R22.share;
  const double a1s1 = ipow(a1, s - 1);  // a1^(s-1): s >= 1
  const double a1s = a1s1 * a1;
  const double a2s = ipow(a2, s);
  // nominal_load_term(a_i, A_i), with the square roots above.
  const double asin1 = std::asin(a1 * inv_A1_);
  const double asin2 = std::asin(a2 * inv_A2_);
  const double b0 = K_P_ * a1s * a1 + 2.0 * X * (A1 * A1 * asin1 - a1 * S1);
  const double b1 = K_P_ * a2s * a2 + 2.0 * X * (A2 * A2 * asin2 - a2 * S2);
  const double inv_det = 1.0 / (M00 * M11 - M01 * M10);
  const double Q1 = (b0 * M11 - M01 * b1) * inv_det;
  const double Q2 = (M00 * b1 - M10 * b0) * inv_det;
  e.Q[0] = Q1;
  e.Q[1] = Q2;

  const double inv_load = 1.0 / (l * l * X);
  constexpr double k4_pi = 4.0 / kPi;
  r[0] = (Q1 + Q2) * inv_load - 1.0;
  r[1] = (K_d_ * (a1s - a2s) + k4_pi * (Q2 * R12.depth + Q1 * R11.depth - Q1 * R21.depth - Q2 * R22.depth) -
          2.0 * X * (S1 - S2) - problem_.dh) *
         inv_l_;

  // d/d(a1) and d/dz: each building block's derivative is a * (its "rate over a"), and
  // a * da/dvar is chi: a1 for a1, 1/2 for z = a2^2, a2 for z = a2.
  // nominal_load_term_rate_over_a(a_i, A_i) = 2 a_i / S_i.
  const double chi1 = a1;
  const double chi2 = z_power_ == 2 ? 0.5 : a2;
  const double v0 = (s + 1) * K_P_ * a1s + 2.0 * X * chi1 * (2.0 * a1 * inv_S1) +
                    4.0 * chi1 * (R11.share_rate * Q1 + R12.share_rate * Q2);
  const double v1 = K_P_ * power_rate(a2, s + 1, z_power_) + 2.0 * X * chi2 * (2.0 * a2 * inv_S2) +
                    4.0 * chi2 * (R22.share_rate * Q2 + R21.share_rate * Q1);
  const double dQ1_da1 = M11 * v0 * inv_det;
  const double dQ2_da1 = -M10 * v0 * inv_det;
  const double dQ1_dz = -M01 * v1 * inv_det;
  const double dQ2_dz = M00 * v1 * inv_det;
  e.dQ[0] = dQ1_da1;
  e.dQ[1] = dQ1_dz;
  e.dQ[2] = dQ2_da1;
  e.dQ[3] = dQ2_dz;
  auto ring_depth_sum = [&](double dQ1, double dQ2) {
    return dQ2 * R12.depth + dQ1 * R11.depth - dQ1 * R21.depth - dQ2 * R22.depth;
  };
  J[0] = (dQ1_da1 + dQ2_da1) * inv_load;
  J[1] = (dQ1_dz + dQ2_dz) * inv_load;
  J[2] = (K_d_ * s * a1s1 +
          k4_pi * (ring_depth_sum(dQ1_da1, dQ2_da1) + chi1 * (Q2 * R12.depth_rate + Q1 * R11.depth_rate)) +
          2.0 * X * chi1 * inv_S1) *
         inv_l_;
  J[3] = (-K_d_ * power_rate(a2, s, z_power_) +
          k4_pi * (ring_depth_sum(dQ1_dz, dQ2_dz) - chi2 * (Q1 * R21.depth_rate + Q2 * R22.depth_rate)) -
          2.0 * X * chi2 * inv_S2) *
         inv_l_;
  if (radii_rates == nullptr) return e;

  // The radii enter b_i through nominal_load_term(a_i, A_i), whose A-derivative is
  // 2A arcsin(a/A) - 2aA/S, and the height condition through S_i = sqrt(A_i^2 - a_i^2).
  double* Q_A = radii_rates->Q_A;
  double* r_A = radii_rates->r_A;
  const double db0 = 2.0 * X * (2.0 * A1 * asin1 - 2.0 * a1 * A1 * inv_S1);  // d b0 / d A1
  const double db1 = 2.0 * X * (2.0 * A2 * asin2 - 2.0 * a2 * A2 * inv_S2);  // d b1 / d A2
  Q_A[0] = M11 * db0 * inv_det;   // dQ1/dA1
  Q_A[1] = -M01 * db1 * inv_det;  // dQ1/dA2
  Q_A[2] = -M10 * db0 * inv_det;  // dQ2/dA1
  Q_A[3] = M00 * db1 * inv_det;   // dQ2/dA2
  r_A[0] = (Q_A[0] + Q_A[2]) * inv_load;
  r_A[1] = (Q_A[1] + Q_A[3]) * inv_load;
  r_A[2] = (k4_pi * ring_depth_sum(Q_A[0], Q_A[2]) - 2.0 * X * A1 * inv_S1) * inv_l_;
  r_A[3] = (k4_pi * ring_depth_sum(Q_A[1], Q_A[3]) + 2.0 * X * A2 * inv_S2) * inv_l_;
  return e;
}

TwoLevelSystem::Linearization TwoLevelSystem::linearize(double a1, double a2, double X) const {
  Linearization out{};
  RadiiRates rates{};
  const Evaluation e = evaluate(a1, a2, X, &rates);
  std::copy(e.r, e.r + 2, out.r);
  std::copy(e.Q, e.Q + 2, out.Q);
  std::copy(e.J, e.J + 4, out.r_a);
  std::copy(e.dQ, e.dQ + 4, out.Q_a);
  std::copy(rates.r_A, rates.r_A + 4, out.r_A);
  std::copy(rates.Q_A, rates.Q_A + 4, out.Q_A);
  return out;
}

std::array<double, 4> TwoLevelSystem::root_radii_rates(double a1, double a2, double X) const {
  const Linearization lin = linearize(a1, a2, X);
  const double* J = lin.r_a;
  const double* B = lin.r_A;
  const double det = J[0] * J[3] - J[1] * J[2];
  // -J^-1 B, J^-1 = [J3 -J1; -J2 J0] / det.
  return {-(J[3] * B[0] - J[1] * B[2]) / det, -(J[3] * B[1] - J[1] * B[3]) / det,
          -(-J[2] * B[0] + J[0] * B[2]) / det, -(-J[2] * B[1] + J[0] * B[3]) / det};
}

TwoLevelSolve TwoLevelSystem::solve(double X, const TwoLevelState& guess, int max_iterations) const {
  const double l = problem_.l;
  const double l2 = l / std::numbers::sqrt2;
  const double a1_max = std::min(l2, radii_.A1) * kTwoLevelDomainMargin;
  const double a2_max = std::min(l2, radii_.A2) * kTwoLevelDomainMargin;
  const double inv_z_scale = z_power_ == 2 ? inv_l_ * inv_l_ : inv_l_;
  auto to_a2 = [&](double z) { return z_power_ == 2 ? std::sqrt(z) : z; };

  double a1 = std::clamp(guess.a1, 1e-300, a1_max);
  double z = z_power_ == 2 ? guess.a2 * guess.a2 : guess.a2;
  z = std::clamp(z, 0.0, z_power_ == 2 ? a2_max * a2_max : a2_max);
  Evaluation e = evaluate(a1, to_a2(z), X);
  auto norm_of = [](const Evaluation& v) { return std::max(std::abs(v.r[0]), std::abs(v.r[1])); };
  double norm = norm_of(e);
  bool final_step = false;

  TwoLevelSolve out;
  for (int it = 0; it < max_iterations; ++it) {
    const double* r = e.r;
    const double* J = e.J;
    const double inv_det = 1.0 / (J[0] * J[3] - J[1] * J[2]);
    const double d1 = (-r[0] * J[3] + J[1] * r[1]) * inv_det;
    const double d2 = (-J[0] * r[1] + J[2] * r[0]) * inv_det;
    if (!std::isfinite(d1) || !std::isfinite(d2)) break;

    // Close enough for the step to be the last (kFinalStep): take it unevaluated.
    if (std::max(std::abs(d1) * inv_l_, std::abs(d2) * inv_z_scale) < kFinalStep && norm < kResidualTolerance * 1e3 &&
        a1 + d1 > 0.0 && a1 + d1 < a1_max && z + d2 >= 0.0 && to_a2(z + d2) < a2_max) {
      a1 += d1;
      z += d2;
      e.Q[0] += e.dQ[0] * d1 + e.dQ[1] * d2;
      e.Q[1] += e.dQ[2] * d1 + e.dQ[3] * d2;
      final_step = true;
      break;
    }

    // Damped step: stay in the domain and do not let the residual grow. The trial point
    // is evaluated with its Jacobian, so an accepted step costs one evaluation.
    double lambda = 1.0;
    double a1_new = a1;
    double z_new = z;
    Evaluation trial{};
    bool accepted = false;
    for (int halving = 0; halving < 40; ++halving, lambda *= 0.5) {
      a1_new = a1 + lambda * d1;
      z_new = std::max(z + lambda * d2, 0.0);
      if (!(a1_new > 0.0 && a1_new < a1_max && to_a2(z_new) < a2_max)) continue;
      trial = evaluate(a1_new, to_a2(z_new), X);
      const double norm_new = norm_of(trial);
      if (std::isfinite(norm_new) && (norm_new < norm || norm_new <= kResidualTolerance * 1e-3)) {
        accepted = true;
        norm = norm_new;
        break;
      }
    }
    if (!accepted) break;
    const double step = std::max(std::abs(a1_new - a1) * inv_l_, std::abs(z_new - z) * inv_z_scale);
    a1 = a1_new;
    z = z_new;
    e = trial;
    if (step < kStepTolerance || norm < kConvergedResidual) break;
  }
  out.state = TwoLevelState{a1, to_a2(z), e.Q[0], e.Q[1]};
  out.converged = final_step || norm < kResidualTolerance;
  return out;
}

TwoLevelSolve TwoLevelSystem::continue_to(const TwoLevelState& from, double X_from, double X_to, int max_solves,
                                          int* solves) const {
  return continue_branch(*this, from, X_from, X_to, max_solves, solves);
}

TwoLevelSolve TwoLevelSystem::solve_from_touchdown(double X) const {
  const Touchdown touch = touchdown(SingleLevel(problem_.l, problem_.shape), problem_.dh);
  const double a1_touch = touch.a1_star;
  const double X_touch = touch.X_star;
  // Below this share of the target load the touchdown point is too close to a = 0 for
  // Newton; start instead from the isolated-punch limit (interactions negligible).
  constexpr double kSmallLoadShare = 1e-6;
  if (X_touch >= kSmallLoadShare * X) {
    const double l = problem_.l;
    return continue_to(TwoLevelState{a1_touch, 0.0, l * l * X_touch, 0.0}, X_touch, X);
  }
  const double X_start = kSmallLoadShare * X;
  const double load = problem_.l * problem_.l * X_start;
  const int s = problem_.shape.s;
  // Isolated punches: Q_i = K_P a_i^(s+1), K_d (a1^s - a2^s) = dh; bisect on a2.
  auto a1_of = [&](double a2) { return std::pow(ipow(a2, s) + problem_.dh / K_d_, 1.0 / s); };
  auto excess = [&](double a2) {
    const double a1 = a1_of(a2);
    return K_P_ * (ipow(a1, s + 1) + ipow(a2, s + 1)) - load;
  };
  const auto [lo, hi] = bisect_boundary([&](double a2) { return !(excess(a2) > 0.0); }, 0.0,
                                         std::pow(load / K_P_, 1.0 / (s + 1)), 1e-16, 200);
  const double a2 = 0.5 * (lo + hi);
  const double a1 = a1_of(a2);
  const TwoLevelSolve start = solve(X_start, TwoLevelState{a1, a2, 0.0, 0.0});
  if (!start.converged) return start;
  return continue_to(start.state, X_start, X);
}

}  // namespace punchsweep::model
