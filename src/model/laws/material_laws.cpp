#include "model/laws/material_laws.hpp"

#include <array>
#include <sstream>

#include "model/laws/kelvin_series.hpp"
#include "model/laws/power_law.hpp"
#include "model/laws/prony_series.hpp"
#include "model/laws/standard_linear_solid.hpp"
#include "model/laws/time_shift.hpp"
#include "model/problem/parameter.hpp"
#include "model/numerics/number_text.hpp"

namespace punchsweep::model {
namespace {

std::string terms(const MaterialTerms& t) { return std::to_string(t.times.size()) + " terms"; }

/// E(t) = E_inf + sum E_i exp(-t/tau_i), or normalized (Abaqus): E_0 with g_i.
constexpr std::array<MaterialKey, 5> kPronyKeys{{
    {"E_inf", "the long-term modulus E_inf > 0, in modulus_unit (with E_i)"},
    {"E_i", "the terms' moduli E_i > 0, in modulus_unit"},
    {"E_0", "the instantaneous modulus E_0 > 0, in modulus_unit (with g_i, instead of E_inf and E_i)"},
    {"g_i", "the terms' fractions g_i > 0 of E_0, sum g_i < 1"},
    {"tau_i", "the relaxation times tau_i > 0, strictly increasing, in time_unit"},
}};

MaterialTerms read_prony(const MaterialKeys& f) {
  MaterialTerms t;
  const std::vector<double> tau = f.list("material.tau_i");
  if (f.has("material.g_i") || f.has("material.E_0")) {
    // Normalized (Abaqus): E_0 and g_i, g_R(t) = 1 - sum g_i (1 - exp(-t/tau_i)).
    for (const char* key : {"material.E_inf", "material.E_i"}) {
      if (f.has(key)) f.fail_value(key, "give either E_inf with E_i, or E_0 with g_i, not both");
    }
    t.E0 = f.positive("material.E_0", "E_0 > 0");
    t.moduli = f.list("material.g_i");
    f.check_terms("material.g_i", t.moduli, "material.tau_i", tau, "g_i > 0");
    double sum = 0.0;
    for (const double g : t.moduli) sum += g;
    if (!(sum < 1.0)) {
      f.fail_value("material.g_i", "sum g_i = " + number_text(sum, 10) +
                                       " is outside its range: sum g_i < 1 (E_inf = E_0 (1 - sum g_i) must be > 0)");
    }
    t.final = 1.0 - sum;
  } else {
    const double E_inf = f.positive("material.E_inf", "E_inf > 0");
    const std::vector<double> E = f.list("material.E_i");
    f.check_terms("material.E_i", E, "material.tau_i", tau, "E_i > 0");
    t.E0 = E_inf;
    for (const double e : E) t.E0 += e;
    t.final = E_inf / t.E0;
    for (const double e : E) t.moduli.push_back(e / t.E0);
  }
  t.times = tau;
  return t;
}

/// J(t) = 1/E_0 + sum J_i (1 - exp(-t/lambda_i)) [+ t/eta].
constexpr std::array<MaterialKey, 4> kKelvinKeys{{
    {"E_0", "the instantaneous modulus E_0 > 0, in modulus_unit"},
    {"J_i", "the retardation compliances J_i > 0, in 1/modulus_unit"},
    {"lambda_i", "the retardation times lambda_i > 0, strictly increasing, in time_unit"},
    {"eta", "optional: the dashpot's viscosity eta > 0 (unlimited creep), in modulus_unit time_unit"},
}};

MaterialTerms read_kelvin(const MaterialKeys& f) {
  MaterialTerms t;
  t.E0 = f.positive("material.E_0", "E_0 > 0");
  const std::vector<double> J = f.list("material.J_i");  // in 1/modulus_unit
  t.times = f.list("material.lambda_i");
  f.check_terms("material.J_i", J, "material.lambda_i", t.times, "J_i > 0 (in 1/modulus_unit)");
  for (const double j : J) t.moduli.push_back(j * t.E0);
  if (f.has("material.eta")) {
    const double eta = f.positive("material.eta", "eta > 0 (in modulus_unit time_unit)");
    t.final = t.E0 / eta;
  }
  return t;
}

/// J(t) = (1 + (t/t_1)^n)/E_0.
constexpr std::array<MaterialKey, 3> kPowerKeys{{
    {"E_0", "the instantaneous modulus E_0 > 0, in modulus_unit"},
    {"n", "the exponent, 0 < n < 1"},
    {"t_1", "the time t_1 > 0 at which the creep doubles the elastic compliance, in time_unit"},
}};

MaterialTerms read_power(const MaterialKeys& f) {
  MaterialTerms t;
  t.E0 = f.positive("material.E_0", "E_0 > 0");
  t.final = f.number("material.n");
  if (!(t.final > 0.0 && t.final < 1.0)) f.fail_value("material.n", "outside its range: 0 < n < 1");
  const double t_1 = f.positive("material.t_1", "t_1 > 0 (in time_unit)");
  t.times = {t_1};
  return t;
}

/// "NAME = final, TIME = its one time": a law of one value and one time, for describe.
std::string value_and_time(const char* value_name, const char* time_name, const MaterialTerms& t) {
  std::ostringstream out;
  out.precision(6);
  out << value_name << " = " << t.final << ", " << time_name << " = " << t.times.front();
  return out.str();
}

std::string describe_power(const MaterialTerms& t) { return value_and_time("n", "t_1", t); }

/// J(t) = (T - (T - 1) exp(-t/T_eps))/E_0: the standard linear solid of creep_laws(), in
/// physical units.
constexpr std::array<MaterialKey, 3> kSlsKeys{{
    {"E_0", "the instantaneous modulus E_0 > 0, in modulus_unit"},
    {"T", "the creep ratio T = T_eps/T_sigma >= 1 (J(inf) = T/E_0; T = 1 is elastic)"},
    {"T_eps", "the retardation (creep) time T_eps > 0, in time_unit"},
}};

MaterialTerms read_sls(const MaterialKeys& f) {
  MaterialTerms t;
  t.E0 = f.positive("material.E_0", "E_0 > 0");
  t.final = f.number("material.T");
  if (!creep_ratio_parameter().admits(t.final)) {
    f.fail_value("material.T", "outside its range: " + std::string(creep_ratio_parameter().range));
  }
  t.times = {f.positive("material.T_eps", "T_eps > 0 (in time_unit)")};
  return t;
}

std::string describe_sls(const MaterialTerms& t) { return value_and_time("T", "T_eps", t); }

const std::array<MaterialLaw, 4> kLaws{{
    {"standard_linear_solid", "creep J(t) = (T - (T - 1) exp(-t/T_eps))/E_0", kSlsKeys, read_sls,
     [](const MaterialTerms& t) -> std::unique_ptr<CreepLaw> {
       // The law in T_eps, run T_eps times slower: t in the file's time unit.
       return std::make_unique<TimeShiftedLaw>(std::make_unique<StandardLinearSolid>(t.final), t.times.front());
     },
     describe_sls, "E_0 = 2.0\nT = 2.5\nT_eps = 3\n"},
    {"prony", "relaxation E(t) = E_inf + sum E_i exp(-t/tau_i) (a DMA fit), or E_0 (1 - sum g_i (1 - exp(-t/tau_i)))",
     kPronyKeys, read_prony,
     [](const MaterialTerms& t) -> std::unique_ptr<CreepLaw> {
       return std::make_unique<PronySeries>(t.final, t.moduli, t.times);
     },
     terms, "E_inf = 1.0\nE_i = 2.0, 1.5\ntau_i = 0.5, 20\n"},
    {"kelvin", "creep J(t) = 1/E_0 + sum J_i (1 - exp(-t/lambda_i)) [+ t/eta]", kKelvinKeys, read_kelvin,
     [](const MaterialTerms& t) -> std::unique_ptr<CreepLaw> {
       return std::make_unique<KelvinSeries>(t.moduli, t.times, t.final);
     },
     terms, "E_0 = 3.0\nJ_i = 0.2, 0.5\nlambda_i = 0.1, 10\neta = 400\n"},
    {"power_law", "creep J(t) = (1 + (t/t_1)^n)/E_0", kPowerKeys, read_power,
     [](const MaterialTerms& t) -> std::unique_ptr<CreepLaw> {
       return std::make_unique<PowerLaw>(t.final, t.times.front());
     },
     describe_power, "E_0 = 2.0\nn = 0.3\nt_1 = 5\n"},
}};

}  // namespace

std::span<const MaterialLaw> material_laws() { return kLaws; }

const MaterialLaw* find_material_law(std::string_view name) {
  for (const MaterialLaw& law : kLaws) {
    if (law.name == name) return &law;
  }
  return nullptr;
}

std::string material_law_names() {
  std::string names;
  for (const MaterialLaw& law : kLaws) names += (names.empty() ? "" : ", ") + std::string(law.name);
  return names;
}

}  // namespace punchsweep::model
