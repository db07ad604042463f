#include "model/shells/two_level_shells.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "model/numerics/integer_power.hpp"

namespace punchsweep::model {
namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

TwoLevelShells::TwoLevelShells(const ContactProblem& problem, Localization localization)
    : problem_(problem),
      K_P_(load_coefficient(problem.shape)),
      K_d_(depth_coefficient(problem.shape)),
      sums_(&shell_sums(problem.shape.s, localization)),
      margin_(localization.merge_margin()) {}

NominalRadii TwoLevelShells::radii(const TwoLevelState& state, double X) const {
  const double n_same = sums_->same_count();
  const double n_cross = sums_->cross_count();
  return {std::sqrt(((1.0 + n_same) * state.Q1 + n_cross * state.Q2) / (kPi * X)),
          std::sqrt(((1.0 + n_same) * state.Q2 + n_cross * state.Q1) / (kPi * X))};
}

TwoLevelShells::Sums TwoLevelShells::sums(double a1, double a2) const {
  const double l = problem_.l;
  return {{sums_->same(a1 / l), sums_->same(a2 / l)}, {sums_->cross(a1 / l, a2 / l), sums_->cross(a2 / l, a1 / l)}};
}

std::array<double, 4> TwoLevelShells::residuals(double X, const std::array<double, 4>& z) const {
  return residuals(X, z, sums(z[0], z[1]));
}

std::array<double, 4> TwoLevelShells::residuals(double X, const std::array<double, 4>& z, const Sums& sums) const {
  const double l = problem_.l;
  const double a[2] = {z[0], z[1]};
  const double Q[2] = {z[2], z[3]};
  const int s = problem_.shape.s;
  const double scale = 1.0 / (X * l * l);
  const NominalRadii A = radii(TwoLevelState{a[0], a[1], Q[0], Q[1]}, X);
  double depth[2];
  std::array<double, 4> r{};
  for (int i = 0; i < 2; ++i) {
    const int j = 1 - i;
    const double ai = a[i];
    const double Ai = i == 0 ? A.A1 : A.A2;
    const ShellSums::Sums& same = sums.same[i];
    const ShellSums::Sums& cross = sums.cross[i];
    const double S = std::sqrt(Ai * Ai - ai * ai);
    r[i] = (K_P_ * ipow(ai, s + 1) + Q[i] * same.carried + Q[j] * cross.carried +
            2.0 * X * (Ai * Ai * std::asin(ai / Ai) - ai * S) - Q[i]) *
           scale;
    depth[i] = K_d_ * ipow(ai, s) + (Q[i] * same.depth + Q[j] * cross.depth) / l - 2.0 * X * S;
  }
  r[2] = (Q[0] + Q[1]) * scale - 1.0;
  r[3] = (depth[0] - depth[1] - problem_.dh) * scale * l;
  return r;
}

TwoLevelSolve TwoLevelShells::solve(double X, const TwoLevelState& guess, int max_iterations) const {
  const double l = problem_.l;
  const double load = X * l * l;
  // Newton runs in (a1, z, Q1, Q2), z = a2^2 for s >= 2 (a2 for s = 1), in which the
  // residuals stay regular as level 2 starts to touch (as TwoLevelSystem does).
  const bool squared = problem_.shape.s >= 2;
  const auto a2_of = [squared](double z) { return squared ? std::sqrt(std::max(z, 0.0)) : z; };
  const bool split = guess.Q1 + guess.Q2 > 0.0;
  Eigen::Vector4d v(guess.a1, squared ? guess.a2 * guess.a2 : guess.a2, split ? guess.Q1 : 0.9 * load,
                    split ? guess.Q2 : 0.1 * load);
  const auto physical = [&](const Eigen::Vector4d& u) { return std::array<double, 4>{u[0], a2_of(u[1]), u[2], u[3]}; };
  // The spots stay apart by the merge margin (the family's domain, ShellSums' reach).
  const double reach = margin_ * l;
  const auto admissible = [&](const Eigen::Vector4d& u) {
    const double b = a2_of(u[1]);
    return u[0] > 0.0 && u[1] >= 0.0 && 2.0 * u[0] < reach && 2.0 * b < reach &&
           u[0] + b < reach / std::numbers::sqrt2 && u[2] > 0.0 && u[3] >= 0.0;
  };
  const auto norm = [](const std::array<double, 4>& r) {
    return std::max({std::abs(r[0]), std::abs(r[1]), std::abs(r[2]), std::abs(r[3])});
  };
  // Forward differences, each step small against its variable's scale and kept inside the
  // domain (z and Q2 step upward from 0 at touchdown).
  const double steps[4] = {1e-7 * l, 1e-7 * (squared ? l * l : l), 1e-7 * load, 1e-7 * load};
  Sums at = sums(v[0], a2_of(v[1]));
  std::array<double, 4> r = residuals(X, physical(v), at);
  double current = norm(r);
  if (!std::isfinite(current)) current = std::numeric_limits<double>::infinity();
  for (int it = 0; it < max_iterations && current > kConvergedResidual; ++it) {
    Eigen::Matrix4d J;
    for (int c = 0; c < 4; ++c) {
      Eigen::Vector4d shifted = v;
      const double h = c == 0 ? -steps[c] : steps[c];  // a1 steps inward
      shifted[c] += h;
      // The loads leave the sums as they are (they depend on the radii alone).
      const std::array<double, 4> rs =
          c >= 2 ? residuals(X, physical(shifted), at) : residuals(X, physical(shifted));
      for (int k = 0; k < 4; ++k) J(k, c) = (rs[k] - r[k]) / h;
    }
    const Eigen::Vector4d step = J.partialPivLu().solve(-Eigen::Vector4d(r[0], r[1], r[2], r[3]));
    if (!step.allFinite()) break;
    double lambda = 1.0;
    bool accepted = false;
    for (int halving = 0; halving < 40 && !accepted; ++halving, lambda *= 0.5) {
      Eigen::Vector4d trial = v + lambda * step;
      trial[1] = std::max(trial[1], 0.0);
      trial[3] = std::max(trial[3], 0.0);
      if (!admissible(trial)) continue;
      const Sums trial_sums = sums(trial[0], a2_of(trial[1]));
      const std::array<double, 4> rt = residuals(X, physical(trial), trial_sums);
      const double n = norm(rt);
      if (std::isfinite(n) && n < current) {
        v = trial;
        r = rt;
        at = trial_sums;
        current = n;
        accepted = true;
      }
    }
    if (!accepted) break;
  }
  TwoLevelSolve out;
  out.state = TwoLevelState{v[0], a2_of(v[1]), v[2], v[3]};
  out.converged = current <= kResidualTolerance && admissible(v);
  return out;
}

TwoLevelSolve TwoLevelShells::continue_to(const TwoLevelState& from, double X_from, double X_to, int max_solves,
                                          int* solves) const {
  return continue_branch(*this, from, X_from, X_to, max_solves, solves);
}

}  // namespace punchsweep::model
