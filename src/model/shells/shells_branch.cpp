#include "model/shells/shells_branch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "model/numerics/chebyshev.hpp"
#include "model/paper/elastic_two_level.hpp"

namespace punchsweep::model {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
/// Segments beyond X* 2^kMaxSegments are not built (the spots merge long before).
constexpr int kMaxSegments = 64;
/// A piece is halved at most this many times below its segment (then taken as it is).
constexpr int kMaxDepth = 12;
/// Where the interpolant is checked against Newton roots, in the piece's unit variable:
/// between its nodes, and near both ends where Chebyshev interpolation errs most.
constexpr double kChecks[] = {-0.96, 0.0, 0.5, 0.96};
/// The end of the curve is bracketed to this, relative in X, or found where the spots' gap
/// to the merge margin is below kGapTolerance l.
constexpr double kEndTolerance = 1e-12;
constexpr double kGapTolerance = 1e-13;
/// A failed root is taken as beyond the curve's end without following the curve to it only
/// where the spots' gap is below this (in l) and closing, or (in the end search) where the
/// step is shorter than kLongStep X.
constexpr double kNearEnd = 0.01;
constexpr double kLongStep = 1e-3;

}  // namespace

ShellsBranch::ShellsBranch(const ContactProblem& problem, const Touchdown& touch)
    : problem_(problem),
      system_(problem, problem.localization),
      X_star_(touch.X_star),
      l2_(problem.l * problem.l),
      z_scale_(problem.shape.s >= 2 ? problem.l * problem.l : problem.l),
      usable_(touch.X_star > 0.0 && std::isfinite(touch.X_star)),
      X_end_(kInf) {
  last_ = TwoLevelState{touch.a1_star, 0.0, l2_ * X_star_, 0.0};
  X_last_ = X_star_;
  end_state_ = last_;
}

TwoLevelState ShellsBranch::state_of(const Piece& piece, double v) const {
  const double t = chebyshev::unit(v, piece.v_lo, piece.v_hi);
  const double X = X_of(v);
  const double z = std::max(chebyshev::clenshaw(piece.z, kNodes, t), 0.0);
  const double Q1 = chebyshev::clenshaw(piece.q1, kNodes, t) * X * l2_;
  return TwoLevelState{chebyshev::clenshaw(piece.a1, kNodes, t), a2_of(z), Q1, X * l2_ - Q1};
}

TwoLevelState ShellsBranch::predict(double X, const Root& last, const Root* before) const {
  const double scale = X / last.X;
  const TwoLevelState& p = last.state;
  const TwoLevelState plain{p.a1, p.a2, p.Q1 * scale, p.Q2 * scale};
  if (before == nullptr || !(last.X > before->X)) return plain;
  // Linear in v through the two roots, in the curve's smooth variables (a1, z, q1).
  const double v = std::sqrt(X - X_star_);
  const double v1 = std::sqrt(last.X - X_star_);
  const double v0 = std::sqrt(before->X - X_star_);
  const double w = (v - v1) / (v1 - v0);
  const auto q = [this](const Root& r) { return r.state.Q1 / (r.X * l2_); };
  const double a1 = p.a1 + w * (p.a1 - before->state.a1);
  const double z = std::max(z_of(p.a2) + w * (z_of(p.a2) - z_of(before->state.a2)), 0.0);
  const double q1 = q(last) + w * (q(last) - q(*before));
  const TwoLevelState linear{a1, a2_of(z), q1 * X * l2_, (1.0 - q1) * X * l2_};
  // Not past the merge margin (where the sums leave their tables).
  return gap(linear) > 0.0 ? linear : plain;
}

double ShellsBranch::gap(const TwoLevelState& state) const {
  const double reach = problem_.localization.merge_margin();
  const double x1 = state.a1 / problem_.l;
  const double x2 = state.a2 / problem_.l;
  return std::min({reach - 2.0 * x1, reach - 2.0 * x2, reach / std::numbers::sqrt2 - x1 - x2});
}

