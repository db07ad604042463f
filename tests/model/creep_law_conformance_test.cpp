// Every creep law of model::creep_laws() passes the same checks: the interconversion of
// its creep and relaxation functions, monotone J with the declared limits, J^-1, E' = dE/dt,
// its retardation series (when it has one), its time scales, and the factory's refusal of
// values outside each parameter's range. A new law adds one row to kSamples.

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "input/material_file.hpp"
#include "model/laws/creep_laws.hpp"
#include "model/laws/kelvin_series.hpp"
#include "model/laws/material.hpp"
#include "model/laws/material_laws.hpp"
#include "model/laws/power_law.hpp"
#include "model/laws/prony_series.hpp"
#include "model/laws/time_shift.hpp"
#include "model/point/parameters.hpp"

using namespace punchsweep::model;

namespace {

// Parameter values to check each law at, by law name (each row in the law's parameter
// order): its elastic limit, ordinary values and a strongly creeping one.
const std::map<std::string, std::vector<std::vector<double>>> kSamples{
    {"standard_linear_solid", {{1.0}, {1.5}, {2.5}, {10.0}, {40.0}}},
};

// A material file of `law` with its registered example keys.
std::string material_file_of(const MaterialLaw& law) {
  return "[material]\nname = conformance\nlaw = " + std::string(law.name) +
         "\nmodulus_unit = MPa\ntime_unit = s\npoisson = 0.45\n" + std::string(law.example);
}

// A law to check: a registered one at parameter values, or one built directly (a law whose
// data are lists, such as a Prony series, before material files select it by name).
struct Case {
  std::string name;
  const CreepLawSpec* law = nullptr;  ///< the registered law, or nullptr
  std::vector<double> values;
  std::function<std::unique_ptr<CreepLaw>()> build;  ///< for a law built directly
};

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const CreepLawSpec& law : creep_laws()) {
    const auto it = kSamples.find(std::string(law.name));
    if (it == kSamples.end()) continue;  // caught by every_law_has_conformance_samples
    for (const std::vector<double>& values : it->second) out.push_back({std::string(law.name), &law, values, {}});
  }
  // Prony series: one term (the SLS at T = 2.5), and 7 terms over 8 decades.
  out.push_back({"prony", nullptr, {}, [] {
                   return std::make_unique<PronySeries>(0.4, std::vector<double>{0.6}, std::vector<double>{0.4});
                 }});
  out.push_back({"prony", nullptr, {}, [] {
                   return std::make_unique<PronySeries>(
                       0.05, std::vector<double>{0.2, 0.1, 0.3, 0.15, 0.1, 0.05, 0.05},
                       std::vector<double>{1e-4, 1e-3, 1e-2, 1e-1, 1.0, 1e2, 1e4});
                 }});
  // Kelvin series: one term (the SLS at T = 2.5), 5 terms over 6 decades, and with a
  // dashpot (unlimited creep; the Burgers model for one term).
  out.push_back({"kelvin", nullptr, {}, [] {
                   return std::make_unique<KelvinSeries>(std::vector<double>{1.5}, std::vector<double>{1.0});
                 }});
  out.push_back({"kelvin", nullptr, {}, [] {
                   return std::make_unique<KelvinSeries>(std::vector<double>{0.3, 1.0, 0.5, 2.0, 0.2},
                                                         std::vector<double>{1e-3, 1e-2, 1.0, 10.0, 1e3});
                 }});
  out.push_back({"kelvin_dashpot", nullptr, {}, [] {
                   return std::make_unique<KelvinSeries>(std::vector<double>{1.0}, std::vector<double>{1.0}, 0.05);
                 }});
  out.push_back({"kelvin_dashpot", nullptr, {}, [] {
                   return std::make_unique<KelvinSeries>(std::vector<double>{0.5, 2.0}, std::vector<double>{0.1, 10.0},
                                                         1e-3);
                 }});
  // Power law (unlimited creep, a kernel singular at age 0): slow, middling and fast.
  for (const double n : {0.1, 0.4, 0.8}) {
    out.push_back({"power_law", nullptr, {}, [n] { return std::make_unique<PowerLaw>(n, 2.0); }});
  }
  // Every law a material file may name, built from its registered example file.
  for (const MaterialLaw& law : material_laws()) {
    out.push_back({"file_" + std::string(law.name), nullptr, {}, [&law] {
                     return punchsweep::input::read_material_text(material_file_of(law), "example.ini").make({});
                   }});
  }
  // A shifted law: a 3-term Prony series 100 times slower and 1000 times faster.
  for (const double a_T : {100.0, 1e-3}) {
    out.push_back({"shifted_prony", nullptr, {}, [a_T] {
                     return std::make_unique<TimeShiftedLaw>(
                         std::make_unique<PronySeries>(0.2, std::vector<double>{0.3, 0.3, 0.2},
                                                       std::vector<double>{0.01, 1.0, 100.0}),
                         a_T);
                   }});
  }
  return out;
}

