#include "model/shells/single_level_shells.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "model/numerics/integer_power.hpp"
#include "model/numerics/root_finding.hpp"

namespace punchsweep::model {
namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

SingleLevelShells::SingleLevelShells(double l, Shape shape, Localization localization)
    : l_(l),
      shape_(shape),
      K_P_(load_coefficient(shape)),
      K_d_(depth_coefficient(shape)),
      sums_(&shell_sums(shape.s, localization)) {
  // The level-1 punches of the kept neighbourhoods: about the punch (the same-level sum),
  // and about the square centre (a level-2 site: the cross sum about a bare site), so that
  // the phase joins the two-level one at touchdown.
  A_ = l * std::sqrt((1 + sums_->same_count()) / kPi);
  A_M_ = l * std::sqrt(sums_->cross_count() / kPi);
  // The radius limit: spread neighbours count as merged with the spot at a = l/2 within
  // the merge margin (point loads reach it at the nearest distance, l); below, the first
  // zero of the balance's capacity.
  const double hard = localization.distributed ? 0.5 * Localization::kMergeMargin * l : std::min(l, A_) * (1.0 - 1e-12);
  const auto holds = [&](double a) { return capacity(a, sums(a)) > 0.0; };
  a_limit_ = holds(hard) ? hard : bisect_boundary(holds, 0.0, hard, 1e-15).first;
}

SingleLevelShells::Sums SingleLevelShells::sums(double a) const {
  const ShellSums::Sums punch = sums_->same(a / l_);
  return {punch.carried, punch.depth / l_, sums_->cross(0.0, a / l_).depth / l_};
}

double SingleLevelShells::capacity(double a, const Sums& s) const {
  return l_ * l_ * (1.0 - s.carried) - 2.0 * (A_ * A_ * std::asin(a / A_) - a * std::sqrt(A_ * A_ - a * a));
}

double SingleLevelShells::creep_scaled_pressure(double a1) const {
  if (!(a1 < a_limit_)) return std::numeric_limits<double>::infinity();
  return K_P_ * ipow(a1, shape_.s + 1) / capacity(a1, sums(a1));
}

double SingleLevelShells::displacement_difference(double a1, double X) const {
  const Sums s = sums(a1);
  const double P = X * l_ * l_;
  return K_d_ * ipow(a1, shape_.s) + P * s.depth - 2.0 * X * std::sqrt(A_ * A_ - a1 * a1) -
         (P * s.centre - 2.0 * X * A_M_);
}

double SingleLevelShells::displacement_difference(double a1) const {
  return displacement_difference(a1, creep_scaled_pressure(a1));
}

double SingleLevelShells::displacement_difference_rate(double a1) const {
  const double step = 1e-3 * a1;
  if (!(a1 + step < a_limit_) || !(a1 > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  const auto central = [&](double d) {
    return (displacement_difference(a1 + d) - displacement_difference(a1 - d)) / (2.0 * d);
  };
  return (4.0 * central(0.5 * step) - central(step)) / 3.0;
}

double SingleLevelShells::contact_radius(double X) const {
  if (!(X > 0.0)) return 0.0;
  if (std::isinf(X)) return a_limit_;
  // The balance as K_P a^(s+1) - X capacity(a): increasing, and smooth where X(a) has its
  // pole, so Brent's method meets 1e-15 in about ten evaluations (bisection took fifty).
  const auto f = [&](double a) { return K_P_ * ipow(a, shape_.s + 1) - X * capacity(a, sums(a)); };
  const double hi = a_limit_ * (1.0 - 1e-15);
  const double f_hi = f(hi);
  if (!(f_hi > 0.0)) return hi;
  return brent(f, 0.0, hi, f(0.0), f_hi, 1e-15 * a_limit_).x;
}

double SingleLevelShells::contact_radius_at_gap(double dh) const {
  if (!(dh > 0.0)) return 0.0;
  const auto f = [&](double a) { return displacement_difference(a) - dh; };
  const double hi = a_limit_ * (1.0 - 1e-15);
  const double f_hi = f(hi);
  if (f_hi < 0.0) return hi;
  if (!std::isfinite(f_hi)) {
    // h without bound at the limit (point loads): bisection, which needs no finite end.
    const auto below = [&](double a) { return f(a) < 0.0; };
    const auto [lo, up] = bisect_boundary(below, 0.0, a_limit_, 1e-15);
    return 0.5 * (lo + up);
  }
  return brent(f, 0.0, hi, -dh, f_hi, 1e-15 * a_limit_).x;
}

}  // namespace punchsweep::model
