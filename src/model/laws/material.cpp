#include "model/laws/material.hpp"

#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>

#include "model/laws/kelvin_series.hpp"
#include "model/numerics/number_text.hpp"
#include "model/laws/power_law.hpp"
#include "model/laws/prony_series.hpp"
#include "model/numerics/units.hpp"

namespace punchsweep::model {
namespace {

/// The keys a file may hold, by section, and which of them are lists.
struct KeyRule {
  std::string_view section, key;
  bool list;
};
constexpr KeyRule kKeys[] = {
    {"material", "name", false},   {"material", "law", false},     {"material", "modulus_unit", false},
    {"material", "time_unit", false}, {"material", "poisson", false}, {"material", "E_inf", false},
    {"material", "E_0", false},    {"material", "E_i", true},      {"material", "g_i", true},
    {"material", "tau_i", true},   {"material", "J_i", true},      {"material", "lambda_i", true},
    {"material", "eta", false},    {"material", "n", false},       {"material", "t_1", false},
    {"shift", "kind", false},       {"shift", "C1", false},
    {"shift", "C2", false},        {"shift", "T_ref", false},      {"shift", "E_a", false},
    {"shift", "E_a_below", false}, {"shift", "T_min", false},      {"shift", "T_max", false},
};

/// The parsed file: values by "section.key", with their line for messages.
class Entries {
 public:
  Entries(std::string_view text, std::string origin) : origin_(std::move(origin)) {
    std::string section;
    std::size_t line_number = 0;
    std::size_t start = 0;
    if (text.substr(0, 3) == "\xEF\xBB\xBF") start = 3;  // a UTF-8 byte-order mark
    while (start <= text.size()) {
      std::size_t end = text.find('\n', start);
      if (end == std::string_view::npos) end = text.size();
      ++line_number;
      std::string line(text.substr(start, end - start));
      start = end + 1;
      if (const auto hash = line.find_first_of("#;"); hash != std::string::npos) line.erase(hash);
      line = std::string(trim(line));
      if (line.empty()) continue;
      if (line.front() == '[') {
        if (line.back() != ']') fail(line_number, "'" + line + "' is not a section header; valid: [material] or [shift]");
        section = std::string(trim(std::string_view(line).substr(1, line.size() - 2)));
        if (section != "material" && section != "shift") {
          fail(line_number, "unknown section [" + section + "]; valid: [material] and an optional [shift]");
        }
        if (!sections_.insert(section).second) fail(line_number, "section [" + section + "] appears twice");
        continue;
      }
      const auto eq = line.find('=');
      if (eq == std::string::npos) fail(line_number, "'" + line + "' is not 'key = value'");
      if (section.empty()) fail(line_number, "'" + line + "' comes before any section; valid: [material] first");
      const std::string key(trim(std::string_view(line).substr(0, eq)));
      const std::string value(trim(std::string_view(line).substr(eq + 1)));
      bool known = false;
      for (const KeyRule& rule : kKeys) known = known || (rule.section == section && rule.key == key);
      if (!known) fail(line_number, "[" + section + "] has no key '" + key + "'; valid: " + valid_keys(section));
      const std::string id = section + "." + key;
      if (values_.count(id)) fail(line_number, "[" + section + "] " + key + " is given twice");
      if (value.empty()) fail(line_number, "[" + section + "] " + key + " has no value");
      values_[id] = {value, line_number};
    }
  }

  bool has_section(const std::string& s) const { return sections_.count(s) > 0; }
  bool has(const std::string& id) const { return values_.count(id) > 0; }

  const std::string& text(const std::string& id) const {
    const auto it = values_.find(id);
    if (it == values_.end()) fail_key(id, "is missing");
    read_.insert(id);
    return it->second.value;
  }

  /// Refuses the first key given but never read by the law (or the shift) the file names,
  /// listing the keys that were: a stray `n = 0.3` in a Prony file is not silently dropped.
  void refuse_unread(const std::string& material_what, const std::string& shift_what) const {
    for (const auto& [id, entry] : values_) {
      if (read_.count(id)) continue;
      const std::string section = id.substr(0, id.find('.'));
      const std::string& what = section == "material" ? material_what : shift_what;
      std::string used;
      for (const std::string& r : read_) {
        if (r.substr(0, r.find('.')) != section) continue;
        used += (used.empty() ? "" : ", ") + r.substr(r.find('.') + 1);
      }
      fail_value(id, "not a key of " + what + " (the keys it reads here: " + used + ")");
    }
  }

  double number(const std::string& id) const {
    const std::vector<double> v = parse_numbers(id);
    if (v.size() != 1) fail_value(id, "must be one number");
    return v.front();
  }