void PrintTo(const Case& c, std::ostream* out) {
  *out << c.name << " (";
  for (std::size_t k = 0; k < c.values.size(); ++k) {
    *out << (k ? ", " : "") << c.law->parameters[k].name << " = " << c.values[k];
  }
  *out << ")";
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  return info.param.name + "_" + std::to_string(info.index);
}

class CreepLawConformance : public ::testing::TestWithParam<Case> {
 protected:
  std::unique_ptr<CreepLaw> make() const {
    return GetParam().law ? make_creep_law(*GetParam().law, GetParam().values) : GetParam().build();
  }
};

// int_a^b f by GSL's adaptive QAGS (21-point Kronrod with extrapolation, which also takes
// the integrable endpoint singularities of a power law): a quadrature independent of the
// model's own rules.
template <class F>
double qags(F&& f, double a, double b) {
  gsl_integration_workspace* w = gsl_integration_workspace_alloc(2000);
  gsl_function fn;
  fn.function = [](double x, void* p) { return (*static_cast<F*>(p))(x); };
  fn.params = &f;
  double result = 0.0, error = 0.0;
  gsl_set_error_handler_off();
  gsl_integration_qags(&fn, a, b, 0.0, 1e-13, 2000, w, &result, &error);
  gsl_integration_workspace_free(w);
  return result;
}

// int_0-^t E(t - tau) dJ(tau) = E(t) J(0) + int_0^t E(t - tau) J'(tau) dtau, the integral
// by QAGS (J' may be singular at 0, as a power law's is).
double interconversion(const CreepLaw& law, double t) {
  return law.relaxation(t) * law.creep(0.0) +
         qags([&](double tau) { return law.relaxation(t - tau) * law.creep_rate(tau); }, 0.0, t);
}

}  // namespace

TEST(CreepLaws, every_law_has_conformance_samples) {
  for (const CreepLawSpec& law : creep_laws()) {
    EXPECT_TRUE(kSamples.count(std::string(law.name))) << law.name << " has no row in kSamples";
    EXPECT_EQ(find_creep_law(law.name), &law);
    if (!law.alias.empty()) {
      EXPECT_EQ(find_creep_law(law.alias), &law);
    }
    for (const Parameter& p : law.parameters) {
      EXPECT_EQ(find_parameter(p.name), &p) << "parameter names are unique across laws and the problem";
      EXPECT_TRUE(p.sweepable()) << p.name;
    }
  }
  EXPECT_EQ(find_creep_law("no such law"), nullptr);
}

TEST_P(CreepLawConformance, relaxation_and_creep_are_interconverted) {
  const auto law = make();
  const double scale = std::min(law->creep_time_scale(), law->relaxation_time_scale());
  for (const double t : {0.3, 1.0, 4.0}) {
    const double span = t * scale;
    EXPECT_NEAR(interconversion(*law, span), 1.0, 1e-10) << law->describe() << ", t = " << span;
  }
}

