// The fit recovers a known material from sampled DMA isotherms (fit_test_data.hpp): the
// shifts and the moduli, within what the noise allows; and it refuses data it cannot fit.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "fit/material_fit.hpp"
#include "fit_test_data.hpp"

namespace punchsweep::fit {
namespace {

const std::vector<double> kTemperatures{-10, 0, 10, 20, 30, 40, 50, 60};

MaterialFitRequest wlf_at(double T_ref) {
  MaterialFitRequest r;
  r.shift.law = ShiftRequest::Law::wlf;
  r.shift.T_ref = T_ref;
  return r;
}

TEST(MaterialFit, WithoutNoiseRecoversShiftsAndModuli) {
  const MaterialFit f = fit_material(testing::sample(kTemperatures, 0.0, 1), wlf_at(20.0));
  const model::TemperatureShift truth = testing::known_wlf();
  ASSERT_TRUE(f.master.law.has_value());
  for (std::size_t i = 0; i < f.master.temperatures.size(); ++i) {
    const double T = f.master.temperatures[i];
    // Linear interpolation between readings 1/3 decade apart limits the overlap's shifts.
    EXPECT_NEAR(f.master.measured_log10_aT[i], truth.log10_factor(T), 0.03) << T;
    EXPECT_NEAR(f.master.law_log10_aT[i], truth.log10_factor(T), 0.03) << T;
  }
  EXPECT_NEAR(f.master.law->C1, truth.C1, 0.05 * truth.C1);
  EXPECT_NEAR(f.master.law->C2, truth.C2, 0.05 * truth.C2);
  // Against the true moduli at every reading's true reduced frequency.
  const PronyTerms t = testing::known_series();
  double worst = 0.0;
  for (const ReducedReading& r : f.readings) {
    const double w = r.x * std::pow(10.0, truth.log10_factor(r.temperature));
    worst = std::max({worst, std::abs(f.prony.terms.storage(w) / t.storage(w) - 1.0),
                      std::abs(f.prony.terms.loss(w) / t.loss(w) - 1.0)});
  }
  EXPECT_LT(worst, 0.03);
  EXPECT_LT(f.prony.rms_first, 0.01);
  EXPECT_LT(f.prony.rms_second, 0.01);
}

TEST(MaterialFit, WithTwoPercentNoiseTheModuliAreWithinTheNoise) {
  constexpr double kNoise = 0.02;
  const MaterialFit f = fit_material(testing::sample(kTemperatures, kNoise, 7), wlf_at(20.0));
  const model::TemperatureShift truth = testing::known_wlf();
  const PronyTerms t = testing::known_series();
  double ss = 0.0;
  int n = 0;
  for (const ReducedReading& r : f.readings) {
    const double w = r.x * std::pow(10.0, truth.log10_factor(r.temperature));
    ss += std::pow(f.prony.terms.storage(w) / t.storage(w) - 1.0, 2) + std::pow(f.prony.terms.loss(w) / t.loss(w) - 1.0, 2);
    n += 2;
  }
  // The fit's error against the truth is below the noise in the readings.
  EXPECT_LT(std::sqrt(ss / n), kNoise);
  // The residuals against the readings are about the noise (neither over- nor under-fitted).
  EXPECT_GT(f.prony.rms_first, 0.5 * kNoise);
  EXPECT_LT(f.prony.rms_first, 1.5 * kNoise);
  for (std::size_t i = 0; i < f.master.temperatures.size(); ++i) {
    EXPECT_NEAR(f.master.law_log10_aT[i], truth.log10_factor(f.master.temperatures[i]), 0.1);
  }
}

TEST(MaterialFit, AGivenLawIsUsedAsGiven) {
  MaterialFitRequest r;
  r.shift.law = ShiftRequest::Law::given;
  r.shift.given = testing::known_wlf();
  r.shift.T_ref = r.shift.given.T_ref;
  const MaterialFit f = fit_material(testing::sample(kTemperatures, 0.0, 1), r);
  EXPECT_EQ(f.master.law->C1, 8.0);
  EXPECT_EQ(f.master.law->C2, 120.0);
  EXPECT_TRUE(std::isnan(f.master.measured_log10_aT[0]));
  EXPECT_LT(f.prony.rms_first, 0.01);
}

TEST(MaterialFit, ReadingsWanderingAboutTheSetPointAreOneIsotherm) {
  Measurements m = testing::sample({0, 20, 40}, 0.0, 1);
  for (std::size_t k = 0; k < m.dma.size(); ++k) m.dma[k].temperature += (k % 3 == 0 ? 0.2 : -0.15);
  const MaterialFit f = fit_material(m, wlf_at(20.0));
  ASSERT_EQ(f.master.temperatures.size(), 3u);
}

TEST(MaterialFit, RefusesWhatItCannotFit) {
  // Isotherms 40 K apart with a 3-decade window do not overlap in modulus.
  EXPECT_THROW(fit_material(testing::sample({-10, 60}, 0.0, 1), wlf_at(20.0)), std::invalid_argument);
  // Two isotherms are too few for WLF (three unknowns).
  EXPECT_THROW(fit_material(testing::sample({10, 20}, 0.0, 1), wlf_at(20.0)), std::invalid_argument);
  // One isotherm away from T_ref cannot be shifted there without a law.
  EXPECT_THROW(fit_material(testing::sample({10}, 0.0, 1), wlf_at(20.0)), std::invalid_argument);
  EXPECT_THROW(fit_material(Measurements{}, wlf_at(20.0)), std::invalid_argument);
}

TEST(MaterialFit, ArrheniusIsFittedWhereAsked) {
  // Shifts from an Arrhenius law: the fitted E_a is recovered.
  model::TemperatureShift law;
  law.kind = model::TemperatureShift::Kind::arrhenius;
  law.T_ref = 20.0;
  law.E_a = 150e3;
  const PronyTerms t = testing::known_series();
  Measurements m;
  for (const double th : {0.0, 10.0, 20.0, 30.0}) {
    const double aT = std::pow(10.0, law.log10_factor(th));
    for (int k = 0; k < 10; ++k) {
      const double omega = 2.0 * M_PI * 0.1 * std::pow(10.0, 3.0 * k / 9.0);
      m.dma.push_back({th, omega, t.storage(omega * aT), t.loss(omega * aT)});
    }
  }
  MaterialFitRequest r;
  r.shift.law = ShiftRequest::Law::arrhenius;
  r.shift.T_ref = 20.0;
  const MaterialFit f = fit_material(m, r);
  EXPECT_NEAR(f.master.law->E_a, 150e3, 0.03 * 150e3);
}

TEST(PronyFit, ARelaxationTestIsRecovered) {
  const PronyTerms t = testing::known_series();
  std::vector<double> time, modulus;
  for (int k = 0; k <= 40; ++k) {
    time.push_back(1e-5 * std::pow(10.0, 9.0 * k / 40.0));
    modulus.push_back(t.relaxation(time.back()));
  }
  const PronyFit f = fit_prony_relaxation(time, modulus, PronyOptions{});
  for (std::size_t k = 0; k < time.size(); ++k) {
    EXPECT_NEAR(f.terms.relaxation(time[k]) / modulus[k], 1.0, 0.005) << time[k];
  }
  EXPECT_NEAR(f.terms.E_inf, 1e6, 0.05e6);
}

TEST(PronyFit, TheCriterionPrefersFewTermsForAOneTermMaterial) {
  // A standard linear solid sampled over 6 decades: the chosen density keeps few terms.
  PronyTerms sls;
  sls.E_inf = 1e6;
  sls.E = {3e6};
  sls.tau = {1.0};
  std::vector<double> w, s, l;
  for (int k = 0; k <= 30; ++k) {
    w.push_back(1e-3 * std::pow(10.0, 6.0 * k / 30.0));
    s.push_back(sls.storage(w.back()));
    l.push_back(sls.loss(w.back()));
  }
  const PronyFit f = fit_prony_frequency(w, s, l, PronyOptions{});
  EXPECT_LE(f.terms.E.size(), 3u);
  double rel = 0.0;
  for (std::size_t k = 0; k < w.size(); ++k) rel = std::max(rel, std::abs(f.terms.storage(w[k]) / s[k] - 1.0));
  EXPECT_LT(rel, 1e-3);
}

}  // namespace
}  // namespace punchsweep::fit
