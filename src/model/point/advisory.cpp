#include "model/point/advisory.hpp"

#include <algorithm>
#include <cmath>

#include "model/numerics/number_text.hpp"

namespace punchsweep::model {

std::string Advisories::names() const {
  std::string s;
  for (const Advisory a : raised) {
    s += s.empty() ? "" : ", ";
    s += a == Advisory::beyond_paraboloid ? "beyond_paraboloid" : a == Advisory::beyond_cap ? "beyond_cap" : "large_strain";
  }
  return s;
}

std::string Advisories::reason(double cap_radius) const {
  std::string s;
  for (const Advisory a : raised) {
    s += s.empty() ? "" : " ";
    if (a == Advisory::beyond_paraboloid) {
      s += "The contact radius reaches " + number_text(a_max, 4) + " R, beyond " + number_text(kParaboloidBound, 2) +
           " R, where the paraboloid stands for a sphere to " +
           number_text(100 * kParaboloidBound * kParaboloidBound / 4, 3) + "% of its height at the contact edge.";
    } else if (a == Advisory::beyond_cap) {
      s += "The contact radius reaches " + number_text(a_max, 4) + " R, beyond the cap's base radius " +
           number_text(cap_radius, 4) + " R: the flat between the caps would touch.";
    } else {
      s += "The representative strain 0.2 f'(a) reaches " + number_text(100 * strain, 3) + "%, beyond " +
           number_text(100 * kStrainBound, 2) + "%, where linear viscoelasticity is in doubt.";
    }
  }
  return s;
}

Advisories advise(const Shape& shape, double a_max, std::optional<double> cap_radius) {
  Advisories out;
  out.a_max = a_max;
  const int s = shape.s;
  out.strain = 0.2 * shape.C * s * std::pow(out.a_max, s - 1);
  if (!std::isfinite(out.a_max)) return out;
  if (s == 2 && shape.C == 0.5 && out.a_max > kParaboloidBound) out.raised.push_back(Advisory::beyond_paraboloid);
  if (cap_radius && out.a_max > *cap_radius) out.raised.push_back(Advisory::beyond_cap);
  if (out.strain > kStrainBound) out.raised.push_back(Advisory::large_strain);
  return out;
}

Advisories advise(const ContactProblem& problem, const PointSummary& summary, std::optional<double> cap_radius) {
  return advise(problem.shape, std::max(summary.a1_inf, summary.a2_inf), cap_radius);
}

double cap_base_radius(double height) { return std::sqrt(height * (2.0 - height)); }

}  // namespace punchsweep::model