TEST_P(CreepLawConformance, creep_is_non_decreasing_between_its_declared_limits) {
  const auto law = make();
  EXPECT_DOUBLE_EQ(law->creep(0.0), law->creep_initial());
  EXPECT_NEAR(law->creep(0.0), 1.0, 1e-15) << "J(0) = 1/E0*: the unit of pressure";
  double previous = law->creep(0.0);
  const double scale = law->creep_time_scale();
  for (int k = 1; k <= 400; ++k) {
    const double J = law->creep(scale * 0.1 * k);
    EXPECT_GE(J, previous);
    previous = J;
  }
  if (std::isfinite(law->creep_final())) {
    // Long after every creep and relaxation time (the relaxation memory is 40 of the
    // longest relaxation time; a retardation time is at most a few of those).
    const double long_time = 200.0 * std::max(scale, law->relaxation_memory());
    EXPECT_NEAR(law->creep(long_time), law->creep_final(), 1e-12 * law->creep_final());
    EXPECT_NEAR(law->relaxation(long_time), 1.0 / law->creep_final(), 1e-12);
  }
  EXPECT_NEAR(law->relaxation(0.0), 1.0 / law->creep_initial(), 1e-15);
}

TEST_P(CreepLawConformance, relaxation_rate_is_the_derivative_of_relaxation) {
  const auto law = make();
  const double scale = law->relaxation_time_scale();
  for (const double x : {0.05, 0.5, 2.0}) {
    const double t = x * scale;
    const double h = 1e-5 * scale;
    const double central = (law->relaxation(t + h) - law->relaxation(t - h)) / (2 * h);
    const double rate_scale = std::isfinite(law->relaxation_rate(0.0)) ? std::abs(law->relaxation_rate(0.0))
                                                                        : std::abs(law->relaxation_rate(t));
    EXPECT_NEAR(law->relaxation_rate(t), central, 1e-7 * rate_scale + 1e-12)
        << law->describe() << ", t = " << t;
  }
}

TEST_P(CreepLawConformance, creep_rate_is_the_derivative_of_creep) {
  const auto law = make();
  const double scale = law->creep_time_scale();
  for (const double x : {0.05, 0.5, 2.0, 30.0}) {
    const double t = x * scale;
    const double h = 1e-5 * t;
    const double central = (law->creep(t + h) - law->creep(t - h)) / (2 * h);
    EXPECT_NEAR(law->creep_rate(t), central, 1e-6 * std::abs(central) + 1e-9 * law->creep(t) / scale)
        << law->describe() << ", t = " << t;
  }
}

// int_u0^u1 J du against QAGS, also for a short interval far out (where the law must avoid
// the cancellation of I(u1) - I(u0)).
TEST_P(CreepLawConformance, creep_integral_is_the_integral_of_creep) {
  const auto law = make();
  const double scale = law->creep_time_scale();
  const auto reference = [&](double a, double b) { return qags([&](double u) { return law->creep(u); }, a, b); };
  for (const auto& [a, b] : {std::pair{0.0, 0.3}, std::pair{0.0, 5.0}, std::pair{2.0, 3.0}, std::pair{1e6, 1e6 + 1e-3}}) {
    const double u0 = a * scale;
    const double u1 = b * scale;
    const double expected = reference(u0, u1);
    EXPECT_NEAR(law->creep_integral(u0, u1 - u0), expected, 1e-11 * std::abs(expected)) << law->describe() << ", ["
                                                                                   << u0 << ", " << u1 << "]";
  }
  EXPECT_EQ(law->creep_integral(0.7 * scale, 0.0), 0.0);
}

TEST_P(CreepLawConformance, declares_the_singularity_of_its_rates_at_zero) {
  const auto law = make();
  EXPECT_EQ(law->singular_at_zero(), !std::isfinite(law->relaxation_rate(0.0))) << law->describe();
  EXPECT_EQ(law->singular_at_zero(), !std::isfinite(law->creep_rate(0.0))) << law->describe();
}

TEST_P(CreepLawConformance, relaxation_memory_bounds_the_kernel) {
  const auto law = make();
  const double memory = law->relaxation_memory();
  if (std::isinf(memory)) GTEST_SKIP() << law->describe() << ": unlimited memory (no time bounds its kernel)";
  EXPECT_LE(std::abs(law->relaxation_rate(memory)), 1e-16 * std::abs(law->relaxation_rate(0.0)) + 1e-300);
}

