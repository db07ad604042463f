#include "model/long_term_guide.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "model/lattice.hpp"
#include "model/regime.hpp"
#include "model/single_level.hpp"

namespace punchsweep::model {
namespace {

NominalRadii touchdown_radii(double l) {
  const Lattice lattice{l};
  return NominalRadii{lattice.A1_single(), lattice.A_single()};
}

// Chebyshev points of the first kind on [-1, 1], cos((2k+1) pi / (2n)), and their
// barycentric weights (-1)^k sin((2k+1) pi / (2n)); computed once.
template <int N>
struct ChebyshevTable {
  double node[N];
  double weight[N];
  ChebyshevTable() {
    for (int k = 0; k < N; ++k) {
      const double angle = (2.0 * k + 1.0) * std::numbers::pi / (2.0 * N);
      node[k] = std::cos(angle);
      weight[k] = ((k % 2) ? -1.0 : 1.0) * std::sin(angle);
    }
  }
};

}  // namespace

LongTermGuide::LongTermGuide(const ContactProblem& problem)
    : problem_(problem),
      system_(problem, touchdown_radii(problem.l)),
      z_power_(problem.shape.s == 1 ? 1 : 2) {
  const Touchdown touch = touchdown(SingleLevel(problem.l, problem.shape), problem.dh);
  X_star_ = touch.X_star;
  usable_ = X_star_ > 0.0 && std::isfinite(X_star_);
  touch_state_ = TwoLevelState{touch.a1_star, 0.0, problem.l * problem.l * X_star_, 0.0};
  last_state_ = touch_state_;
  last_X_ = X_star_;
}

bool LongTermGuide::build_next() const {
  const int j = static_cast<int>(segments_.size());
  const double X_lo = j == 0 ? X_star_ : X_star_ * std::ldexp(1.0, j);
  const double X_hi = X_star_ * std::ldexp(1.0, j + 1);
  static const ChebyshevTable<kNodes> cheb;
  Segment seg;
  seg.v_lo = std::sqrt(X_lo - X_star_);
  seg.v_hi = std::sqrt(X_hi - X_star_);
  // Nodes in increasing X, each solved by continuation from the previous solution.
  TwoLevelState state = last_state_;
  double X = last_X_;
  for (int i = kNodes - 1; i >= 0; --i) {
    const double t = cheb.node[i];  // increasing as i decreases
    const double v = 0.5 * (seg.v_lo + seg.v_hi) + 0.5 * (seg.v_hi - seg.v_lo) * t;
    const double X_node = X_star_ + v * v;
    const TwoLevelSolve r = system_.continue_to(state, X, X_node);
    if (!r.converged) return false;
    state = r.state;
    X = X_node;
    seg.a1[i] = state.a1;
    seg.z[i] = z_power_ == 2 ? state.a2 * state.a2 : state.a2;
  }
  const TwoLevelSolve end = system_.continue_to(state, X, X_hi);
  if (!end.converged) return false;
  last_state_ = end.state;
  last_X_ = X_hi;
  segments_.push_back(seg);
  return true;
}

std::optional<TwoLevelState> LongTermGuide::guess(double X) const {
  if (!usable_ || !(X > X_star_) || !std::isfinite(X)) return std::nullopt;
  int exponent = 0;
  std::frexp(X / X_star_, &exponent);  // X / X* = m 2^exponent, m in [0.5, 1): segment exponent - 1
  const int j = std::max(0, exponent - 1);
  if (j >= kMaxSegments) return std::nullopt;
  while (static_cast<int>(segments_.size()) <= j) {
    if (exhausted_ || !build_next()) {
      exhausted_ = true;
      return std::nullopt;
    }
  }
  static const ChebyshevTable<kNodes> cheb;
  const Segment& seg = segments_[static_cast<std::size_t>(j)];
  const double v = std::sqrt(X - X_star_);
  const double t = std::clamp((2.0 * v - seg.v_lo - seg.v_hi) / (seg.v_hi - seg.v_lo), -1.0, 1.0);
  // Chebyshev interpolation through the node values (barycentric form, first kind).
  double num_a1 = 0.0;
  double num_z = 0.0;
  double den = 0.0;
  for (int k = 0; k < kNodes; ++k) {
    const double d = t - cheb.node[k];
    if (d == 0.0) return TwoLevelState{seg.a1[k], z_power_ == 2 ? std::sqrt(std::max(seg.z[k], 0.0)) : seg.z[k], 0, 0};
    const double w = cheb.weight[k] / d;
    num_a1 += w * seg.a1[k];
    num_z += w * seg.z[k];
    den += w;
  }
  const double z = std::max(num_z / den, 0.0);
  return TwoLevelState{num_a1 / den, z_power_ == 2 ? std::sqrt(z) : z, 0.0, 0.0};
}

}  // namespace punchsweep::model
