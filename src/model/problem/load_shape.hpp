#pragma once

#include <memory>
#include <string>
#include <vector>

namespace punchsweep::model {

/// The shape phi(t) of the nominal pressure history pbar(t) = pbar0 phi(t)
/// (docs/model.md, section 10): a jump phi(0+) at t = 0, then piecewise linear and
/// non-decreasing up to phi = 1 at the end of the rise, held after it.
///   step:  phi = 1 for t > 0 (the paper's load; rise time 0);
///   ramp:  phi = t / t_r up to t_r, then 1;
///   table: through given points (t_k, phi_k), t_0 = 0, the last phi = 1.
/// It never decreases: the extended correspondence principle, on which the whole model rests,
/// holds only while the contact does not recede. Copies are cheap (a table's points are
/// shared).
class LoadShape {
 public:
  /// One linear piece: phi rises with `slope` (in 1/time) over [t_a, t_b].
  struct Segment {
    double t_a = 0.0;
    double t_b = 0.0;
    double slope = 0.0;
  };
  struct Point {
    double t = 0.0;
    double phi = 0.0;
  };

  /// The step.
  LoadShape() = default;
  /// A ramp over `ramp_time` (time unit of the law); 0 is the step. Throws
  /// std::invalid_argument naming the value when it is negative or not finite.
  static LoadShape ramp(double ramp_time);
  /// Through `points`. Throws std::invalid_argument with the offending point and the rule
  /// when t_0 != 0, the t_k do not increase strictly, a phi_k is outside [0, 1], phi
  /// decreases (saying why that is refused), or the last phi is not 1.
  static LoadShape table(const std::vector<Point>& points);

  bool is_step() const { return kind_ == Kind::step; }
  /// phi(0+), the part applied at once.
  double jump() const { return jump_; }
  /// The time phi reaches 1 (0 for the step).
  double rise_time() const { return rise_time_; }
  /// phi(t) for t > 0.
  double at(double t) const;
  /// The linear pieces with slope > 0, in time order.
  const std::vector<Segment>& segments() const;
  /// The times where phi has a kink (segment ends inside (0, rise_time]).
  std::vector<double> kinks() const;

 private:
  enum class Kind { step, ramp, table };
  Kind kind_ = Kind::step;
  double jump_ = 1.0;
  double rise_time_ = 0.0;
  std::shared_ptr<const std::vector<Segment>> segments_;  ///< null for the step
};

/// Calls f(a, b) for the pieces of [lo, hi] between `kinks` (ascending, LoadShape::kinks):
/// a quadrature of anything that follows the load ends its pieces there. Nothing if hi <= lo.
template <class F>
void for_each_piece(const std::vector<double>& kinks, double lo, double hi, F&& f) {
  if (!(hi > lo)) return;
  double a = lo;
  for (const double k : kinks) {
    if (k > a && k < hi) {
      f(a, k);
      a = k;
    }
  }
  f(a, hi);
}

struct Parameter;
/// ramp_time, the rise time of a ramp load (model/problem/parameter.hpp), in the law's time unit.
const Parameter& ramp_time_parameter();

}  // namespace punchsweep::model
