// The square lattice's far field at small spots (model/numerics/lattice.hpp): the closed
// form 4 (2 - sqrt 2) zeta(1/2) beta(1/2) / pi against Ewald's sum of the lattice's
// zero-mean potential, computed here.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "model/numerics/lattice.hpp"

using namespace punchsweep::model;

namespace {

/// sum over the sites R of the unit square lattice of 1/|x - R|, less the uniform background
/// that makes it zero-mean (Ewald: erfc-screened sites in real space, the rest in Fourier
/// space, G = 0 left out; the background adds -2 sqrt(pi) / alpha). At a site itself
/// (`at_site`), the site's own 1/|x| is taken out: the limit of the rest as x -> the site.
double ewald(double x, double y, bool at_site, double alpha = 2.5, int reach = 8) {
  constexpr double pi = std::numbers::pi;
  double real = 0.0, fourier = 0.0;
  for (int i = -reach; i <= reach; ++i) {
    for (int j = -reach; j <= reach; ++j) {
      const double r = std::hypot(i - x, j - y);
      if (at_site && i == 0 && j == 0) {
        real -= 2.0 * alpha / std::sqrt(pi);  // erfc(alpha r)/r - 1/r -> -2 alpha / sqrt(pi)
      } else {
        real += std::erfc(alpha * r) / r;
      }
      if (i != 0 || j != 0) {
        const double g = 2.0 * pi * std::hypot(i, j);
        fourier += 2.0 * pi / g * std::erfc(g / (2.0 * alpha)) * std::cos(2.0 * pi * (i * x + j * y));
      }
    }
  }
  return real + fourier - 2.0 * std::sqrt(pi) / alpha;
}

}  // namespace

TEST(LatticeFarField, equals_ewalds_sum_of_the_lattice) {
  // Per unit load on a half-space of E* = 1 a point load makes 1/(pi r): Psi is the site's
  // regularized potential less the square centre's, over pi.
  for (const double alpha : {1.5, 2.5, 4.0}) {  // the split does not matter
    const double site = ewald(0.0, 0.0, true, alpha), centre = ewald(0.5, 0.5, false, alpha);
    EXPECT_NEAR((site - centre) / std::numbers::pi, lattice_far_field_constant(), 1e-13) << alpha;
    // The closed form's two pieces: the site sum 4 zeta(1/2) beta(1/2), and the centre as a
    // site of the lattice of pitch 1/sqrt(2) that sites and centres make together.
    EXPECT_NEAR(site, -3.9002649200019558, 1e-12);
    EXPECT_NEAR(centre, (std::numbers::sqrt2 - 1.0) * site, 1e-12);
  }
  EXPECT_NEAR(lattice_far_field_constant(), -0.72724969313843255, 1e-15);
}