TwoLevelSolve ShellsBranch::newton(double X, const TwoLevelState& guess) const {
  if (solves_ >= kMaxSolves) return {guess, false};
  ++solves_;
  return system_.solve(X, guess);
}

TwoLevelSolve ShellsBranch::continuation(const Root& from, double X) const {
  if (solves_ >= kMaxSolves) return {from.state, false};
  return system_.continue_to(from.state, from.X, X, std::min(kMaxContinuationSolves, kMaxSolves - solves_), &solves_);
}

TwoLevelSolve ShellsBranch::root(double X, const TwoLevelState& guess, const Root& from, const Root* before) const {
  ++roots_;
  TwoLevelSolve r = newton(X, guess);
  if (r.converged) return r;
  // Continuation from `from`, unless the spots' gap, extrapolated from the two roots before,
  // closes before X: then the curve has ended (the end search finds where), and following
  // it there would only fail, step after halved step.
  if (before != nullptr && from.X > before->X && from.gap < kNearEnd) {
    const double slope = (from.gap - before->gap) / (from.X - before->X);
    if (from.gap + slope * (X - from.X) < 0.0) return r;
  }
  return continuation(from, X);
}

bool ShellsBranch::build_pieces(double v_lo, double v_hi, int depth, Failure* failure, const Root* end_root) const {
  Piece piece;
  piece.v_lo = v_lo;
  piece.v_hi = v_hi;
  // Nodes in increasing v (chebyshev::nodes runs downward), each from the root before,
  // its loads scaled to the new nominal load.
  const std::vector<double> v_nodes = chebyshev::nodes(kNodes, v_lo, v_hi);
  double values[3][kNodes];
  const Root start{X_last_, last_, gap(last_)};
  Root previous = start;
  std::optional<Root> before;
  const auto failed = [&](double X, const Root& below, const std::optional<Root>& under) {
    *failure = Failure{X, below, under};
    return false;
  };
  for (int j = kNodes - 1; j >= 0; --j) {
    const double X = X_of(v_nodes[j]);
    const TwoLevelSolve r = root(X, predict(X, previous, before ? &*before : nullptr), previous,
                                 before ? &*before : nullptr);
    if (!r.converged) return failed(X, previous, before);
    before = previous;
    previous = Root{X, r.state, gap(r.state)};
    values[0][j] = r.state.a1;
    values[1][j] = z_of(r.state.a2);
    values[2][j] = r.state.Q1 / (X * l2_);
  }
  for (int k = 0; k < 3; ++k) {
    const std::vector<double> c = chebyshev::coefficients(values[k], kNodes);
    std::copy(c.begin(), c.end(), k == 0 ? piece.a1 : k == 1 ? piece.z : piece.q1);
  }
  bool good = true;
  for (const double t : kChecks) {
    const double v = 0.5 * (v_lo + v_hi) + 0.5 * (v_hi - v_lo) * t;
    const double X = X_of(v);
    const TwoLevelState guess = state_of(piece, v);
    const TwoLevelSolve r = root(X, guess, start, nullptr);
    if (!r.converged) return failed(X, start, std::nullopt);
    good = good && std::abs(guess.a1 - r.state.a1) <= kTolerance * problem_.l &&
           std::abs(z_of(guess.a2) - z_of(r.state.a2)) <= kTolerance * z_scale_ &&
           std::abs(guess.Q1 - r.state.Q1) <= kTolerance * X * l2_;
  }
  if (!good && depth < kMaxDepth) {
    const double v_mid = 0.5 * (v_lo + v_hi);
    return build_pieces(v_lo, v_mid, depth + 1, failure) &&
           build_pieces(v_mid, v_hi, depth + 1, failure, end_root);
  }
  // The root at the piece's end starts the next piece (at the curve's end it is known).
  const double X_hi = X_of(v_hi);
  const TwoLevelSolve end = end_root != nullptr ? TwoLevelSolve{end_root->state, true}
                                                : root(X_hi, state_of(piece, v_hi), previous, before ? &*before : nullptr);
  if (!end.converged) return failed(X_hi, previous, before);
  pieces_.push_back(piece);
  last_ = end.state;
  X_last_ = end_root != nullptr ? end_root->X : X_hi;
  return true;
}

