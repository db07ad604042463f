#include "model/paper/long_term_guide.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "model/numerics/lattice.hpp"
#include "model/contact/regime.hpp"
#include "model/paper/single_level.hpp"

namespace punchsweep::model {
namespace {

NominalRadii touchdown_radii(double l) {
  const Lattice lattice{l};
  return NominalRadii{lattice.A1_single(), lattice.A_single()};
}

// Chebyshev points of the first kind on [-1, 1], node[k] = cos((2k+1) pi / (2n)), and the
// matrix that turns values at them into Chebyshev coefficients (the first one halved, so
// that f = sum_j c_j T_j); computed once.
template <int N>
struct ChebyshevTable {
  double node[N];
  double to_coefficient[N][N];
  ChebyshevTable() {
    for (int k = 0; k < N; ++k) node[k] = std::cos((2.0 * k + 1.0) * std::numbers::pi / (2.0 * N));
    for (int j = 0; j < N; ++j) {
      for (int k = 0; k < N; ++k) {
        to_coefficient[j][k] = (j == 0 ? 1.0 : 2.0) / N * std::cos(j * (2.0 * k + 1.0) * std::numbers::pi / (2.0 * N));
      }
    }
  }
  // Node values -> coefficients, in place.
  void transform(double* f) const {
    double c[N] = {};
    for (int j = 0; j < N; ++j) {
      for (int k = 0; k < N; ++k) c[j] += to_coefficient[j][k] * f[k];
    }
    std::copy(c, c + N, f);
  }
};

// sum_j c_j T_j(t) by Clenshaw's recurrence (no divisions: the guess is made at every point
// of a regime map).
template <int N>
double clenshaw(const double* c, double t) {
  double b1 = 0.0;
  double b2 = 0.0;
  for (int j = N - 1; j >= 1; --j) {
    const double b0 = c[j] + 2.0 * t * b1 - b2;
    b2 = b1;
    b1 = b0;
  }
  return c[0] + t * b1 - b2;
}

}  // namespace

LongTermGuide::LongTermGuide(const ContactProblem& problem)
    : problem_(problem),
      system_(problem, touchdown_radii(problem.l)),
      z_power_(problem.shape.s == 1 ? 1 : 2) {
  const Touchdown touch = touchdown(SingleLevel(problem.l, problem.shape), problem.dh);
  X_star_ = touch.X_star;
  inv_X_star_ = 1.0 / X_star_;
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
  seg.inv_width = 1.0 / (seg.v_hi - seg.v_lo);
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
    const std::array<double, 4> rate = system_.root_radii_rates(state.a1, state.a2, X_node);
    for (int k = 0; k < 4; ++k) seg.rate[k][i] = rate[static_cast<std::size_t>(k)];
  }
  cheb.transform(seg.a1);
  cheb.transform(seg.z);
  for (auto& rate : seg.rate) cheb.transform(rate);
  const TwoLevelSolve end = system_.continue_to(state, X, X_hi);
  if (!end.converged) return false;
  last_state_ = end.state;
  last_X_ = X_hi;
  segments_.push_back(seg);
  return true;
}

std::optional<TwoLevelState> LongTermGuide::guess(double X) const { return guess(X, system_.radii()); }

std::optional<TwoLevelState> LongTermGuide::guess(double X, const NominalRadii& radii) const {
  if (!usable_ || !(X > X_star_) || !std::isfinite(X)) return std::nullopt;
  int exponent = 0;
  std::frexp(X * inv_X_star_, &exponent);  // X / X* = m 2^exponent, m in [0.5, 1): segment exponent - 1
  const int j = std::max(0, exponent - 1);
  if (j >= kMaxSegments) return std::nullopt;
  while (static_cast<int>(segments_.size()) <= j) {
    if (exhausted_ || !build_next()) {
      exhausted_ = true;
      return std::nullopt;
    }
  }
  const Segment& seg = segments_[static_cast<std::size_t>(j)];
  const double v = std::sqrt(X - X_star_);
  const double t = std::clamp((2.0 * v - seg.v_lo - seg.v_hi) * seg.inv_width, -1.0, 1.0);
  double a1 = clenshaw<kNodes>(seg.a1, t);
  double z = clenshaw<kNodes>(seg.z, t);
  const double dA1 = radii.A1 - system_.radii().A1;
  const double dA2 = radii.A2 - system_.radii().A2;
  if (dA1 != 0.0 || dA2 != 0.0) {
    a1 += clenshaw<kNodes>(seg.rate[0], t) * dA1 + clenshaw<kNodes>(seg.rate[1], t) * dA2;
    z += clenshaw<kNodes>(seg.rate[2], t) * dA1 + clenshaw<kNodes>(seg.rate[3], t) * dA2;
  }
  z = std::max(z, 0.0);
  return TwoLevelState{a1, z_power_ == 2 ? std::sqrt(z) : z, 0.0, 0.0};
}

}  // namespace punchsweep::model