  std::vector<double> list(const std::string& id) const { return parse_numbers(id); }

  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw MaterialError(origin_ + ":" + std::to_string(line) + ": " + what);
  }
  [[noreturn]] void fail_key(const std::string& id, const std::string& what) const {
    const auto dot = id.find('.');
    throw MaterialError(origin_ + ": [" + id.substr(0, dot) + "] " + id.substr(dot + 1) + " " + what);
  }
  /// "[section] key = VALUE: what".
  [[noreturn]] void fail_value(const std::string& id, const std::string& what) const {
    const auto dot = id.find('.');
    const Entry& e = values_.at(id);
    throw MaterialError(origin_ + ":" + std::to_string(e.line) + ": [" + id.substr(0, dot) + "] " +
                        id.substr(dot + 1) + " = " + e.value + ": " + what);
  }

 private:
  struct Entry {
    std::string value;
    std::size_t line = 0;
  };

  static std::string valid_keys(const std::string& section) {
    std::string out;
    for (const KeyRule& rule : kKeys) {
      if (rule.section == section) out += (out.empty() ? "" : ", ") + std::string(rule.key);
    }
    return out;
  }

  std::vector<double> parse_numbers(const std::string& id) const {
    const std::string& value = text(id);
    std::vector<double> out;
    std::string item;
    std::istringstream in(value);
    while (std::getline(in, item, ',')) {
      item = std::string(trim(item));
      char* end = nullptr;
      const double v = std::strtod(item.c_str(), &end);
      if (item.empty() || end != item.c_str() + item.size()) fail_value(id, "'" + item + "' is not a number");
      if (!std::isfinite(v)) fail_value(id, "'" + item + "' is not finite");
      out.push_back(v);
    }
    return out;
  }

  std::string origin_;
  std::set<std::string> sections_;
  std::map<std::string, Entry> values_;
  mutable std::set<std::string> read_;  ///< the keys the parse asked for
};


/// Strictly increasing, positive times; every entry of `moduli` positive; the same count.
void check_terms(const Entries& f, const std::string& moduli_key, const std::vector<double>& moduli,
                 const std::string& times_key, const std::vector<double>& times, const std::string& modulus_range) {
  if (moduli.size() != times.size()) {
    f.fail_value(times_key, std::to_string(times.size()) + " times for " + std::to_string(moduli.size()) + " values of " +
                                moduli_key.substr(moduli_key.find('.') + 1) + "; valid: one time per term");
  }
  for (std::size_t i = 0; i < moduli.size(); ++i) {
    if (!(moduli[i] > 0.0)) {
      f.fail_value(moduli_key, "term " + std::to_string(i + 1) + " = " + number_text(moduli[i], 10) + " is outside its range: " +
                                   modulus_range);
    }
    if (!(times[i] > 0.0)) {
      f.fail_value(times_key, "term " + std::to_string(i + 1) + " = " + number_text(times[i], 10) +
                                  " is outside its range: times > 0");
    }
    if (i > 0 && !(times[i] > times[i - 1])) {
      f.fail_value(times_key, "term " + std::to_string(i + 1) + " = " + number_text(times[i], 10) +
                                  " does not exceed the one before it (" + number_text(times[i - 1], 10) +
                                  "); valid: strictly increasing times (a repeated time is one term)");
    }
  }
}

}  // namespace

const Parameter& temperature_parameter() {
  static const Parameter kTemperature{"temperature",
                                      "degC",
                                      "temperature",
                                      "temperature, in degC (a material with a [shift] only)",
                                      "temperature > -273.15 (in degC) and in the material's shift range",
                                      [](double v) { return v > -kZeroCelsius; },
                                      false,
                                      {},
                                      "20",
                                      "the material's reference temperature (its [shift] T_ref)"};
  return kTemperature;
}

const Parameter& material_parameter() {
  static const Parameter kMaterial{"material",
                                   "1",
                                   "material",
                                   "the material, one of the sweep's material files",
                                   "one of the material files given",
                                   [](double v) { return v >= 0.0; },
                                   true,
                                   {},
                                   {}};
  return kMaterial;
}