bool ShellsBranch::build_next() const {
  const int j = segments_built_;
  const double X_lo = j == 0 ? X_star_ : std::ldexp(X_star_, j);
  const double X_hi = std::ldexp(X_star_, j + 1);
  Failure failure{X_lo, Root{X_last_, last_, gap(last_)}, std::nullopt};
  if (j < kMaxSegments && build_pieces(std::sqrt(X_lo - X_star_), std::sqrt(X_hi - X_star_), 0, &failure)) {
    ++segments_built_;
    return true;
  }
  // The curve ends between the failure and the root below it. Where its spots reach the
  // merge margin (the usual end) the gap closes smoothly: secant steps on it from the two
  // highest roots find the end in a few roots; else (or where a step overshoots) bisection.
  // Each root by Newton from the highest one: the steps shrink, so a failure is the end.
  Root good = failure.below;
  Root under = failure.under.value_or(Root{good.X, good.state, -1.0});  // gap < 0: none
  double X_bad = failure.X;
  while (X_bad - good.X > kEndTolerance * X_bad && good.gap > kGapTolerance) {
    double X = 0.5 * (good.X + X_bad);
    if (under.gap > good.gap) {
      const double secant = good.X + good.gap * (good.X - under.X) / (under.gap - good.gap);
      if (secant > good.X && secant < X_bad) X = secant;
    }
    ++roots_;
    TwoLevelSolve r = newton(X, predict(X, good, under.gap >= 0.0 ? &under : nullptr));
    // A long step may fail where the curve goes on: follow it there (near the end, where the
    // steps are short, a failure is the end).
    if (!r.converged && X - good.X > kLongStep * X) r = continuation(good, X);
    if (r.converged) {
      under = good;
      good = Root{X, r.state, gap(r.state)};
    } else {
      X_bad = X;
      under.gap = -1.0;  // the next step bisects
    }
  }
  X_end_ = good.X;
  end_state_ = good.state;
  if (X_end_ > X_last_ &&
      !build_pieces(std::sqrt(X_last_ - X_star_), std::sqrt(X_end_ - X_star_), 0, &failure, &good)) {
    // Not expected (every root below X_end_ was found once): end where the pieces do.
    X_end_ = X_last_;
    end_state_ = last_;
  }
  segments_built_ = kMaxSegments;
  return false;
}

TwoLevelSolve ShellsBranch::at(double X) const {
  if (!usable_) {
    // No touchdown to start from (dh = 0: level 2 touches at once; X* infinite: never):
    // Newton from the paper's elastic state at X.
    ContactProblem paper = problem_;
    paper.pbar0 = X;
    paper.localization = Localization{};
    const ElasticTwoLevel guess = solve_elastic_two_level(paper, 1.0);
    if (!guess.converged || !guess.level2_touches) return {last_, false};
    return system_.solve(X, TwoLevelState{guess.state.a1, guess.state.a2, 0.0, 0.0});
  }
  if (!(X <= X_end_)) return {end_state_, false};
  const double v = std::sqrt(std::max(X - X_star_, 0.0));
  while ((pieces_.empty() || v > pieces_.back().v_hi) && segments_built_ < kMaxSegments) build_next();
  if (!(X <= X_end_) || pieces_.empty()) return {end_state_, false};
  const auto piece = std::upper_bound(pieces_.begin(), pieces_.end(), v,
                                      [](double value, const Piece& p) { return value < p.v_hi; });
  return {state_of(piece == pieces_.end() ? pieces_.back() : *piece, v), true};
}

}  // namespace punchsweep::model
