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
      response_(grid.size()) {}

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
  const double nd = static_cast<double>(n);

  // First guess: the given field scaled to the prescribed mean, or the uniform one.
  double sum_p = 0.0;
  bool usable = true;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(p[i] >= 0.0) || !std::isfinite(p[i])) usable = false;
    sum_p += p[i];
  }
  if (usable && sum_p > 0.0) {
    const double scale = mean_pressure * nd / sum_p;
    for (std::size_t i = 0; i < n; ++i) p[i] *= scale;
  } else {
    std::fill(p.begin(), p.end(), mean_pressure);
  }

  std::vector<double>& g = gap_;
  std::vector<double>& t = direction_;
  std::vector<double>& r = response_;
  std::fill(t.begin(), t.end(), 0.0);
  double G_old = 1.0;
  bool conjugate = false;
  // The load-control rescaling of p is applied lazily, at the top of the next iteration,
  // where K p is needed anyway (K is linear): one pass over the arrays fewer.
  double pending_scale = 1.0;
  ContactStatus status;

  for (int it = 0;; ++it) {
    influence_.apply(p, u, compliance * pending_scale);
    // Gap up to the approach; the approach is its mean over the contact set I_c = {p > 0}.
    double sum_g = 0.0;
    std::size_t n_contact = 0;
    double u_min = std::numeric_limits<double>::infinity();
    double u_max = -u_min;
    for (std::size_t i = 0; i < n; ++i) {
      p[i] *= pending_scale;
      g[i] = u[i] + profile[i];
      u_min = std::min(u_min, u[i]);
      u_max = std::max(u_max, u[i]);
      if (p[i] > 0.0) {
        sum_g += g[i];
        ++n_contact;
      }
    }
    pending_scale = 1.0;
    const double approach = sum_g / static_cast<double>(n_contact);
    double violation = 0.0;
    double G = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      g[i] -= approach;
      if (p[i] > 0.0) {
        violation = std::max(violation, std::abs(g[i]));
        G += g[i] * g[i];
      } else {
        violation = std::max(violation, -g[i]);
      }
    }
    const double range = u_max - u_min;
    status.approach = approach;
    status.iterations = it;
    status.residual = range > 0.0 ? violation / range : violation;
    if (status.residual <= options_.tolerance) {
      status.converged = true;
      return status;
    }
    if (it >= options_.max_iterations) return status;

    // Conjugate direction on the contact set (PK eq. 3.4): restart after an overlap correction.
    const double beta = conjugate ? G / G_old : 0.0;
    for (std::size_t i = 0; i < n; ++i) t[i] = p[i] > 0.0 ? g[i] + beta * t[i] : 0.0;
    G_old = G;

    // Step length on the contact set, with the response r = c K t taken about its mean there.
    influence_.apply(t, r, compliance);
    double sum_r = 0.0, sum_t = 0.0, gt = 0.0, rt_raw = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (p[i] > 0.0) {
        sum_r += r[i];
        sum_t += t[i];
        gt += g[i] * t[i];
        rt_raw += r[i] * t[i];
      }
    }
    const double rt = rt_raw - sum_r / static_cast<double>(n_contact) * sum_t;
    if (!(rt > 0.0)) return status;  // no descent left at round-off level
    const double tau = gt / rt;

    // Step, project onto p >= 0, and move pressure onto penetrating free nodes (PK eq. 3.7).
    bool overlap = false;
    sum_p = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (p[i] > 0.0) p[i] = std::max(p[i] - tau * t[i], 0.0);
      if (p[i] == 0.0 && g[i] < 0.0) {
        p[i] = -tau * g[i];
        overlap = true;
      }
      sum_p += p[i];
    }
    conjugate = !overlap;

    // Load control: rescale to the prescribed mean pressure (PK eq. 3.8).
    if (!(sum_p > 0.0)) return status;
    pending_scale = mean_pressure * nd / sum_p;
  }
}

}  // namespace punchsweep::reference
