#include "model/two_level_shells.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "model/integer_power.hpp"
#include "model/lattice.hpp"
#include "model/shape.hpp"

namespace punchsweep::model {
namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

TwoLevelShells::TwoLevelShells(const ContactProblem& problem, Localization localization)
    : problem_(problem),
      localization_(localization),
      K_P_(load_coefficient(problem.shape)),
      K_d_(depth_coefficient(problem.shape)),
      spot_(problem.shape.s) {
  for (int level = 1; level <= 2; ++level) {
    for (const DistanceShell& shell : kept_neighbours(level, localization.shells)) {
      kept_[level - 1].push_back({shell.distance * problem.l, shell.count, shell.level});
    }
  }
}

std::vector<double> TwoLevelShells::residuals(double X, const double* z, double* A1, double* A2) const {
  const double a[2] = {z[0], z[1]};
  const double Q[2] = {z[2], z[3]};
  const int s = problem_.shape.s;
  double depth[2];
  std::vector<double> r(4);
  for (int i = 0; i < 2; ++i) {
    const double ai = a[i];
    const auto carried = [ai](double x) { return 2.0 / kPi * (ai / std::sqrt(x * x - ai * ai) - std::asin(ai / x)); };
    const auto depth_kernel = [ai](double x) { return 1.0 / (kPi * std::sqrt(x * x - ai * ai)); };
    double loads = Q[i];
    double share = 0.0;
    double d = 0.0;
    for (const DistanceShell& k : kept_[i]) {
      const double source = a[k.level - 1];
      const bool spread = localization_.distributed && source > 0.0;
      loads += k.count * Q[k.level - 1];
      share += k.count * Q[k.level - 1] * (spread ? spot_(carried, k.distance, source) : carried(k.distance));
      d += k.count * Q[k.level - 1] * (spread ? spot_(depth_kernel, k.distance, source) : depth_kernel(k.distance));
    }
    const double A = std::sqrt(loads / (kPi * X));
    (i == 0 ? *A1 : *A2) = A;
    r[i] = K_P_ * ipow(ai, s + 1) + share + 2.0 * X * (A * A * std::asin(ai / A) - ai * std::sqrt(A * A - ai * ai)) - Q[i];
    depth[i] = K_d_ * ipow(ai, s) + d - 2.0 * X * std::sqrt(A * A - ai * ai);
  }
  r[2] = Q[0] + Q[1] - X * problem_.l * problem_.l;
  r[3] = depth[0] - depth[1] - problem_.dh;
  return r;
}

TwoLevelShells::State TwoLevelShells::solve(double X, double a1, double a2) const {
  const double l = problem_.l;
  const double scale = X * l * l;  // loads and, over l, the residuals' size
  // Newton runs in (a1, w, Q1, Q2) with w = a2^2 for s >= 2 (a2 for s = 1), in which the
  // residuals stay regular as level 2 starts to touch (as TwoLevelSystem does).
  const bool squared = problem_.shape.s >= 2;
  const auto a2_of = [squared](double w) { return squared ? std::sqrt(std::max(w, 0.0)) : w; };
  Eigen::Vector4d z(a1, squared ? a2 * a2 : a2, 0.9 * scale, 0.1 * scale);
  const auto physical = [&](const Eigen::Vector4d& v) { return Eigen::Vector4d(v[0], a2_of(v[1]), v[2], v[3]); };
  const auto admissible = [&](const Eigen::Vector4d& v) {
    const double b = a2_of(v[1]);
    return v[0] > 0.0 && v[1] > 0.0 && 2.0 * v[0] < l && 2.0 * b < l && v[0] + b < l / std::numbers::sqrt2 &&
           v[2] > 0.0 && v[3] > 0.0;
  };
  const auto norm = [&](const std::vector<double>& r) {
    return std::max({std::abs(r[0]), std::abs(r[1]), std::abs(r[2]), std::abs(r[3]) * l}) / scale;
  };
  const auto residuals_at = [&](const Eigen::Vector4d& v, double* A1, double* A2) {
    const Eigen::Vector4d p = physical(v);
    return residuals(X, p.data(), A1, A2);
  };
  State out;
  double A1 = 0.0, A2 = 0.0;
  std::vector<double> r = residuals_at(z, &A1, &A2);
  for (int it = 0; it < 60 && norm(r) > 1e-13; ++it) {
    Eigen::Matrix4d J;
    for (int c = 0; c < 4; ++c) {
      Eigen::Vector4d zp = z;
      const double h = 1e-7 * (c == 0 ? l : c == 1 ? std::max(std::abs(z[1]), 1e-6 * (squared ? l * l : l)) : scale);
      zp[c] += h;
      Eigen::Vector4d zm = z;
      zm[c] -= h;
      double t1, t2;
      const std::vector<double> rp = residuals_at(zp, &t1, &t2);
      const std::vector<double> rm = residuals_at(zm, &t1, &t2);
      for (int k = 0; k < 4; ++k) J(k, c) = (rp[k] - rm[k]) / (2.0 * h);
    }
    const Eigen::Vector4d step = J.partialPivLu().solve(-Eigen::Vector4d(r[0], r[1], r[2], r[3]));
    double lambda = 1.0;
    bool accepted = false;
    for (int halving = 0; halving < 30 && !accepted; ++halving, lambda *= 0.5) {
      const Eigen::Vector4d trial = z + lambda * step;
      if (!admissible(trial)) continue;
      const std::vector<double> rt = residuals_at(trial, &A1, &A2);
      if (norm(rt) < norm(r)) {
        z = trial;
        r = rt;
        accepted = true;
      }
    }
    if (!accepted) break;
  }
  residuals_at(z, &A1, &A2);
  out = {z[0], a2_of(z[1]), z[2], z[3], A1, A2, norm(r) <= 1e-12 && admissible(z)};
  return out;
}

}  // namespace punchsweep::model