CreepLawSpec material_choice(std::vector<std::shared_ptr<const Material>> materials) {
  if (materials.empty()) throw std::invalid_argument("material_choice: no materials");
  const Material& first = *materials.front();
  for (const auto& m : materials) {
    if (m->time_unit() != first.time_unit()) {
      throw std::invalid_argument("the materials' time units differ (" + first.time_unit() + " and " + m->time_unit() +
                                  "); valid: one time_unit for every material of a map");
    }
    if (m->shift().has_value() != first.shift().has_value()) {
      throw std::invalid_argument("some materials have a [shift] and some do not; valid: all or none (a map has one "
                                  "temperature axis or none)");
    }
  }
  struct Held {
    std::vector<std::shared_ptr<const Material>> materials;
    std::vector<Parameter> parameters;
  };
  auto held = std::make_shared<Held>();
  held->materials = std::move(materials);
  held->parameters.push_back(material_parameter());
  if (first.shift()) held->parameters.push_back(temperature_parameter());
  const std::span<const Parameter> parameters(held->parameters);
  return CreepLawSpec{"material", {}, "one of several material files", parameters,
                      [held](std::span<const double> values) {
                        const auto k = static_cast<std::size_t>(values[0]);
                        if (k >= held->materials.size()) {
                          throw std::invalid_argument("material index " + std::to_string(k) + " is outside its range");
                        }
                        return held->materials[k]->make(values.subspan(1));
                      }};
}

Material Material::parse(std::string_view text, std::string_view origin) {
  const Entries f(text, std::string(origin));
  Material m;
  m.text_ = std::string(text);
  if (!f.has_section("material")) throw MaterialError(std::string(origin) + ": no [material] section");
  m.name_ = f.text("material.name");
  m.law_ = f.text("material.law");
  const Unit* modulus = find_unit(Dimension::pressure, f.text("material.modulus_unit"));
  if (!modulus) f.fail_value("material.modulus_unit", "unknown unit; valid: " + unit_names(Dimension::pressure));
  m.time_unit_ = f.text("material.time_unit");
  if (!find_unit(Dimension::time, m.time_unit_)) f.fail_value("material.time_unit", "unknown unit; valid: " + unit_names(Dimension::time));
  m.nu_ = f.number("material.poisson");
  if (!(m.nu_ > -1.0 && m.nu_ <= 0.5)) f.fail_value("material.poisson", "outside its range: -1 < poisson <= 0.5");

  const auto forbid = [&](std::initializer_list<const char*> keys, const std::string& why) {
    for (const char* key : keys) {
      if (f.has(std::string("material.") + key)) f.fail_value(std::string("material.") + key, why);
    }
  };
  double E0 = 0.0;
  if (m.law_ == "prony") {
    forbid({"J_i", "lambda_i", "eta"}, "not a key of law = prony (those are law = kelvin's)");
    const std::vector<double> tau = f.list("material.tau_i");
    if (f.has("material.g_i") || f.has("material.E_0")) {
      // Normalized (Abaqus): E_0 and g_i, g_R(t) = 1 - sum g_i (1 - exp(-t/tau_i)).
      forbid({"E_inf", "E_i"}, "give either E_inf with E_i, or E_0 with g_i, not both");
      E0 = f.number("material.E_0");
      if (!(E0 > 0.0)) f.fail_value("material.E_0", "outside its range: E_0 > 0");
      m.moduli_ = f.list("material.g_i");
      check_terms(f, "material.g_i", m.moduli_, "material.tau_i", tau, "g_i > 0");
      double sum = 0.0;
      for (const double g : m.moduli_) sum += g;
      if (!(sum < 1.0)) {
        f.fail_value("material.g_i", "sum g_i = " + number_text(sum, 10) + " is outside its range: sum g_i < 1 "
                                     "(E_inf = E_0 (1 - sum g_i) must be > 0)");
      }
      m.final_ = 1.0 - sum;
    } else {
      const double E_inf = f.number("material.E_inf");
      if (!(E_inf > 0.0)) f.fail_value("material.E_inf", "outside its range: E_inf > 0");
      const std::vector<double> E = f.list("material.E_i");
      check_terms(f, "material.E_i", E, "material.tau_i", tau, "E_i > 0");
      E0 = E_inf;
      for (const double e : E) E0 += e;
      m.final_ = E_inf / E0;
      for (const double e : E) m.moduli_.push_back(e / E0);
    }
    m.times_ = tau;
  } else if (m.law_ == "kelvin") {
    forbid({"E_inf", "E_i", "g_i", "tau_i"}, "not a key of law = kelvin (those are law = prony's)");
    E0 = f.number("material.E_0");
    if (!(E0 > 0.0)) f.fail_value("material.E_0", "outside its range: E_0 > 0");
    const std::vector<double> J = f.list("material.J_i");  // in 1/modulus_unit
    m.times_ = f.list("material.lambda_i");
    check_terms(f, "material.J_i", J, "material.lambda_i", m.times_, "J_i > 0 (in 1/modulus_unit)");
    for (const double j : J) m.moduli_.push_back(j * E0);
    if (f.has("material.eta")) {
      const double eta = f.number("material.eta");  // in modulus_unit * time_unit
      if (!(eta > 0.0)) f.fail_value("material.eta", "outside its range: eta > 0 (in modulus_unit time_unit)");
      m.final_ = E0 / eta;
    }
  } else if (m.law_ == "power_law") {
    forbid({"E_inf", "E_i", "g_i", "tau_i", "J_i", "lambda_i", "eta"},
           "not a key of law = power_law (its keys: E_0, n, t_1)");
    E0 = f.number("material.E_0");
    if (!(E0 > 0.0)) f.fail_value("material.E_0", "outside its range: E_0 > 0");
    m.final_ = f.number("material.n");
    if (!(m.final_ > 0.0 && m.final_ < 1.0)) f.fail_value("material.n", "outside its range: 0 < n < 1");
    const double t_1 = f.number("material.t_1");
    if (!(t_1 > 0.0)) f.fail_value("material.t_1", "outside its range: t_1 > 0 (in time_unit)");
    m.times_ = {t_1};
  } else {
    f.fail_value("material.law", "unknown law; valid: prony, kelvin, power_law");
  }
  m.E0_Pa_ = E0 * modulus->si;

  if (f.has_section("shift")) {
    TemperatureShift shift;
    const std::string kind = f.text("shift.kind");
    shift.T_ref = f.number("shift.T_ref");
    if (kind == "wlf") {
      if (f.has("shift.E_a")) f.fail_value("shift.E_a", "not a key of kind = wlf (it is kind = arrhenius's)");
      shift.kind = TemperatureShift::Kind::wlf;
      shift.C1 = f.number("shift.C1");
      shift.C2 = f.number("shift.C2");
      if (f.has("shift.E_a_below")) shift.E_a_below = f.number("shift.E_a_below");
    } else if (kind == "arrhenius") {
      for (const char* key : {"shift.C1", "shift.C2", "shift.E_a_below"}) {
        if (f.has(key)) f.fail_value(key, "not a key of kind = arrhenius (it is kind = wlf's)");
      }
      shift.kind = TemperatureShift::Kind::arrhenius;
      shift.E_a = f.number("shift.E_a");
    } else {
      f.fail_value("shift.kind", "unknown kind; valid: wlf, arrhenius");
    }
    if (f.has("shift.T_min")) shift.T_min = f.number("shift.T_min");
    if (f.has("shift.T_max")) shift.T_max = f.number("shift.T_max");
    if (std::string e = shift.error(); !e.empty()) throw MaterialError(std::string(origin) + ": [shift] " + e);
    m.shift_ = shift;
    auto temperature = std::make_shared<Temperature>(Temperature{f.text("shift.T_ref"), temperature_parameter()});
    temperature->parameter.point_default = temperature->reference;
    temperature->parameter.sweep_default = temperature->reference;
    m.temperature_ = std::move(temperature);
  }
  f.refuse_unread("law = " + m.law_, m.shift_ ? "kind = " + f.text("shift.kind") : std::string("[shift]"));
  // Build once, so that what the law's own checks refuse is refused here, with the file named.
  try {
    m.make(m.shift_ ? std::vector<double>{m.shift_->T_ref} : std::vector<double>{});
  } catch (const std::invalid_argument& e) {
    throw MaterialError(std::string(origin) + ": " + e.what());
  }
  return m;
}

