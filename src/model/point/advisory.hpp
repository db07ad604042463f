#pragma once
/// @file
/// Physical advisories (docs/model.md, section 16): where a valid point's answer stands
/// for less than it seems. Not failures of the model (its validity is valid()), but limits
/// of the physics it stands for: a paraboloid for a spherical cap, a cap of finite size,
/// small strains.

#include <optional>
#include <string>
#include <vector>

#include "model/point/point_evaluation.hpp"

namespace punchsweep::model {

/// The contact radius above which a paraboloid z = r^2/(2R) no longer stands for a sphere:
/// the sphere is higher by r^4/(8R^3) + ..., a share r^2/(4R^2) of the paraboloid's height,
/// 2.25% at the contact edge at a = 0.3 R (Hertz's theory takes a << R).
inline constexpr double kParaboloidBound = 0.3;
/// The representative strain above which linear viscoelasticity is in doubt: 10%.
inline constexpr double kStrainBound = 0.1;

enum class Advisory { beyond_paraboloid, beyond_cap, large_strain };

struct Advisories {
  double a_max = 0.0;   ///< the largest contact radius, max(a1_inf, a2_inf), in R: radii only grow
  /// Tabor's representative strain of an indentation, 0.2 f'(a) at the contact edge, with
  /// f(r) = C r^s / R^(s-1) (0.2 a/R for a sphere; 0.2 cot(alpha) for a cone).
  double strain = 0.0;
  std::vector<Advisory> raised;
  /// "beyond_paraboloid, large_strain" ("" for none).
  std::string names() const;
  /// One sentence per advisory raised, with the numbers and bounds ("" for none).
  std::string reason(double cap_radius) const;
};

/// The advisories of a cap of `shape` whose contact radius reaches a_max (in R):
/// beyond_paraboloid for a sphere (s = 2, C = 0.5) past kParaboloidBound, beyond_cap past
/// `cap_radius` where given, large_strain where 0.2 f'(a_max) exceeds kStrainBound.
Advisories advise(const Shape& shape, double a_max, std::optional<double> cap_radius = std::nullopt);

/// The advisories of a point: beyond_paraboloid for a sphere (s = 2, C = 0.5) whose a_max
/// exceeds kParaboloidBound; beyond_cap where `cap_radius` (the cap's base radius, in R) is
/// given and a_max exceeds it; large_strain where the strain exceeds kStrainBound.
Advisories advise(const ContactProblem& problem, const PointSummary& summary, std::optional<double> cap_radius);

/// The base radius of a spherical cap of height H (in R): sqrt(H (2 - H)).
double cap_base_radius(double height);

}  // namespace punchsweep::model
