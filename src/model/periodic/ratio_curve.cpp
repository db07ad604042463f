#include "model/periodic/ratio_curve.hpp"

#include <algorithm>
#include <cmath>

#include "model/numerics/integer_power.hpp"
#include "model/problem/shape.hpp"

namespace punchsweep::model {

RatioCurve::RatioCurve(int s, double v_top, std::vector<double> a1_ratio, std::vector<double> h_ratio)
    : s_(s),
      grid_(0.0, v_top, static_cast<int>(h_ratio.size())),
      a1_(std::move(a1_ratio)),
      h_(std::move(h_ratio)) {
  const Shape unit{s, 1.0};
  a_per_v_ = std::pow(load_coefficient(unit), -1.0 / (s + 1));
  h_per_v_ = depth_coefficient(unit) * ipow(a_per_v_, s);
  for (int k = 0; k < grid_.count; ++k) {
    const double v = grid_.step * k;
    h_nodes_.push_back(h_per_v_ * ipow(v, s) * h_[static_cast<std::size_t>(k)]);
    root_nodes_.push_back(v * iroot(h_[static_cast<std::size_t>(k)], s));
  }
  const double width = root_nodes_.back() / grid_.count;
  root_per_bucket_ = width > 0.0 ? 1.0 / width : 0.0;
  for (int b = 0, k = 0; b < grid_.count; ++b) {
    while (k + 1 < grid_.count && root_nodes_[static_cast<std::size_t>(k) + 1] <= b * width) ++k;
    root_start_.push_back(k);
  }
}

int RatioCurve::last_at_or_below(double target) const {
  const double bucket = std::min(target * root_per_bucket_, static_cast<double>(grid_.count - 1));
  int k = root_start_[static_cast<std::size_t>(std::max(bucket, 0.0))];
  const int last = grid_.count - 1;
  while (k < last && root_nodes_[static_cast<std::size_t>(k) + 1] <= target) ++k;
  while (k > 0 && root_nodes_[static_cast<std::size_t>(k)] > target) --k;  // rounding of the bucket
  return k;
}

PeriodicState RatioCurve::at(double xi, double v) const {
  PeriodicState out;
  out.Q1 = xi;
  if (!(xi > 0.0)) return out;
  const Stencil stencil = this->stencil(v);
  out.a1 = a_per_v_ * v * stencil(a1_.data());
  out.h = h_per_v_ * ipow(v, s_) * stencil(h_.data());
  return out;
}

double RatioCurve::gap(double v, const Stencil& at) const { return h_per_v_ * ipow(v, s_) * at(h_.data()); }

double RatioCurve::gap(double v, double* slope) const {
  const GridPosition at = grid_.at(v);
  const Stencil stencil(at, grid_.count);
  const double* p = &h_[static_cast<std::size_t>(stencil.first)];
  const double ratio = stencil.w.apply(p[0], p[1], p[2], p[3]);
  const double ratio_slope = cubic_slope_weights(at.u + (at.i - stencil.first - 1)).apply(p[0], p[1], p[2], p[3]) / grid_.step;
  const double vs1 = ipow(v, s_ - 1);
  *slope = h_per_v_ * vs1 * (s_ * ratio + v * ratio_slope);
  return h_per_v_ * vs1 * v * ratio;
}

double RatioCurve::radius(double v) const { return a_per_v_ * v * stencil(v)(a1_.data()); }

std::optional<double> RatioCurve::touchdown(double delta) const {
  if (!(delta > 0.0)) return 0.0;
  if (delta > h_nodes_.back()) return std::nullopt;
  const int M = grid_.count - 1;
  const double target = iroot(delta / h_per_v_, s_);
  const int i = std::min(last_at_or_below(target), M - 1);
  const IntervalCubic ratio(h_.data(), i, M + 1);
  const double step = grid_.step;
  const double chord = root_nodes_[static_cast<std::size_t>(i) + 1] - root_nodes_[static_cast<std::size_t>(i)];
  const double start = chord > 0.0 ? std::clamp((target - root_nodes_[static_cast<std::size_t>(i)]) / chord, 0.0, 1.0) : 0.5;
  const double u = newton_in_interval(
      [&](double w, double* rate) {
        const double x = w + ratio.shift, v = step * (i + w);
        const double vs1 = ipow(v, s_ - 1), r = ratio.value(x);
        *rate = h_per_v_ * vs1 * (s_ * step * r + v * ratio.slope(x));
        return h_per_v_ * vs1 * v * r - delta;
      },
      start);
  return ipow(step * (i + u), s_ + 1);
}

}  // namespace punchsweep::model
