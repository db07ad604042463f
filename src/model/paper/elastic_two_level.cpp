#include "model/paper/elastic_two_level.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <Eigen/Dense>

#include "model/numerics/integer_power.hpp"
#include "model/numerics/lattice.hpp"
#include "model/paper/long_term_guide.hpp"
#include "model/contact/regime.hpp"
#include "model/numerics/ring_loads.hpp"
#include "model/paper/single_level.hpp"

namespace punchsweep::model {

std::optional<ElasticTwoLevel> solve_elastic_jointly(const ContactProblem& problem, double X,
                                                     const TwoLevelState& start, NominalRadii radii) {
  const double l = problem.l;
  const double l2 = l / std::numbers::sqrt2;
  const int z_power = problem.shape.s == 1 ? 1 : 2;
  const double z_scale = z_power == 2 ? l * l : l;
  const double scale = 1.0 / (l * l * X);
  auto to_a2 = [&](double z) { return z_power == 2 ? std::sqrt(z) : z; };

  struct Point {
    Eigen::Vector4d u;  // a1, z, A1, A2
    Eigen::Vector4d F;
    Eigen::Matrix4d DF;
    Eigen::Matrix<double, 2, 4> dQ;
    double Q[2];
    double norm;
  };
  auto at = [&](const Eigen::Vector4d& u) -> std::optional<Point> {
    const double a1 = u[0];
    const double a2 = to_a2(std::max(u[1], 0.0));
    if (!(a1 > 0.0 && u[1] >= 0.0 && a1 < std::min(l2, u[2]) * kTwoLevelDomainMargin &&
          a2 < std::min(l2, u[3]) * kTwoLevelDomainMargin)) {
      return std::nullopt;
    }
    const TwoLevelSystem system(problem, NominalRadii{u[2], u[3]});
    const TwoLevelSystem::Linearization lin = system.linearize(a1, a2, X);
    Point p;
    p.u = u;
    p.Q[0] = lin.Q[0];
    p.Q[1] = lin.Q[1];
    p.dQ << lin.Q_a[0], lin.Q_a[1], lin.Q_A[0], lin.Q_A[1], lin.Q_a[2], lin.Q_a[3], lin.Q_A[2], lin.Q_A[3];
    p.F << lin.r[0], lin.r[1], (std::numbers::pi * X * u[2] * u[2] - 5.0 * lin.Q[0] - 4.0 * lin.Q[1]) * scale,
        (std::numbers::pi * X * u[3] * u[3] - 5.0 * lin.Q[1] - 4.0 * lin.Q[0]) * scale;
    p.DF.row(0) << lin.r_a[0], lin.r_a[1], lin.r_A[0], lin.r_A[1];
    p.DF.row(1) << lin.r_a[2], lin.r_a[3], lin.r_A[2], lin.r_A[3];
    p.DF.row(2) = -(5.0 * p.dQ.row(0) + 4.0 * p.dQ.row(1)) * scale;
    p.DF.row(3) = -(5.0 * p.dQ.row(1) + 4.0 * p.dQ.row(0)) * scale;
    p.DF(2, 2) += 2.0 * std::numbers::pi * u[2] / (l * l);
    p.DF(3, 3) += 2.0 * std::numbers::pi * u[3] / (l * l);
    p.norm = p.F.cwiseAbs().maxCoeff();
    if (!std::isfinite(p.norm)) return std::nullopt;
    return p;
  };

  std::optional<Point> current =
      at(Eigen::Vector4d(start.a1, z_power == 2 ? start.a2 * start.a2 : start.a2, radii.A1, radii.A2));
  if (!current) return std::nullopt;
  const Eigen::Vector4d relative(1.0 / l, 1.0 / z_scale, 1.0 / l, 1.0 / l);
  for (int it = 0; it < TwoLevelSystem::kMaxIterations; ++it) {
    const Eigen::Vector4d d = -current->DF.partialPivLu().solve(current->F);
    if (!d.allFinite()) return std::nullopt;
    const double size = d.cwiseProduct(relative).cwiseAbs().maxCoeff();
    if (size < TwoLevelSystem::kFinalStep && current->norm < TwoLevelSystem::kResidualTolerance * 1e3) {
      // The last step, taken unevaluated (as in TwoLevelSystem::solve).
      const Eigen::Vector4d u = current->u + d;
      const Eigen::Vector2d Q = Eigen::Vector2d(current->Q[0], current->Q[1]) + current->dQ * d;
      if (!(u[0] > 0.0 && u[1] >= 0.0)) return std::nullopt;
      return ElasticTwoLevel{TwoLevelState{u[0], to_a2(u[1]), Q[0], Q[1]}, NominalRadii{u[2], u[3]}, true, true};
    }
    std::optional<Point> next;
    double lambda = 1.0;
    for (int halving = 0; halving < 40 && !next; ++halving, lambda *= 0.5) {
      next = at(current->u + lambda * d);
      if (next && !(next->norm < current->norm || next->norm <= TwoLevelSystem::kResidualTolerance * 1e-3)) {
        next.reset();
      }
    }
    if (!next) return std::nullopt;
    current = next;
    if (lambda * size < TwoLevelSystem::kStepTolerance || current->norm < TwoLevelSystem::kConvergedResidual) break;
  }
  if (!(current->norm < TwoLevelSystem::kResidualTolerance)) return std::nullopt;
  const Eigen::Vector4d& u = current->u;
  return ElasticTwoLevel{TwoLevelState{u[0], to_a2(u[1]), current->Q[0], current->Q[1]}, NominalRadii{u[2], u[3]},
                         true, true};
}

ElasticTwoLevel solve_elastic_two_level(const ContactProblem& problem, double E,
                                        const LongTermGuide* guide) {
  const double X = problem.pbar0 / E;
  const Lattice lattice{problem.l};
  const NominalRadii touchdown_radii{lattice.A1_single(), lattice.A_single()};
  ElasticTwoLevel out;
  out.radii = touchdown_radii;

  const SingleLevel single(problem.l, problem.shape);
  const double a1_single = single.contact_radius(X);
  if (single.displacement_difference(a1_single, X) < problem.dh) {
    // Level 2 does not touch: the single-level solution, with its own radii (eq 9.3).
    out.state = TwoLevelState{a1_single, 0.0, problem.l * problem.l * X, 0.0};
    out.converged = true;
    return out;
  }
  out.level2_touches = true;
  // At touchdown eq 9.13 gives exactly the single-level radii, so start there.
  const TwoLevelSystem touchdown_system(problem, touchdown_radii);
  TwoLevelSolve current{TwoLevelState{}, false};
  if (guide != nullptr) {
    if (const std::optional<TwoLevelState> start = guide->guess(X)) {
      if (std::optional<ElasticTwoLevel> joint = solve_elastic_jointly(problem, X, *start, touchdown_radii)) return *joint;
      current = touchdown_system.solve(X, *start);
    }
  }
  if (!current.converged) current = touchdown_system.solve_from_touchdown(X);
  NominalRadii radii = touchdown_radii;
  // One Newton step per update of A (both converge together: Newton quadratically, the
  // A iteration at its small contraction rate), then a full solve at the final radii.
  constexpr int kMaxSweeps = 200;
  for (int sweep = 0; sweep < kMaxSweeps && current.converged; ++sweep) {
    // Eq (9.13): pi A_i^2 pbar = 5 P_i + 4 P_j, with P/E = Q and pbar/E = X.
    const NominalRadii next{std::sqrt((5.0 * current.state.Q1 + 4.0 * current.state.Q2) / (std::numbers::pi * X)),
                            std::sqrt((5.0 * current.state.Q2 + 4.0 * current.state.Q1) / (std::numbers::pi * X))};
    const double change = std::max(std::abs(next.A1 - radii.A1), std::abs(next.A2 - radii.A2));
    radii = next;
    const TwoLevelSystem system(problem, radii);
    if (change < 1e-13 * problem.l) {
      current = system.solve(X, current.state);
      out.state = current.state;
      out.radii = radii;
      out.converged = current.converged;
      return out;
    }
    const TwoLevelSolve step = system.solve(X, current.state, 1);
    current.state = step.state;
    current.converged = std::isfinite(step.state.Q1) && std::isfinite(step.state.a1);
  }
  out.state = current.state;
  out.radii = radii;
  out.converged = false;
  return out;
}

}  // namespace punchsweep::model
