#include "reference/contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace punchsweep::reference {

ContactSolver::ContactSolver(const PeriodicGrid& grid, ContactSolverOptions options)
    : options_(options),
      influence_(grid),
      gap_(grid.size()),
      direction_(grid.size()),
      response_(grid.size()),
      weight_(grid.size()),
      preconditioned_(options.precondition ? grid.size() : 0) {
  for (std::size_t k = 0; k < grid.size(); ++k) weight_[k] = grid.multiplicity(k);
}

ContactSolution ContactSolver::solve(std::span<const double> profile, double mean_pressure,
                                     double compliance) {
  ContactSolution solution;
  solution.pressure.assign(grid().size(), mean_pressure);
  solution.displacement.assign(grid().size(), 0.0);
  solution.status =
      solve(profile, mean_pressure, compliance, solution.pressure, solution.displacement);
  return solution;
}

ContactStatus ContactSolver::solve(std::span<const double> profile, double mean_pressure,
                                   double compliance, std::span<double> p, std::span<double> u) {
  const std::size_t n = grid().size();
  if (profile.size() != n || p.size() != n || u.size() != n) {
    throw std::invalid_argument("ContactSolver::solve: array size differs from the grid");
  }
  if (!(mean_pressure > 0.0) || !(compliance > 0.0)) {
    throw std::invalid_argument("ContactSolver::solve: mean pressure and compliance must be > 0");
  }
  // Sums over the cell: over the stored nodes, each weighted by its multiplicity (1 on a
  // whole grid: the weighted sums below are then the plain ones, bit for bit).
  const double nd = static_cast<double>(grid().nodes());
  const std::vector<double>& m = weight_;

  // First guess: the given field scaled to the prescribed mean, or the uniform one.
  double sum_p = 0.0;
  bool usable = true;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(p[i] >= 0.0) || !std::isfinite(p[i])) usable = false;
    sum_p += m[i] * p[i];
  }
  if (usable && sum_p > 0.0) {
    const double scale = mean_pressure * nd / sum_p;
    for (std::size_t i = 0; i < n; ++i) p[i] *= scale;
  } else {
    std::fill(p.begin(), p.end(), mean_pressure);
  }

  // The profile's own range: the scale of a residual where u has none yet (the uniform
  // field's u is flat), so that the test is scale-free at any relief.
  const auto [profile_min, profile_max] = std::minmax_element(profile.begin(), profile.end());
  const double relief = *profile_max - *profile_min;

  std::vector<double>& g = gap_;
  std::vector<double>& t = direction_;
  std::vector<double>& r = response_;
  std::vector<double>& z = preconditioned_;
  std::fill(t.begin(), t.end(), 0.0);
  double G_old = 1.0;
  bool conjugate = false;
  // The load-control rescaling of p is applied lazily, at the top of the next iteration,
  // where K p is needed anyway (K is linear): one pass over the arrays fewer.
  double pending_scale = 1.0;
  // K is linear: after a step that neither clipped a pressure to zero nor added a node,
  // p_new = p - tau t exactly and K p_new = u - tau r needs no transform (half of an
  // iteration's work). The update's round-off grows by about 1e-16 of u per iteration, far
  // below any tolerance, and a solve that passes its test on an updated u is tested again
  // on a transformed one before it returns, so the answer and its residual are K p's.
  bool linear_step = false;
  ContactStatus status;

  for (int it = 0;; ++it) {
    // After a linear step u is K p's update, still to be rescaled with p.
    const double u_scale = linear_step ? pending_scale : 1.0;
    if (!linear_step) influence_.apply(p, u, compliance * pending_scale);
    // Gap up to the approach; the approach is its mean over the contact set I_c = {p > 0}.
    double sum_g = 0.0;
    double n_contact = 0.0;
    double u_min = std::numeric_limits<double>::infinity();
    double u_max = -u_min;
    for (std::size_t i = 0; i < n; ++i) {
      p[i] *= pending_scale;
      u[i] *= u_scale;
      g[i] = u[i] + profile[i];
      u_min = std::min(u_min, u[i]);
      u_max = std::max(u_max, u[i]);
      if (p[i] > 0.0) {
        sum_g += m[i] * g[i];
        n_contact += m[i];
      }
    }
    pending_scale = 1.0;
    const double approach = sum_g / n_contact;
    double violation = 0.0;
    double G = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      g[i] -= approach;
      if (p[i] > 0.0) {
        violation = std::max(violation, std::abs(g[i]));
        G += m[i] * g[i] * g[i];
      } else {
        violation = std::max(violation, -g[i]);
      }
      if (options_.precondition) z[i] = p[i] > 0.0 ? g[i] : 0.0;
    }
    const double range = u_max - u_min;
    status.approach = approach;
    status.iterations = it;
    // (A flat u, the uniform field's, took the violation as it was: a texture whose relief
    // is below the tolerance, 1e-11 R at s = 10 and l = 0.16 R, passed the uniform field
    // as full contact at any load.)
    status.residual = range > 0.0 ? violation / range : relief > 0.0 ? violation / relief : violation;
    if (status.residual <= options_.tolerance) {
      if (linear_step) {  // test again on u = c K p itself
        linear_step = false;
        pending_scale = 1.0;
        --it;
        continue;
      }
      status.converged = true;
      return status;
    }
    if (it >= options_.max_iterations) return status;

    // Preconditioned: the descent is z = S g on the contact set about its mean there (S,
    // the half-space's stiffness), and G = g.z measures the residual in its norm (g sums to
    // zero over the contact set, so the mean drops out of G).
    double mean_z = 0.0;
    if (options_.precondition) {
      influence_.apply_stiffness(z, z, 1.0 / compliance);
      double sum_z = 0.0;
      G = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        if (p[i] > 0.0) {
          sum_z += m[i] * z[i];
          G += m[i] * g[i] * z[i];
        }
      }
      mean_z = sum_z / n_contact;
    }
    const std::vector<double>& descent = options_.precondition ? z : g;
    // Conjugate direction on the contact set (PK eq. 3.4): restart after an overlap correction.
    const double beta = conjugate ? G / G_old : 0.0;
    for (std::size_t i = 0; i < n; ++i) t[i] = p[i] > 0.0 ? descent[i] - mean_z + beta * t[i] : 0.0;
    G_old = G;

    // Step length on the contact set, with the response r = c K t taken about its mean there.
    influence_.apply(t, r, compliance);
    double sum_r = 0.0, sum_t = 0.0, gt = 0.0, rt_raw = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (p[i] > 0.0) {
        sum_r += m[i] * r[i];
        sum_t += m[i] * t[i];
        gt += m[i] * g[i] * t[i];
        rt_raw += m[i] * r[i] * t[i];
      }
    }
    const double rt = rt_raw - sum_r / n_contact * sum_t;
    if (!(rt > 0.0)) return status;  // no descent left at round-off level
    const double tau = gt / rt;

    // Step, project onto p >= 0, and move pressure onto penetrating free nodes (PK eq. 3.7).
    bool overlap = false;
    bool clipped = false;
    sum_p = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      u[i] -= tau * r[i];  // K p's update, kept only after a linear step
      if (p[i] > 0.0) {
        const double stepped = p[i] - tau * t[i];
        clipped = clipped || !(stepped > 0.0);
        p[i] = std::max(stepped, 0.0);
      }
      if (p[i] == 0.0 && g[i] < 0.0) {
        p[i] = -tau * g[i];
        overlap = true;
      }
      sum_p += m[i] * p[i];
    }
    conjugate = !overlap;
    linear_step = !overlap && !clipped;

    // Load control: rescale to the prescribed mean pressure (PK eq. 3.8).
    if (!(sum_p > 0.0)) return status;
    pending_scale = mean_pressure * nd / sum_p;
  }
}

}  // namespace punchsweep::reference
