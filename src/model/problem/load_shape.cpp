#include "model/problem/load_shape.hpp"

#include <cmath>
#include <stdexcept>

#include "model/numerics/number_text.hpp"
#include "model/problem/parameter.hpp"

namespace punchsweep::model {
const Parameter& ramp_time_parameter() {
  static const Parameter kRampTime{"ramp_time",
                                   "T_eps",
                                   "ramp time",
                                   "ramp time t_r over which the nominal pressure rises linearly to pbar (then held), "
                                   "in the law's time unit; 0 is a step",
                                   "ramp_time >= 0 (0 is a step)",
                                   [](double v) { return v >= 0.0; },
                                   false,
                                   "0",
                                   "0"};
  return kRampTime;
}

LoadShape LoadShape::ramp(double ramp_time) {
  if (!(std::isfinite(ramp_time) && ramp_time >= 0.0)) {
    throw std::invalid_argument("ramp time ramp_time = " + number_text(ramp_time, 12) +
                                " is outside its range: ramp_time >= 0 (0 is a step)");
  }
  LoadShape shape;
  if (ramp_time == 0.0) return shape;
  shape.kind_ = Kind::ramp;
  shape.jump_ = 0.0;
  shape.rise_time_ = ramp_time;
  shape.segments_ = std::make_shared<const std::vector<Segment>>(std::vector<Segment>{{0.0, ramp_time, 1.0 / ramp_time}});
  return shape;
}

LoadShape LoadShape::table(const std::vector<Point>& points) {
  const auto bad = [](std::size_t k, const Point& p, const std::string& rule) {
    return std::invalid_argument("load table point " + std::to_string(k + 1) + " (t = " + number_text(p.t, 12) +
                                 ", phi = " + number_text(p.phi, 12) + "): " + rule);
  };
  if (points.empty()) throw std::invalid_argument("load table: no points; valid: (0, phi_0), ..., (t_n, 1)");
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Point& p = points[k];
    if (!std::isfinite(p.t) || !std::isfinite(p.phi)) throw bad(k, p, "values must be finite");
    if (k == 0 && p.t != 0.0) throw bad(k, p, "the table starts at t = 0");
    if (k > 0 && !(p.t > points[k - 1].t)) throw bad(k, p, "times must increase strictly");
    if (!(p.phi >= 0.0 && p.phi <= 1.0)) throw bad(k, p, "phi must lie in [0, 1] (pbar = pbar0 phi)");
    if (k > 0 && p.phi < points[k - 1].phi) {
      throw bad(k, p,
                "the load decreases; refused because the model (the extended correspondence principle) holds "
                "only while the contact does not recede, i.e. for a non-decreasing load");
    }
  }
  if (points.back().phi != 1.0) {
    throw bad(points.size() - 1, points.back(), "the last point must have phi = 1 (pbar0 is the held pressure)");
  }
  LoadShape shape;
  shape.kind_ = Kind::table;
  shape.jump_ = points.front().phi;
  std::vector<Segment> segments;
  for (std::size_t k = 1; k < points.size(); ++k) {
    const double rise = points[k].phi - points[k - 1].phi;
    if (rise > 0.0) segments.push_back({points[k - 1].t, points[k].t, rise / (points[k].t - points[k - 1].t)});
    if (points[k - 1].phi < 1.0) shape.rise_time_ = points[k].t;
  }
  if (segments.empty()) return LoadShape{};  // a jump to 1 at t = 0: the step
  shape.segments_ = std::make_shared<const std::vector<Segment>>(std::move(segments));
  return shape;
}

double LoadShape::at(double t) const {
  if (!segments_) return 1.0;
  double phi = jump_;
  for (const Segment& s : *segments_) {
    if (t <= s.t_a) break;
    phi += s.slope * (std::min(t, s.t_b) - s.t_a);
  }
  return t >= rise_time_ ? 1.0 : std::min(phi, 1.0);
}

const std::vector<LoadShape::Segment>& LoadShape::segments() const {
  static const std::vector<Segment> kNone;
  return segments_ ? *segments_ : kNone;
}

std::vector<double> LoadShape::kinks() const {
  std::vector<double> out;
  for (const Segment& s : segments()) {
    if (s.t_a > 0.0 && (out.empty() || out.back() != s.t_a)) out.push_back(s.t_a);
    out.push_back(s.t_b);
  }
  return out;
}

}  // namespace punchsweep::model
