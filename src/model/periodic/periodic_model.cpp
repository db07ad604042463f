#include "model/periodic/periodic_model.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "model/numerics/integer_power.hpp"

namespace punchsweep::model {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

PeriodicScales::PeriodicScales(const ContactProblem& problem)
    : X_unit(problem.shape.C * ipow(problem.l, problem.shape.s - 1)),
      h_unit(X_unit * problem.l),
      Q_unit(h_unit * problem.l),
      l(problem.l) {}

PeriodicSingleLevel::PeriodicSingleLevel(const ContactProblem& problem)
    : table_(&periodic_solution(problem.shape.s)), scales_(problem) {}

double PeriodicSingleLevel::contact_radius(double X) const {
  if (!std::isfinite(X)) return scales_.l / std::sqrt(std::numbers::pi);
  return scales_.l * table_->single(X / scales_.X_unit).a1;
}

double PeriodicSingleLevel::displacement_difference(double /*a1*/, double X) const {
  if (!std::isfinite(X)) return scales_.h_unit * table_->delta_hidden();
  return scales_.h_unit * table_->single(X / scales_.X_unit).h;
}

PeriodicSingleLevel::State PeriodicSingleLevel::state(double X) const {
  if (!std::isfinite(X)) return {contact_radius(X), kInf};
  const PeriodicState s = table_->single(X / scales_.X_unit);
  return {scales_.l * s.a1, scales_.h_unit * s.h};
}

Touchdown PeriodicSingleLevel::touchdown(double dh) const {
  Touchdown t;
  t.X_star = table_->touchdown(dh / scales_.h_unit) * scales_.X_unit;
  t.a1_star = std::isfinite(t.X_star) ? contact_radius(t.X_star) : contact_radius(kInf);
  return t;
}

PeriodicBranch::PeriodicBranch(const ContactProblem& problem, const Touchdown& touch)
    : table_(&periodic_solution(problem.shape.s)),
      scales_(problem),
      row_(table_->row(problem.dh / scales_.h_unit, touch.X_star / scales_.X_unit)),
      X_star_(touch.X_star) {}

bool PeriodicBranch::covered() const { return row_.delta <= table_->delta_top() || !std::isfinite(X_star_); }

TwoLevelSolve PeriodicBranch::at(double X) const {
  const double l2 = scales_.l * scales_.l;
  if (X < X_star_) {
    // Level 2 still free: the single level's state.
    const PeriodicState s = table_->single(X / scales_.X_unit);
    return {{scales_.l * s.a1, 0.0, l2 * X, 0.0}, true};
  }
  if (!covered()) return {{kNaN, kNaN, kNaN, kNaN}, false};
  if (!std::isfinite(X)) {
    // Every node in contact: the areas are the levels' shares of the cell.
    const PeriodicState full = table_->tables().two_level(kInf, row_.table);
    return {{scales_.l * full.a1, scales_.l * full.a2, kInf, kInf}, true};
  }
  const PeriodicState s = table_->two_level(X / scales_.X_unit, row_);
  // One height (dh = 0): the levels alike, each carrying half the load, exactly.
  TwoLevelState state{scales_.l * s.a1, scales_.l * s.a2, 0.0, row_.delta == 0.0 ? 0.5 * l2 * X : scales_.Q_unit * s.Q2};
  state.Q1 = l2 * X - state.Q2;  // the cell's load balance, exactly
  return {state, true};
}

bool PeriodicBranch::pressure_monotone(double X_a, double X_b) const {
  if (!std::isfinite(X_b)) X_b = std::numeric_limits<double>::max();
  return table_->pressure_monotone(X_a / scales_.X_unit, X_b / scales_.X_unit, row_);
}

}  // namespace punchsweep::model