TEST_P(CreepLawConformance, time_at_creep_inverts_creep) {
  const auto law = make();
  if (law->creep_final() == law->creep_initial()) GTEST_SKIP() << law->describe() << ": elastic, J is constant";
  const double scale = law->creep_time_scale();
  for (const double x : {1e-6, 0.01, 0.77, 3.0}) {
    const double t = x * scale;
    const double J = law->creep(t);
    const double slope = (law->creep(t * 1.001) - law->creep(t * 0.999)) / (0.002 * t);
    // J(t) is computed from terms as large as J(inf) (for a limited law): its rounding,
    // divided by the slope, bounds how well t can be recovered.
    const double magnitude = std::isfinite(law->creep_final()) ? std::max(J, law->creep_final()) : J;
    const double conditioning = 8.0 * 2.2e-16 * magnitude / slope;
    EXPECT_NEAR(law->time_at_creep(J), t, conditioning + 1e-12 * t) << law->describe();
  }
  EXPECT_EQ(law->time_at_creep(law->creep_initial()), 0.0);
  if (std::isfinite(law->creep_final())) {
    EXPECT_TRUE(std::isinf(law->time_at_creep(law->creep_final())));
  }
}

TEST_P(CreepLawConformance, retardation_series_reproduces_the_creep_function) {
  const auto law = make();
  const std::optional<RetardationSeries> series = law->retardation_series();
  if (!series) GTEST_SKIP() << law->describe() << ": offers no retardation series";
  EXPECT_EQ(series->J_final, law->creep_final());
  for (const double t : {0.0, 0.1, 1.0, 7.0}) {
    double J = series->J_final;
    for (const RetardationSeries::Term& term : series->terms) {
      EXPECT_GT(term.lambda, 0.0);
      J -= term.J * std::exp(-t / term.lambda);
    }
    EXPECT_NEAR(J, law->creep(t), 1e-14 * series->J_final) << law->describe() << ", t = " << t;
  }
}

TEST_P(CreepLawConformance, relaxation_series_reproduces_the_relaxation_function) {
  // A law that offers its relaxation series has its load histories integrated term by term
  // (LoadHistory): the series must be the law's E and E', with tau ascending.
  const auto law = make();
  const std::optional<RelaxationSeries> series = law->relaxation_series();
  if (!series) GTEST_SKIP() << law->describe() << ": offers no relaxation series";
  ASSERT_FALSE(series->terms.empty());
  for (std::size_t k = 1; k < series->terms.size(); ++k) {
    EXPECT_GT(series->terms[k].tau, series->terms[k - 1].tau) << law->describe();
  }
  for (const double t : {0.0, 1e-3, 0.1, 1.0, 7.0}) {
    double E = series->E_final;
    double rate = 0.0;
    for (const RelaxationSeries::Term& term : series->terms) {
      EXPECT_GT(term.E, 0.0);
      E += term.E * std::exp(-t / term.tau);
      rate -= term.E / term.tau * std::exp(-t / term.tau);
    }
    EXPECT_NEAR(E, law->relaxation(t), 1e-14 * law->relaxation(0.0)) << law->describe() << ", t = " << t;
    EXPECT_NEAR(rate, law->relaxation_rate(t), 1e-13 * std::abs(law->relaxation_rate(0.0)))
        << law->describe() << ", t = " << t;
  }
}

// The factory's refusals, over the laws it builds (the others are built directly, their
// checks in their own tests).
class CreepLawFactory : public CreepLawConformance {};