std::span<const Parameter> Material::parameters() const {
  if (!shift_) return {};
  return {&temperature_->parameter, 1};
}

std::unique_ptr<CreepLaw> Material::make(std::span<const double> values) const {
  std::unique_ptr<CreepLaw> law;
  if (law_ == "prony") {
    law = std::make_unique<PronySeries>(final_, moduli_, times_);
  } else if (law_ == "power_law") {
    law = std::make_unique<PowerLaw>(final_, times_.front());
  } else {
    law = std::make_unique<KelvinSeries>(moduli_, times_, final_);
  }
  if (!shift_) return law;
  const double th = values[0];
  if (!shift_->admits(th)) {
    throw std::invalid_argument("temperature = " + number_text(th, 10) + " is outside its range: " + shift_->range());
  }
  const double a_T = std::pow(10.0, shift_->log10_factor(th));
  return std::make_unique<TimeShiftedLaw>(std::move(law), a_T);
}

CreepLawSpec Material::spec() const {
  return CreepLawSpec{law_, {}, name_, parameters(), [this](std::span<const double> values) { return make(values); }};
}

std::string Material::describe() const {
  std::ostringstream out;
  out.precision(6);
  out << name_ << "; " << law_;
  if (law_ == "power_law") {
    out << ", n = " << final_ << ", t_1 = " << times_.front();
  } else {
    out << ", " << times_.size() << " terms";
  }
  out << ", E_0 = " << E0_Pa_ << " Pa, nu = " << nu_
      << ", time in " << time_unit_;
  if (shift_) out << "; " << shift_->describe();
  return out.str();
}

}  // namespace punchsweep::model
