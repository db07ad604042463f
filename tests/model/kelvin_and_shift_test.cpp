// The Kelvin series and the time-temperature shift against closed forms: the one-term Kelvin
// solid is the standard linear solid (E(t) = 1/T + (1 - 1/T) e^(-T t), eq 9.11); a Kelvin
// series built from a Prony series' retardation terms gives back that Prony series'
// relaxation function (the two interconversions are inverse root problems); WLF and
// Arrhenius factors as the model notes write them.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/laws/kelvin_series.hpp"
#include "model/laws/prony_series.hpp"
#include "model/laws/standard_linear_solid.hpp"
#include "model/laws/time_shift.hpp"

using namespace punchsweep::model;

TEST(KelvinSeries, one_term_is_the_standard_linear_solid) {
  for (const double T : {1.5, 2.5, 10.0, 1e3}) {
    const KelvinSeries law({T - 1.0}, {1.0});
    for (const double t : {0.0, 1e-3, 0.1, 1.0, 5.0, 50.0}) {
      EXPECT_NEAR(law.relaxation(t), 1.0 / T + (1.0 - 1.0 / T) * std::exp(-T * t), 1e-14) << "T = " << T;
      EXPECT_NEAR(law.creep(t), T - (T - 1.0) * std::exp(-t), 1e-13 * T);
    }
    EXPECT_NEAR(law.relaxation_times().front(), 1.0 / T, 1e-15);
    EXPECT_NEAR(law.modulus_final(), 1.0 / T, 1e-15);
  }
}

TEST(KelvinSeries, inverts_the_prony_interconversion) {
  const PronySeries prony(0.05, {0.2, 0.1, 0.3, 0.15, 0.1, 0.05, 0.05}, {1e-4, 1e-3, 1e-2, 1e-1, 1.0, 1e2, 1e4});
  const KelvinSeries kelvin(prony.compliances(), prony.retardation_times());
  ASSERT_EQ(kelvin.relaxation_times().size(), prony.relaxation_times().size());
  for (std::size_t i = 0; i < prony.relaxation_times().size(); ++i) {
    EXPECT_NEAR(kelvin.relaxation_times()[i], prony.relaxation_times()[i], 1e-11 * prony.relaxation_times()[i]);
    EXPECT_NEAR(kelvin.moduli()[i], prony.moduli()[i], 1e-11);
  }
  for (const double t : {0.0, 1e-5, 1e-3, 0.3, 30.0, 3e3, 1e5}) {
    EXPECT_NEAR(kelvin.relaxation(t), prony.relaxation(t), 1e-12) << "t = " << t;
  }
}

TEST(KelvinSeries, dashpot_relaxes_completely) {
  // Burgers model: one Kelvin element and a dashpot; E(inf) = 0, J unlimited.
  const KelvinSeries law({1.0}, {1.0}, 0.05);
  EXPECT_TRUE(std::isinf(law.creep_final()));
  EXPECT_EQ(law.modulus_final(), 0.0);
  EXPECT_EQ(law.relaxation_times().size(), 2u);
  EXPECT_LT(law.relaxation(40.0 * law.relaxation_times().back()), 1e-15);
  EXPECT_FALSE(law.retardation_series().has_value());
  EXPECT_NEAR(law.creep(100.0), 1.0 + (1.0 - std::exp(-100.0)) + 5.0, 1e-13);
}

