#include "report/point_output.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <string>
#include <vector>

#include "map/quantities.hpp"
#include "model/laws/material.hpp"

namespace punchsweep::report {

OutputFormat read_output_format(const boost::program_options::variables_map& vm) {
  const std::string text = input::read_choice(vm, "format", {"table", "json", "csv"});
  return text == "json" ? OutputFormat::json : text == "csv" ? OutputFormat::csv : OutputFormat::table;
}
namespace {

using map::kQuantities;
using map::QuantitySpec;

std::string number(double v) { return input::json_number(v); }

/// "dt_star_ddh": d t*/d dh's key; "dlog_t_star_dlog_dh": its elasticity's.
std::string derivative_name(const model::TStarDerivative& d) { return "dt_star_d" + std::string(d.parameter->name); }
std::string elasticity_name(const model::TStarDerivative& d) { return "dlog_t_star_dlog_" + std::string(d.parameter->name); }
bool is_temperature(const model::TStarDerivative& d) { return d.parameter->name == model::temperature_parameter().name; }

bool is_point(const QuantitySpec& q) { return q.source == map::Source::model && q.extent == map::Extent::point; }
bool is_series(const QuantitySpec& q) { return q.source == map::Source::model && q.extent == map::Extent::series; }

// A flag quantity's value as the point command names it.
std::string flag_text(const QuantitySpec& q, const model::PointResult& r) {
  if (q.flags == map::Flags::regime) return std::string(model::regime_name(r.regime));
  return std::string(model::validity_name(r.validity));
}

/// The JSON object's lines: the point's fields, then its series in a "series" object.
struct JsonFields final : PointFields {
  std::ostream& out;
  bool in_series = false;
  explicit JsonFields(std::ostream& o) : out(o) {}
  void text(std::string_view name, const std::string& value) override {
    out << "  \"" << name << "\": " << input::json_string(value) << ",\n";
  }
  void boolean(std::string_view name, bool value) override {
    out << "  \"" << name << "\": " << (value ? "true" : "false") << ",\n";
  }
  void number(std::string_view name, double value) override {
    out << "  \"" << name << "\": " << punchsweep::input::json_number(value) << ",\n";
  }
  void series(std::string_view name, const std::vector<double>& values) override {
    out << (in_series ? ",\n    \"" : "  \"series\": {\n    \"") << name << "\": " << input::json_array(values);
    in_series = true;
  }
};

void write_physical(std::ostream& out, const std::vector<PhysicalField>& physical) {
  out << ",\n  \"physical\": {";
  bool first = true;
  for (const PhysicalField& f : physical) {
    if (f.series) continue;
    out << (first ? "\n    \"" : ",\n    \"") << f.name << "\": " << number(f.values.front());
    first = false;
  }
  out << ",\n    \"series\": {";
  first = true;
  for (const PhysicalField& f : physical) {
    if (!f.series) continue;
    out << (first ? "\n      \"" : ",\n      \"") << f.name << "\": " << input::json_array(f.values);
    first = false;
  }
  out << "\n    }\n  },\n  \"units\": {";
  first = true;
  for (const PhysicalField& f : physical) {
    out << (first ? "\n    \"" : ",\n    \"") << f.name << "\": " << input::json_string(f.units);
    first = false;
  }
  out << "\n  }";
}

void write_json(std::ostream& out, const input::PointInputs& inputs, const model::PointResult& r) {
  out << "{\n";
  // The model, where it is not the paper's (whose output keeps its form).
  if (!inputs.problem.localization.is_paper()) {
    out << "  \"localization\": " << input::json_string(inputs.problem.localization.spelling()) << ",\n";
  }
  JsonFields fields(out);
  visit_point(r, inputs.time_unit, fields);
  out << "\n  }";
  if (const std::vector<PhysicalField> physical = physical_fields(inputs, r); !physical.empty()) {
    write_physical(out, physical);
  }
  if (!inputs.notes.empty()) {
    out << ",\n  \"notes\": [";
    for (std::size_t k = 0; k < inputs.notes.size(); ++k) out << (k ? ", " : "") << input::json_string(inputs.notes[k]);
    out << "]";
  }
  out << "\n}\n";
}

}  // namespace

void visit_point(const model::PointResult& r, std::string_view time_unit, PointFields& fields) {
  for (const QuantitySpec& q : kQuantities) {
    if (!is_point(q)) continue;
    if (q.flags == map::Flags::validity) {
      fields.boolean(q.name, r.valid());
      fields.text("reason", r.reason(time_unit));
    } else if (q.kind == map::Kind::flag) {
      fields.text(q.name, flag_text(q, r));
    } else {
      fields.number(q.name, q.value(r));
    }
  }
  fields.text("advisories", r.advisories);
  fields.text("advisory_reason", r.advisory_reason);
  fields.number("strain", r.strain);
  for (const model::TStarDerivative& d : r.t_star_derivatives) {
    fields.number(derivative_name(d), d.derivative);
    if (!is_temperature(d)) fields.number(elasticity_name(d), d.elasticity);
  }
  if (r.t_star_range) {
    fields.number("t_star_low", r.t_star_range->low);
    fields.number("t_star_high", r.t_star_range->high);
    // How many corners of the box fall in each regime: t_star_high null with corners_never
    // > 0 is "never at some corner", with corners_not_computed > 0 "not computed".
    fields.number("corners_immediate", r.t_star_range->immediate);
    fields.number("corners_delayed", r.t_star_range->delayed);
    fields.number("corners_never", r.t_star_range->never);
    fields.number("corners_not_computed", r.t_star_range->not_computed);
  }
  std::vector<double> column(r.series.size());
  for (std::size_t i = 0; i < r.series.size(); ++i) column[i] = r.series[i].t;
  fields.series("t", column);
  for (const QuantitySpec& q : kQuantities) {
    if (!is_series(q)) continue;
    for (std::size_t i = 0; i < r.series.size(); ++i) column[i] = q.series_value(r.series[i]);
    fields.series(q.name, column);
  }
}

namespace {
std::string significant(double v, int digits);
}  // namespace

std::vector<PhysicalField> physical_fields(const input::PointInputs& inputs, const model::PointResult& r) {
  std::vector<PhysicalField> fields;
  const input::PhysicalScales& scales = inputs.scales;
  if (!scales.R && !scales.E0_star) return fields;
  const auto add = [&](std::string_view name, std::string_view scale, std::vector<double> values, bool series) {
    const std::optional<input::PhysicalUnit> unit = input::physical_unit(scale, scales);
    if (!unit) return;
    for (double& v : values) v *= unit->per_scaled;
    fields.push_back({std::string(name), std::move(values), series, unit->units});
  };
  if (scales.R) fields.push_back({"R", {scales.R->number}, false, std::string(scales.R->unit->name)});
  if (scales.E0_star) fields.push_back({"E0_star", {scales.E0_star->si()}, false, "Pa"});
  for (const auto& [p, value] : inputs.values) {
    add(p->name == model::kPressure ? std::string_view("pressure") : p->name, p->scale, {value}, false);
  }
  // The inputs echoed as the user gave them: to 15 digits, so 3 R of 0.05 mm reads 0.15 mm,
  // not the product's 0.15000000000000002.
  for (PhysicalField& f : fields) f.values.front() = std::strtod(significant(f.values.front(), 15).c_str(), nullptr);
  for (const QuantitySpec& q : kQuantities) {
    if (is_point(q) && q.kind != map::Kind::flag) add(q.name, q.scale, {q.value(r)}, false);
  }
  // d t*/dx in the material's time unit per x's physical unit (s/um, s/Pa; s/K for a
  // temperature, whose scale is already physical), where the time is physical.
  if (inputs.time_unit != "T_eps") {
    for (const model::TStarDerivative& d : r.t_star_derivatives) {
      if (is_temperature(d)) {
        fields.push_back({derivative_name(d), {d.derivative}, false, inputs.time_unit + "/K"});
      } else if (const auto unit = input::physical_unit(d.parameter->scale, scales)) {
        fields.push_back({derivative_name(d), {d.derivative / unit->per_scaled}, false, inputs.time_unit + "/" + unit->units});
      }
    }
    if (r.t_star_range) {
      fields.push_back({"t_star_low", {r.t_star_range->low}, false, inputs.time_unit});
      fields.push_back({"t_star_high", {r.t_star_range->high}, false, inputs.time_unit});
    }
  }
  std::vector<double> column(r.series.size());
  for (std::size_t i = 0; i < r.series.size(); ++i) column[i] = r.series[i].t;
  add("t", "T_eps", column, true);
  for (const QuantitySpec& q : kQuantities) {
    if (!is_series(q)) continue;
    for (std::size_t i = 0; i < r.series.size(); ++i) column[i] = q.series_value(r.series[i]);
    add(q.name, q.scale, column, true);
  }
  return fields;
}

namespace {

// Units as people read them in the table and the CSV comments.
std::string display_units(const QuantitySpec& q, const std::string& time_unit) {
  if (q.scale == "R^2 E0/(1-nu^2)") return "R^2 E0*";
  if (q.scale == "T_eps") return time_unit;
  return q.scale == "1" ? std::string() : std::string(q.scale);
}

// `digits` significant digits, for a number quoted beside the results (not one of them).
std::string significant(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string fixed(double v, int width, int precision) {
  if (!std::isfinite(v)) return std::string(static_cast<std::size_t>(width) - 3, ' ') + "nan";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%*.*f", width, precision, v);
  return buf;
}

void write_table(std::ostream& out, const input::PointInputs& inputs, const model::PointResult& r) {
  out << "punchsweep point: " << inputs.describe() << "\n"
      << "  (units: lengths in R, pressures in E0* = E0/(1-nu^2), loads in R^2 E0*, time in " << inputs.time_unit
      << ")\n";
  if (inputs.material) {
    out << "  material: " << inputs.material->describe() << "\n"
        << "  E0* = E0/(1-nu^2) = " << significant(inputs.material->plane_strain_modulus_Pa(), 6) << " Pa\n";
  }
  out << "\n";
  for (const QuantitySpec& q : kQuantities) {
    if (!is_point(q)) continue;
    std::string name(q.name);
    name.resize(20, ' ');
    std::string value;
    if (q.flags == map::Flags::validity) {
      value = r.valid() ? "yes" : "no (" + flag_text(q, r) + "): " + r.reason(inputs.time_unit);
    } else if (q.kind == map::Kind::flag) {
      value = flag_text(q, r);
    } else if (!r.t_star && q.value == map::quantity_access::t_star) {
      value = "none (never)";
    } else {
      value = number(q.value(r));
      if (const std::string u = display_units(q, inputs.time_unit); !u.empty()) value += " " + u;
      // The physical value beside a scaled one, where the scale is known (R given: um).
      if (const auto unit = input::physical_unit(q.scale, inputs.scales); unit && q.scale != "T_eps") {
        value += " (" + significant(q.value(r) * unit->per_scaled, 6) + " " + unit->units + ")";
      }
      if (q.value == map::quantity_access::h_0 && inputs.problem.loading.jump() == 0.0) {
        value += " (unloaded at t = 0: the load rises from 0)";
      }
    }
    out << "  " << name << value << "\n";
    if (q.flags == map::Flags::validity && !inputs.problem.localization.periodic) {
      out << (inputs.problem.localization.is_paper() ? "  A1, A2 (frozen)     " : "  A1, A2 at the start ")
          << number(r.radii.A1) << " R, " << number(r.radii.A2) << " R\n";
    }
  }
  out << "  strain              " << significant(r.strain, 4) << " (0.2 f'(a) at the largest contact radius)\n";
  if (!r.advisories.empty()) out << "  advisories          " << r.advisories << ": " << r.advisory_reason << "\n";
  if (!r.t_star_derivatives.empty()) {
    out << "  sensitivity of t*:  d t*/dx (x/t* d t*/dx)";
    bool any = false;
    for (const model::TStarDerivative& d : r.t_star_derivatives) {
      if (std::isnan(d.derivative)) continue;
      any = true;
      out << "\n    " << d.parameter->name << ": " << significant(d.derivative, 6) << " " << inputs.time_unit << " per "
          << (d.parameter->scale == "1" ? "1" : std::string(d.parameter->scale));
      if (!is_temperature(d)) out << " (" << significant(d.elasticity, 4) << ")";
      if (const auto unit = input::physical_unit(d.parameter->scale, inputs.scales); unit && inputs.time_unit != "T_eps") {
        out << ": " << significant(d.derivative / unit->per_scaled, 6) << " " << inputs.time_unit << "/" << unit->units;
      }
    }
    out << (any ? "\n" : ": none (t* is not delayed here, or not smooth within the step)\n");
    if (const std::string note = model::knife_edge_note(r.t_star_derivatives); !note.empty()) out << "  note: " << note << "\n";
  }
  if (r.t_star_range) {
    const auto text = [&](double t) { return std::isinf(t) ? std::string("never") : number(t) + " " + inputs.time_unit; };
    const model::TStarRange& b = *r.t_star_range;
    out << "  t* over the tolerances: ";
    if (b.not_computed > 0) {
      out << "not computed";
    } else {
      out << text(b.low) << " to " << text(b.high);
    }
    std::string counts;
    for (const auto& [n, name] : {std::pair{b.immediate, "immediate"}, std::pair{b.delayed, "delayed"},
                                  std::pair{b.never, "never"}, std::pair{b.not_computed, "not computed"}}) {
      if (n > 0) counts += (counts.empty() ? "" : ", ") + std::to_string(n) + " " + name;
    }
    out << " (corners of the box: " << counts << ")\n";
  }
  for (const std::string& note : inputs.notes) out << "  note: " << note << "\n";
  // The series' columns: each head with its unit, 12 wide (15 for a long head).
  struct Column {
    const QuantitySpec* q;
    std::string head;
    int width;
  };
  std::vector<Column> columns;
  for (const QuantitySpec& q : kQuantities) {
    if (!is_series(q)) continue;
    const std::string u = display_units(q, inputs.time_unit);
    std::string head = std::string(q.name) + (u.empty() ? "" : " [" + u + "]");
    const int width = head.size() < 12 ? 12 : 15;
    columns.push_back({&q, std::move(head), width});
  }
  std::string t_head = "t [" + inputs.time_unit + "]";
  if (t_head.size() < 12) t_head.insert(0, 12 - t_head.size(), ' ');
  out << "\n" << t_head;
  for (const Column& c : columns) out << std::string(static_cast<std::size_t>(c.width) - c.head.size(), ' ') << c.head;
  out << "\n";
  for (const model::Snapshot& s : r.series) {
    out << fixed(s.t, 12, 4);
    for (const Column& c : columns) {
      out << fixed(c.q->series_value(s), c.width, c.q->scale == "R^2 E0/(1-nu^2)" ? 9 : 7);
    }
    out << "\n";
  }
}

std::string csv_number(double v) { return std::isfinite(v) ? number(v) : "nan"; }

void write_csv(std::ostream& out, const input::PointInputs& inputs, const model::PointResult& r) {
  out << "# punchsweep point: " << inputs.describe() << "\n";
  for (const QuantitySpec& q : kQuantities) {
    if (!is_point(q)) continue;
    if (q.flags == map::Flags::validity) {
      out << "# " << q.name << " = " << (r.valid() ? "true" : "false") << "\n# reason = " << r.reason(inputs.time_unit) << "\n";
    } else if (q.kind == map::Kind::flag) {
      out << "# " << q.name << " = " << flag_text(q, r) << "\n";
    } else if (!r.t_star && q.value == map::quantity_access::t_star) {
      out << "# " << q.name << " = null (never)\n";
    } else {
      const std::string u = display_units(q, inputs.time_unit);
      out << "# " << q.name << " = " << number(q.value(r)) << (u.empty() ? "" : " " + u) << "\n";
    }
  }
  std::string units = "# units: t in " + inputs.time_unit;
  std::string header = "t";
  for (const QuantitySpec& q : kQuantities) {
    if (!is_series(q)) continue;
    header += ',';
    header.append(q.name);
    if (const std::string u = display_units(q, inputs.time_unit); !u.empty()) units += ", " + std::string(q.name) + " in " + u;
  }
  out << units << "\n" << header << "\n";
  for (const model::Snapshot& s : r.series) {
    out << csv_number(s.t);
    for (const QuantitySpec& q : kQuantities) {
      if (is_series(q)) out << ',' << csv_number(q.series_value(s));
    }
    out << "\n";
  }
}

}  // namespace

void write_point(std::ostream& out, OutputFormat format, const input::PointInputs& inputs, const model::PointResult& result) {
  switch (format) {
    case OutputFormat::table: write_table(out, inputs, result); break;
    case OutputFormat::json: write_json(out, inputs, result); break;
    case OutputFormat::csv: write_csv(out, inputs, result); break;
  }
}

}  // namespace punchsweep::report
