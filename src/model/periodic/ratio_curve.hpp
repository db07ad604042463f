#pragma once
/// @file
/// A single level's curve read as ratios to the isolated punch (docs/model.md, section 14.7):
/// a1 / a0 and h / h0 over v = xi^(1/(s+1)) on a uniform grid from v = 0 (where both are 1),
/// a0 = (xi / K_P)^(1/(s+1)) = v K_P^(-1/(s+1)), h0 = K_d a0^s, in the scaled variables of
/// section 14.2 (l = 1, C = 1). The ratios are smooth in v down to 0, so the curve is read by
/// the cubic of the four samples about v. What the small-spot table holds for the refined
/// localization, and the periodic solution for its blend of the two tables.

#include <optional>
#include <vector>

#include "model/periodic/periodic_table.hpp"
#include "model/numerics/uniform_cubic.hpp"

namespace punchsweep::model {

class RatioCurve {
 public:
  RatioCurve() = default;
  /// Samples at v_k = v_top k / (size - 1), k = 0 .. size - 1 (size >= 4): a1 / a0 and h / h0.
  RatioCurve(int s, double v_top, std::vector<double> a1_ratio, std::vector<double> h_ratio);

  int s() const { return s_; }
  double v_top() const { return grid_.lo + grid_.step * (grid_.count - 1); }
  const UniformGrid& grid() const { return grid_; }
  const std::vector<double>& a1_ratio() const { return a1_; }
  const std::vector<double>& h_ratio() const { return h_; }
  /// h at each sample (increasing, for a curve of a gap).
  const std::vector<double>& h_samples() const { return h_nodes_; }

  /// a0 / v and h0 / v^s.
  double a_per_v() const { return a_per_v_; }
  double h_per_v() const { return h_per_v_; }

  /// The stencil of the samples about v: every field read at v shares it.
  Stencil stencil(double v) const { return Stencil(grid_.at(v), grid_.count); }
  /// At v = xi^(1/(s+1)) (the caller's): h, a1 (Q1 = xi); h alone, with dh/dv; a1 alone.
  PeriodicState at(double xi, double v) const;
  double gap(double v) const { return gap(v, stencil(v)); }
  double gap(double v, const Stencil& at) const;
  double gap(double v, double* slope) const;
  double radius(double v) const;
  /// The load at which h = delta (0 for delta <= 0), empty above the last sample: the
  /// interval that holds it by the chord of (h / h_per_v)^(1/s) = v (h / h0)^(1/s), nearly
  /// linear in v, then Newton on the curve gap() reads there, one or two steps.
  std::optional<double> touchdown(double delta) const;

 private:
  int s_ = 2;
  UniformGrid grid_;
  std::vector<double> a1_, h_;
  std::vector<double> h_nodes_;     ///< h at each sample
  std::vector<double> root_nodes_;  ///< (h / h_per_v)^(1/s) at each sample
  /// Buckets of equal width w = root_nodes_.back() / count over the roots: for b = 0 ..
  /// count - 1 the last sample with root_nodes_ <= b w, where touchdown() starts its walk (a
  /// step or two; a binary search cost it a quarter of its time).
  std::vector<int> root_start_;
  double root_per_bucket_ = 1.0;  ///< 1 / w (0 for a curve of zero roots)
  double a_per_v_ = 1.0, h_per_v_ = 1.0;

  /// The last sample k with root_nodes_[k] <= target (0 where none is).
  int last_at_or_below(double target) const;
};

}  // namespace punchsweep::model