TEST(KelvinSeries, refuses_bad_terms_by_name) {
  const auto message = [](auto&& build) {
    try {
      build();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message([] { KelvinSeries({1.0, -0.5}, {1.0, 2.0}); }).find("J_2 = -0.5"), std::string::npos);
  EXPECT_NE(message([] { KelvinSeries({1.0, 0.5}, {2.0, 2.0}); }).find("strictly increasing"), std::string::npos);
  EXPECT_NE(message([] { KelvinSeries({1.0}, {1.0, 2.0}); }).find("the same number"), std::string::npos);
  EXPECT_NE(message([] { KelvinSeries({1.0}, {1.0}, -1.0); }).find("E_0/eta"), std::string::npos);
}

TEST(TemperatureShift, wlf_and_arrhenius_as_written) {
  TemperatureShift wlf;
  wlf.C1 = 17.44;
  wlf.C2 = 51.6;
  wlf.T_ref = 105.0;
  EXPECT_EQ(wlf.error(), "");
  EXPECT_NEAR(wlf.log10_factor(125.0), -17.44 * 20.0 / 71.6, 1e-14);
  EXPECT_NEAR(wlf.log10_factor(95.0), 17.44 * 10.0 / 41.6, 1e-14);
  EXPECT_EQ(wlf.log10_factor(105.0), 0.0);
  // T_ref - C2 = 53.4: log10 a_T diverges, and reaches 100 (a_T = 1e100; at 54 degC it is
  // 10^1482, which overflows) at 105 - 51.6 * 100 / 117.44 = 61.0626703.
  EXPECT_FALSE(wlf.admits(53.4));
  EXPECT_FALSE(wlf.admits(54.0));
  EXPECT_FALSE(wlf.admits(61.062));
  EXPECT_TRUE(wlf.admits(61.0627));
  EXPECT_NEAR(wlf.log10_factor(61.0626703), 100.0, 1e-5);
  EXPECT_NE(wlf.range().find("temperature > 61.0626703"), std::string::npos) << wlf.range();
  EXPECT_NE(wlf.range().find("53.4"), std::string::npos);

  TemperatureShift arrhenius;
  arrhenius.kind = TemperatureShift::Kind::arrhenius;
  arrhenius.E_a = 1e5;
  arrhenius.T_ref = 25.0;
  EXPECT_NEAR(arrhenius.log10_factor(35.0), 1e5 / 8.314462618 * (1.0 / 308.15 - 1.0 / 298.15) / std::log(10.0),
              1e-13);
  EXPECT_TRUE(arrhenius.admits(-200.0));  // log10 a_T = 53.9
  EXPECT_FALSE(arrhenius.admits(-273.15));
  // Near absolute zero a_T would overflow: refused past |log10 a_T| = 100, at
  // 1 / (1/298.15 + 100 ln 10 R / E_a) - 273.15 = -228.703 degC.
  EXPECT_FALSE(arrhenius.admits(-228.71));
  EXPECT_TRUE(arrhenius.admits(-228.70));

  TemperatureShift bad = wlf;
  bad.C2 = -3.0;
  EXPECT_NE(bad.error().find("C2 = -3"), std::string::npos);
}

TEST(TemperatureShift, wlf_above_and_arrhenius_below_a_glass_transition) {
  // WLF above T_ref, Arrhenius with E_a_below under it (log10 a_T = C3 (1/T - 1/T_ref) in
  // the form papers write, C3 = E_a / (R ln 10)), continuous at T_ref; outside [T_min,
  // T_max] refused.
  TemperatureShift s;
  s.C1 = 17.4;
  s.C2 = 51.6;
  s.T_ref = 65.0;
  s.E_a_below = 35000.0 * 8.314462618 * std::log(10.0);
  s.T_min = 23.0;
  s.T_max = 85.0;
  EXPECT_EQ(s.error(), "");
  EXPECT_NEAR(s.log10_factor(85.0), -17.4 * 20.0 / 71.6, 1e-14);
  EXPECT_NEAR(s.log10_factor(23.0), 35000.0 * (1.0 / 296.15 - 1.0 / 338.15), 1e-11);
  EXPECT_EQ(s.log10_factor(65.0), 0.0);
  EXPECT_NEAR(s.log10_factor(64.999999), 0.0, 1e-4);  // continuous at T_ref
  EXPECT_TRUE(s.admits(23.0));
  EXPECT_TRUE(s.admits(85.0));
  EXPECT_FALSE(s.admits(22.9));
  EXPECT_FALSE(s.admits(85.1));
  EXPECT_NE(s.range().find(">= 23"), std::string::npos) << s.range();
  EXPECT_NE(s.range().find("<= 85"), std::string::npos) << s.range();
  EXPECT_NE(s.describe().find("Arrhenius below T_ref"), std::string::npos) << s.describe();
  // Without the limits, the Arrhenius branch holds down to absolute zero (no WLF divergence).
  TemperatureShift open = s;
  open.T_min = -273.15;
  open.T_max = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(open.admits(-100.0));
  TemperatureShift bad = s;
  bad.T_min = 90.0;
  EXPECT_NE(bad.error().find("T_min = 90"), std::string::npos) << bad.error();
  bad = s;
  bad.E_a_below = -1.0;
  EXPECT_NE(bad.error().find("E_a_below = -1"), std::string::npos) << bad.error();
}

TEST(TimeShiftedLaw, is_the_reference_law_at_scaled_time) {
  const double a = 250.0;
  const TimeShiftedLaw law(std::make_unique<StandardLinearSolid>(4.0), a);
  const StandardLinearSolid ref(4.0);
  for (const double t : {0.0, 1.0, 100.0, 1e4}) {
    EXPECT_EQ(law.creep(t), ref.creep(t / a));
    EXPECT_EQ(law.relaxation(t), ref.relaxation(t / a));
  }
  EXPECT_NEAR(law.time_at_creep(ref.creep(0.3)), 0.3 * a, 1e-12 * a);
  EXPECT_EQ(law.retardation_series()->terms.front().lambda, a);
  EXPECT_THROW(TimeShiftedLaw(std::make_unique<StandardLinearSolid>(4.0), 0.0), std::invalid_argument);
  EXPECT_THROW(TimeShiftedLaw(std::make_unique<StandardLinearSolid>(4.0), INFINITY), std::invalid_argument);
}