TEST_P(CreepLawFactory, refuses_values_outside_each_parameters_range) {
  ASSERT_NE(GetParam().law, nullptr);
  const CreepLawSpec& spec = *GetParam().law;
  for (std::size_t k = 0; k < spec.parameters.size(); ++k) {
    std::vector<double> values = GetParam().values;
    values[k] = std::nan("");
    try {
      make_creep_law(spec, values);
      ADD_FAILURE() << spec.name << " accepted NaN for " << spec.parameters[k].name;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(std::string(spec.parameters[k].range)), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(make_creep_law(spec, std::vector<double>(spec.parameters.size() + 1, 1.0)), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(EveryLaw, CreepLawConformance, ::testing::ValuesIn(cases()), case_name);

std::vector<Case> factory_cases() {
  std::vector<Case> out;
  for (const Case& c : cases()) {
    if (c.law != nullptr) out.push_back(c);
  }
  return out;
}
INSTANTIATE_TEST_SUITE_P(EveryFactoryLaw, CreepLawFactory, ::testing::ValuesIn(factory_cases()), case_name);

// Every law of the material-file registry reads exactly the keys it declares: its example
// uses only declared keys, each declared key is one the file reader accepts, a key of another
// law is refused by name, a key its example needs is refused when missing, and
// docs/materials.md documents every declared key.
TEST(MaterialLaws, every_file_law_reads_its_declared_keys_and_refuses_others) {
  std::ifstream docs_file(std::string(PUNCHSWEEP_SOURCE_DIR) + "/docs/materials.md");
  std::stringstream docs;
  docs << docs_file.rdbuf();
  for (const MaterialLaw& law : material_laws()) {
    SCOPED_TRACE(std::string(law.name));
    EXPECT_EQ(find_material_law(law.name), &law);
    const std::string file = material_file_of(law);
    EXPECT_NO_THROW(punchsweep::input::read_material_text(file, "example.ini"));
    std::istringstream lines{std::string(law.example)};
    for (std::string line; std::getline(lines, line);) {
      const std::string key = line.substr(0, line.find(' '));
      EXPECT_TRUE(std::any_of(law.keys.begin(), law.keys.end(), [&](const MaterialKey& k) { return k.key == key; }))
          << key << " is in the example but not declared";
      // Without it the file is refused, naming the key (an optional key leaves a valid file).
      std::string without = file;
      without.erase(without.find(line + "\n"), line.size() + 1);
      try {
        punchsweep::input::read_material_text(without, "example.ini");
        EXPECT_NE(std::string(std::find_if(law.keys.begin(), law.keys.end(),
                                           [&](const MaterialKey& k) { return k.key == key; })->meaning)
                      .find("optional"),
                  std::string::npos)
            << key << " is not optional, yet a file without it was accepted";
      } catch (const MaterialError& e) {
        EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
      }
    }
    for (const MaterialKey& k : law.keys) {
      EXPECT_NE(docs.str().find("`" + std::string(k.key) + "`"), std::string::npos)
          << k.key << " is not in docs/materials.md";
    }
    for (const MaterialLaw& other : material_laws()) {
      for (const MaterialKey& k : other.keys) {
        if (std::any_of(law.keys.begin(), law.keys.end(), [&](const MaterialKey& own) { return own.key == k.key; })) {
          continue;
        }
        try {
          punchsweep::input::read_material_text(file + std::string(k.key) + " = 1\n", "example.ini");
          ADD_FAILURE() << k.key << " of " << other.name << " was accepted in a " << law.name << " file";
        } catch (const MaterialError& e) {
          EXPECT_NE(std::string(e.what()).find(std::string(k.key) + " = 1: not a key of law = " + std::string(law.name)),
                    std::string::npos)
              << e.what();
        }
      }
    }
  }
}

// The laws of parameter values and the laws of material files are one vocabulary: every law
// a sweep may name by model.creep_law also has its material-file form, of the same name, and
// that form at T_eps = 1 and E_0 = 1 is the law itself.
TEST(MaterialLaws, every_law_of_values_has_its_file_form) {
  for (const CreepLawSpec& law : creep_laws()) {
    const MaterialLaw* file = find_material_law(law.name);
    ASSERT_NE(file, nullptr) << law.name << " has no entry in material_laws()";
    const std::vector<double> values = kSamples.at(std::string(law.name)).at(2);
    std::string keys = "E_0 = 1\nT_eps = 1\n";
    for (std::size_t k = 0; k < values.size(); ++k) {
      std::ostringstream line;
      line.precision(17);
      line << law.parameters[k].name << " = " << values[k] << "\n";
      keys += line.str();
    }
    const std::string text = "[material]\nname = x\nlaw = " + std::string(law.name) +
                             "\nmodulus_unit = Pa\ntime_unit = s\npoisson = 0\n" + keys;
    const std::unique_ptr<CreepLaw> from_file = punchsweep::input::read_material_text(text, "x.ini").make({});
    const std::unique_ptr<CreepLaw> from_values = make_creep_law(law, values);
    for (const double t : {0.0, 0.1, 1.0, 3.0, 30.0}) {
      EXPECT_NEAR(from_file->creep(t), from_values->creep(t), 1e-14) << law.name << " t = " << t;
    }
  }
}
