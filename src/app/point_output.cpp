#include "app/point_output.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <string>

#include "app/command_options.hpp"

namespace punchsweep::app {
namespace {

std::string number(double v) { return json_number(v); }

std::string json_string(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

template <class Field>
std::string json_array(const model::PointResult& result, Field field) {
  std::string text = "[";
  for (std::size_t i = 0; i < result.series.size(); ++i) {
    if (i > 0) text += ", ";
    text += number(field(result.series[i]));
  }
  return text + "]";
}

void write_json(std::ostream& out, const model::PointResult& r) {
  const std::string t_star = r.t_star ? number(*r.t_star) : "null";
  out << "{\n"
      << "  \"regime\": " << json_string(std::string(model::regime_name(r.regime))) << ",\n"
      << "  \"t_star\": " << t_star << ",\n"
      << "  \"h_0\": " << number(r.h_0) << ",\n"
      << "  \"h_inf\": " << number(r.h_inf) << ",\n"
      << "  \"valid\": " << (r.valid() ? "true" : "false") << ",\n"
      << "  \"reason\": " << json_string(r.reason()) << ",\n"
      << "  \"a1_inf\": " << number(r.a1_inf) << ",\n"
      << "  \"a2_inf\": " << number(r.a2_inf) << ",\n"
      << "  \"area_fraction_inf\": " << number(r.area_fraction_inf) << ",\n"
      << "  \"series\": {\n"
      << "    \"t\": " << json_array(r, [](const model::Snapshot& s) { return s.t; }) << ",\n"
      << "    \"a1\": " << json_array(r, [](const model::Snapshot& s) { return s.a1; }) << ",\n"
      << "    \"a2\": " << json_array(r, [](const model::Snapshot& s) { return s.a2; }) << ",\n"
      << "    \"P1\": " << json_array(r, [](const model::Snapshot& s) { return s.P1; }) << ",\n"
      << "    \"P2\": " << json_array(r, [](const model::Snapshot& s) { return s.P2; }) << ",\n"
      << "    \"area_fraction\": "
      << json_array(r, [](const model::Snapshot& s) { return s.area_fraction; }) << "\n"
      << "  }\n"
      << "}\n";
}

std::string fixed(double v, int width, int precision) {
  if (!std::isfinite(v)) return std::string(static_cast<std::size_t>(width) - 3, ' ') + "nan";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%*.*f", width, precision, v);
  return buf;
}

void write_table(std::ostream& out, const model::ContactProblem& p,
                 const model::StandardLinearSolid& creep, const model::PointResult& r) {
  out << "punchsweep point: l = " << number(p.l) << " R, dh = " << number(p.dh)
      << " R, T = " << number(creep.creep_ratio()) << ", pbar0 = " << number(p.pbar0)
      << " E0*, s = " << p.shape.s << ", C = " << number(p.shape.C) << "\n"
      << "  (units: lengths in R, pressures in E0* = E0/(1-nu^2), loads in R^2 E0*, time in T_eps)\n\n"
      << "  regime              " << model::regime_name(r.regime) << "\n"
      << "  t_star              " << (r.t_star ? number(*r.t_star) + " T_eps" : "none (never)") << "\n"
      << "  h_0                 " << number(r.h_0) << " R\n"
      << "  h_inf               " << number(r.h_inf) << " R\n"
      << "  valid               "
      << (r.valid() ? std::string("yes")
                    : "no (" + std::string(model::validity_name(r.validity)) + "): " + r.reason())
      << "\n"
      << "  A1, A2 (frozen)     " << number(r.radii.A1) << " R, " << number(r.radii.A2) << " R\n"
      << "  a1_inf              " << number(r.a1_inf) << " R\n"
      << "  a2_inf              " << number(r.a2_inf) << " R\n"
      << "  area_fraction_inf   " << number(r.area_fraction_inf) << "\n\n"
      << "   t [T_eps]      a1 [R]      a2 [R]   P1 [R^2 E0*]   P2 [R^2 E0*]  area_fraction\n";
  for (const model::Snapshot& s : r.series) {
    out << fixed(s.t, 12, 4) << fixed(s.a1, 12, 7) << fixed(s.a2, 12, 7) << fixed(s.P1, 15, 9)
        << fixed(s.P2, 15, 9) << fixed(s.area_fraction, 15, 7) << "\n";
  }
}

std::string csv_number(double v) { return std::isfinite(v) ? number(v) : "nan"; }

void write_csv(std::ostream& out, const model::ContactProblem& p,
               const model::StandardLinearSolid& creep, const model::PointResult& r) {
  out << "# punchsweep point: l = " << number(p.l) << " R, dh = " << number(p.dh)
      << " R, T = " << number(creep.creep_ratio()) << ", pbar0 = " << number(p.pbar0)
      << " E0*, s = " << p.shape.s << ", C = " << number(p.shape.C) << "\n"
      << "# regime = " << model::regime_name(r.regime) << "\n"
      << "# t_star = " << (r.t_star ? number(*r.t_star) + " T_eps" : "null (never)") << "\n"
      << "# h_0 = " << number(r.h_0) << " R\n"
      << "# h_inf = " << number(r.h_inf) << " R\n"
      << "# valid = " << (r.valid() ? "true" : "false") << "\n"
      << "# reason = " << r.reason() << "\n"
      << "# a1_inf = " << number(r.a1_inf) << " R\n"
      << "# a2_inf = " << number(r.a2_inf) << " R\n"
      << "# area_fraction_inf = " << number(r.area_fraction_inf) << "\n"
      << "# units: t in T_eps, a1 and a2 in R, P1 and P2 in R^2 E0*\n"
      << "t,a1,a2,P1,P2,area_fraction\n";
  for (const model::Snapshot& s : r.series) {
    out << csv_number(s.t) << ',' << csv_number(s.a1) << ',' << csv_number(s.a2) << ','
        << csv_number(s.P1) << ',' << csv_number(s.P2) << ',' << csv_number(s.area_fraction)
        << "\n";
  }
}

}  // namespace

void write_point(std::ostream& out, OutputFormat format, const model::ContactProblem& problem,
                 const model::StandardLinearSolid& creep, const model::PointResult& result) {
  switch (format) {
    case OutputFormat::table: write_table(out, problem, creep, result); break;
    case OutputFormat::json: write_json(out, result); break;
    case OutputFormat::csv: write_csv(out, problem, creep, result); break;
  }
}

}  // namespace punchsweep::app
