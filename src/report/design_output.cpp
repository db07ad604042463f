#include "report/design_output.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>

#include "input/command_options.hpp"
#include "model/numerics/number_text.hpp"
#include "model/problem/parameter.hpp"

namespace punchsweep::report {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Whether the window is of a level's drop (dh, or dh2 of a third level), not a searched range.
bool finds_drop(const engine::DesignResult& d) { return d.quantity == "dh" || d.quantity == "dh2"; }

/// The name of the drop of the level the requirements are on: dh, or dh2 (level 2 of three).
std::string drop_name(const engine::DesignResult& d) { return d.texture && d.texture->level == 2 ? "dh2" : "dh"; }

/// That drop, in R (for the paper's lattice, its dh).
double level_drop(const engine::DesignResult& d) {
  return d.texture ? d.texture->drops[static_cast<std::size_t>(d.texture->level - 1)] : d.inputs.problem.dh;
}

/// The geometry and material of the design, without what it finds or varies (the
/// quantity, the pressure, the temperature).
std::string geometry_text(const engine::DesignResult& d) {
  const input::PointInputs& in = d.inputs;
  const std::string& quantity = d.quantity;
  // (A cell file's or height map's geometry is the file's: the point's l, dh, s and C are not.)
  const bool file = d.texture && !d.texture->file.empty();
  input::PointInputs kept;
  kept.scales = in.scales;
  kept.time_unit = in.time_unit;
  for (const auto& [p, v] : in.values) {
    const bool geometry = p->name == model::kPitch || p->name == model::kHeightDifference || p->name == model::kExponent ||
                          p->name == model::kShapeConstant;
    if (p->name != quantity && p->name != model::kPressure && p->name != model::temperature_parameter().name &&
        !(file && geometry)) {
      kept.values.emplace_back(p, v);
    }
  }
  std::string text = kept.describe();
  if (text.rfind(", ", 0) == 0) text.erase(0, 2);  // (a file's geometry left out, the scales remain)
  if (in.material) text += "; material " + in.material->name();
  return text;
}

/// A texture's design in words: its lattice and levels, the level the requirements are on,
/// the fixed drops and the grid (empty for the paper's lattice by the model).
std::string texture_text(const engine::DesignResult& d, const engine::Unit& L) {
  if (!d.texture) return "";
  const engine::DesignTexture& t = *d.texture;
  std::string text = (t.file.empty() ? t.lattice + " lattice" : t.lattice + " " + t.file) + " of " +
                     std::to_string(t.levels) + " levels; the requirements on level " + std::to_string(t.level);
  if (t.levels == 3 && d.quantity != "dh2" && t.file.empty()) {
    text += "; level 2 at dh2 = " + model::number_text(t.drops[1] * L.per, 4) + " " + L.unit;
  }
  if (t.caps > 0) {
    text += t.supercell > 1 ? "; a " + std::to_string(t.supercell) + " x " + std::to_string(t.supercell) + " supercell of " +
                                  std::to_string(t.caps) + " caps"
                            : "; " + std::to_string(t.caps) + " caps";
    text += (t.scatter.empty() ? "" : ", heights " + t.scatter + " (seed " + t.seed + ")") +
            (d.quantity == model::kPressure ? ", read off the load curve of every cap"
                                            : ", the level's caps moved as one (each keeps its offset)");
  }
  if (t.solves == 0 && t.small_spot > 0) {
    // Every closure in the small-spot limit: no grid was read.
    return text + "; every closure in the small-spot limit (the spots in contact within 0.2 of their distances: no grid)";
  }
  text += t.small_spot > 0 ? "; the small-spot limit where the spots in contact are small, else the cell's boundary elements on "
                           : "; the cell's boundary elements on ";
  text += std::to_string(t.nodes) + " nodes a pitch";
  if (t.coarser > 0) {
    text += " (--grid auto: edges within " + model::number_text(t.grid_move, 2) + " of those on " + std::to_string(t.coarser) + ")";
  }
  return text;
}

std::string tolerance_text(const engine::DesignResult& d, const engine::Unit& L) {
  std::vector<std::string> parts;
  if (d.tolerance.dh > 0) parts.push_back(drop_name(d) + " +- " + model::number_text(d.tolerance.dh * L.per, 4) + " " + L.unit);
  if (d.tolerance.pressure > 0) {
    parts.push_back("pressure +- " + (d.tolerance.pressure_absolute ? engine::pressure_text(d.tolerance.pressure, d.inputs)
                                                          : model::number_text(100 * d.tolerance.pressure, 4) + "%"));
  }
  if (d.tolerance.l > 0) {
    parts.push_back("l +- " + (d.tolerance.l_absolute ? model::number_text(d.tolerance.l * L.per, 4) + " " + L.unit
                                            : model::number_text(100 * d.tolerance.l, 4) + "%"));
  }
  if (d.tolerance.C > 0) parts.push_back("C +- " + model::number_text(100 * d.tolerance.C, 4) + "%");
  std::string t;
  for (const std::string& p : parts) t += (t.empty() ? "" : ", ") + p;
  return t;
}

std::string where_text(const engine::RequirementBound& r, const engine::DesignResult& d, const engine::Unit& L, bool touch) {
  const engine::DesignBound& b = r.binding;
  std::string t;
  if (r.every_temperature) {
    t += "every temperature, ";
  } else if (!std::isnan(b.temperature)) {
    t += model::number_text(b.temperature, 4) + " degC, ";
  }
  if (d.quantity != model::kPressure) t += engine::pressure_text(b.pbar, d.inputs) + ", ";
  if (d.quantity != "l" && d.tolerance.l > 0) t += "l = " + model::number_text(b.l * L.per, 4) + " " + L.unit + ", ";
  if (d.tolerance.C > 0) t += "C = " + model::number_text(b.C, 4) + ", ";
  if (!finds_drop(d)) {
    t += drop_name(d) + " = " + model::number_text(b.dh * L.per, 4) + " " + L.unit;
  } else if (d.tolerance.dh > 0) {
    t += drop_name(d) + (touch ? " + " : " - ") + model::number_text(d.tolerance.dh * L.per, 4) + " " + L.unit;
  }
  if (t.size() >= 2 && t.compare(t.size() - 2, 2, ", ") == 0) t.resize(t.size() - 2);
  return t;
}

/// What the window is of, as the table says it: dh, dh2, l or pressure.
std::string quantity_name(const engine::DesignResult& d) { return d.quantity == model::kPressure ? "pressure" : d.quantity; }

/// The window's quantity in its physical unit (R's for dh and l, kPa or the like for the
/// pressure).
engine::Unit quantity_unit(const engine::DesignResult& d) {
  return d.quantity == model::kPressure ? engine::pressure_unit(d.inputs, d.search_hi) : engine::length_unit(d.inputs);
}

/// A requirement's advisories at its edge as sentences ("" for none raised): which caps,
/// then point's reasons.
std::string edge_advisory_text(const engine::RequirementBound& b) {
  if (b.advice.raised.empty()) return "";
  return std::string("at the edge, in the long term, on the ") +
         (b.advice_level < 0 ? std::string("tall caps") : "widest caps, level " + std::to_string(b.advice_level) + "'s") +
         ": " + b.advice.reason(0.0);
}

/// What to say where no value meets every requirement: the nearest miss (in the quantity's
/// unit `L`).
std::string miss_text(const engine::DesignResult& d, const engine::Unit& L) {
  const std::string q = quantity_name(d);
  if (!std::isfinite(d.lower) || !std::isfinite(d.upper)) {
    return finds_drop(d) ? "no " + q + ": a requirement holds at no " + q + " (see the notes)"
                     : "no " + std::string(q == "l" ? "pitch" : "pressure") +
                           " of the range searched: a requirement holds at none of them (see the notes)";
  }
  const double gap = d.lower - d.upper;
  std::string t = "the nearest miss is " + q + " = " + model::number_text(0.5 * (d.lower + d.upper) * L.per, 4) +
                  " " + L.unit + ", short of both edges by " + model::number_text(0.5 * gap * L.per, 4) + " " + L.unit;
  // The window with an exact value (the bounds before the quantity's own tolerance) and the
  // tolerance that would leave it a point.
  double exact_lower = finds_drop(d) ? 0.0 : d.search_lo, exact_upper = finds_drop(d) ? kInf : d.search_hi;
  for (const engine::RequirementBound& b : d.bounds) {
    (b.upper ? exact_upper : exact_lower) =
        b.upper ? std::min(exact_upper, b.binding.value) : std::max(exact_lower, b.binding.value);
  }
  const engine::OwnTolerance own = engine::own_tolerance(d.tolerance, d.quantity);
  if (!(exact_lower <= exact_upper) || own.width == 0.0) {
    t += "; not even an exact " + q + " meets every requirement";
  } else if (own.relative) {
    const double ratio = exact_upper / exact_lower;  // edges e/(1 -+ t) meet at t = (ratio - 1)/(ratio + 1)
    t += "; a " + q + " tolerance of +- " + model::number_text(100 * (ratio - 1) / (ratio + 1), 4) +
         "% or less would meet every requirement";
  } else {
    t += "; a " + q + " tolerance of +- " + model::number_text(0.5 * (exact_upper - exact_lower) * L.per, 4) + " " +
         L.unit + " or less would meet every requirement";
  }
  return t;
}

}  // namespace

std::string design_json(const engine::DesignResult& d) {
  const engine::Unit L = engine::length_unit(d.inputs), Q = quantity_unit(d);
  const bool by_pressure = d.quantity == model::kPressure;
  const auto pressure = input::physical_unit("E0/(1-nu^2)", d.inputs.scales);
  const double E0_star_Pa = pressure ? pressure->per_scaled : kNaN;
  std::ostringstream s;
  const auto num = [](double v) { return input::json_number(v); };
  s << "{\"quantity\": " << input::json_string(d.quantity) << ", \"unit\": \"" << (by_pressure ? "E0/(1-nu^2)" : "R")
    << "\", \"lower\": " << num(d.lower) << ", \"upper\": " << num(d.upper)
    << ", \"empty\": " << (d.empty() ? "true" : "false");
  const bool finite = !d.empty() && std::isfinite(d.upper);
  s << ", \"centre\": " << num(finite ? 0.5 * (d.lower + d.upper) : kNaN)
    << ", \"margin\": " << num(finite ? 0.5 * (d.upper - d.lower) : kNaN);
  s << ",\n \"physical\": {\"unit\": " << input::json_string(Q.unit) << ", \"scale\": " << num(Q.per)
    << ", \"lower\": " << num(d.lower * Q.per)
    << ", \"upper\": " << num(d.upper * Q.per) << ", \"centre\": " << num(finite ? 0.5 * (d.lower + d.upper) * Q.per : kNaN)
    << ", \"margin\": " << num(finite ? 0.5 * (d.upper - d.lower) * Q.per : kNaN)
    << ", \"length_unit\": " << input::json_string(L.unit) << ", \"R\": " << num(L.per)
    << ", \"dh_tolerance\": " << num(d.tolerance.dh * L.per) << ", \"E0_star_Pa\": " << num(E0_star_Pa) << "}";
  if (!finds_drop(d)) s << ",\n \"search\": [" << num(d.search_lo) << ", " << num(d.search_hi) << "]";
  s << ",\n \"texture\": ";
  if (d.texture) {
    const engine::DesignTexture& t = *d.texture;
    s << "{\"lattice\": " << input::json_string(t.lattice) << ", \"levels\": " << t.levels << ", \"level\": " << t.level
      << ", \"drops\": [";
    for (std::size_t k = 0; k < t.drops.size(); ++k) {
      const bool found = static_cast<int>(k) + 1 == t.level && finds_drop(d);
      s << (k ? ", " : "") << (found ? "null" : num(t.drops[k]));
    }
    s << "], \"grid\": " << t.nodes << ", \"grid_coarser\": " << t.coarser << ", \"grid_move\": " << num(t.grid_move)
      << ", \"every_drop\": " << (t.every_drop ? "true" : "false") << ", \"solves\": " << t.solves << ", \"small_spot_closures\": " << t.small_spot
      << ", \"supercell\": " << t.supercell << ", \"scatter\": " << input::json_string(t.scatter)
      << ", \"seed\": " << input::json_string(t.seed) << ", \"caps\": " << t.caps
      << ", \"file\": " << input::json_string(t.file) << "}";
  } else {
    s << "null";
  }
  s << ",\n \"point\": " << input::json_string(geometry_text(d)) << ", \"time_unit\": " << input::json_string(d.inputs.time_unit);
  s << ",\n \"tolerance\": {\"dh\": " << num(d.tolerance.dh) << ", \"pressure\": " << num(d.tolerance.pressure)
    << ", \"pressure_is\": \"" << (d.tolerance.pressure_absolute ? "absolute, E0/(1-nu^2)" : "relative") << "\", \"l\": "
    << num(d.tolerance.l) << ", \"l_is\": \"" << (d.tolerance.l_absolute ? "absolute, R" : "relative") << "\", \"C\": "
    << num(d.tolerance.C) << "}";
  s << ",\n \"temperatures\": [";
  for (std::size_t i = 0; i < d.temperatures.size(); ++i) s << (i ? ", " : "") << num(d.temperatures[i]);
  s << "],\n \"requirements\": [";
  for (std::size_t i = 0; i < d.bounds.size(); ++i) {
    const engine::RequirementBound& b = d.bounds[i];
    const bool touch = b.requirement.kind == engine::Requirement::Kind::touch_by;
    s << (i ? ",\n  " : "\n  ") << "{\"text\": " << input::json_string(b.requirement.text) << ", \"kind\": \""
      << (touch ? "touch_by" : "no_touch_by") << "\", \"time\": " << num(b.requirement.time)
      << ", \"share\": " << num(b.requirement.share) << ", \"share_level\": " << b.requirement.share_level
      << ", \"pbar\": " << num(b.requirement.pbar) << ", \"side\": \"" << (b.upper ? "upper" : "lower")
      << "\", \"edge\": " << num(b.edge) << ", \"edge_physical\": " << num(b.edge * Q.per)
      << ", \"binds_at\": {\"temperature\": " << num(b.binding.temperature)
      << ", \"every_temperature\": " << (b.every_temperature ? "true" : "false") << ", \"pbar\": " << num(b.binding.pbar)
      << ", \"l\": " << num(b.binding.l) << ", \"C\": " << num(b.binding.C) << ", \"dh\": " << num(b.binding.dh)
      << ", \"value\": " << num(b.binding.value)
      << "},\n   \"advisories\": " << input::json_string(b.advice.names())
      << ", \"advisory_reason\": " << input::json_string(edge_advisory_text(b))
      << ", \"contact_radius\": " << num(b.advice.a_max) << ", \"strain\": " << num(b.advice.strain)
      << ",\n   \"bounds\": [";
    for (std::size_t k = 0; k < b.bounds.size(); ++k) {
      const engine::DesignBound& x = b.bounds[k];
      s << (k ? ", " : "") << "{\"temperature\": " << num(x.temperature) << ", \"pbar\": " << num(x.pbar)
        << ", \"l\": " << num(x.l) << ", \"C\": " << num(x.C) << ", \"dh\": " << num(x.dh)
        << ", \"value\": " << num(x.value) << ", \"edge\": " << num(x.edge) << "}";
    }
    s << "]}";
  }
  s << "],\n \"miss\": " << (d.empty() ? input::json_string(miss_text(d, Q)) : "null") << ", \"notes\": [";
  for (std::size_t i = 0; i < d.notes.size(); ++i) s << (i ? ", " : "") << input::json_string(d.notes[i]);
  s << "]}\n";
  return s.str();
}

void write_design_table(std::ostream& out, const engine::DesignResult& d) {
  const engine::Unit L = engine::length_unit(d.inputs), Q = quantity_unit(d);
  const auto len = [&](double v) { return model::number_text(v * Q.per, 4) + " " + Q.unit; };
  const std::string q = quantity_name(d);
  out << "punchsweep design: the "
      << (q == "dh" ? "height difference dh" : q == "dh2" ? "drop dh2 of level 2" : q == "l" ? "pitch l" : "nominal pressure") << " that meets every requirement\n"
      << "  " << geometry_text(d) << "\n"
      << (d.texture ? "  " + texture_text(d, L) + "\n" : "") << "  checked at ";
  if (d.temperatures.size() > 1) {
    out << "every temperature of " << model::number_text(d.temperatures.front(), 4) << " to "
        << model::number_text(d.temperatures.back(), 4) << " degC (" << d.temperatures.size() << " temperatures)";
  } else if (d.temperatures.size() == 1) {
    out << model::number_text(d.temperatures.front(), 4) << " degC";
  } else {
    out << "the law's own parameters";
  }
  const std::string box = tolerance_text(d, L);
  out << (box.empty() ? "" : " and every corner of the tolerance box " + box) << "\n";
  if (!finds_drop(d)) {
    out << "  " << (q == "l" ? "pitches" : "pressures") << " searched: " << len(d.search_lo) << " to " << len(d.search_hi)
        << (q == "l" ? "" : " (" + drop_name(d) + " = " + model::number_text(level_drop(d) * L.per, 4) + " " + L.unit + ")") << "\n";
  }
  out << "\n";
  // dh: touching by t is dh <= (closed), never is dh > (open); another level's share the other
  // way round (touching dh >=, never dh <); l: touching is l >=, never l <.
  const auto sign = [&](const engine::RequirementBound& b) {
    const bool touch = b.requirement.kind == engine::Requirement::Kind::touch_by;
    return b.upper ? (touch ? "<= " : "< ") : (touch ? ">= " : "> ");
  };
  // Whether a drop's window edge is closed: where a touch binds it (the searched level's own
  // upper edge, another level's share's lower one), and at 0.
  const auto closed_by_touch = [&](bool upper, double edge) {
    return std::any_of(d.bounds.begin(), d.bounds.end(), [&](const engine::RequirementBound& b) {
      return b.upper == upper && b.edge == edge && b.requirement.kind == engine::Requirement::Kind::touch_by;
    });
  };
  const bool lower_closed = !finds_drop(d) || d.lower == 0 || closed_by_touch(false, d.lower);
  for (const engine::RequirementBound& b : d.bounds) {
    const bool touch = b.requirement.kind == engine::Requirement::Kind::touch_by;
    out << "  " << b.requirement.text << ": " << q << " " << sign(b)
        << (std::isinf(b.edge) ? std::string(b.edge > 0 ? "inf" : "-inf") : len(b.edge)) << "  (binds at "
        << where_text(b, d, L, touch) << ")\n";
    if (const std::string advice = edge_advisory_text(b); !advice.empty()) out << "    advisories " << advice << "\n";
  }
  out << "\n";
  const bool tolerance = engine::own_tolerance(d.tolerance, d.quantity).width > 0;
  if (d.empty()) {
    out << "no design meets this: the requirements leave " << q << " between " << len(d.lower) << " and "
        << len(d.upper) << ", an empty window; " << miss_text(d, Q) << "\n";
  } else if (std::isinf(d.upper)) {
    out << "window: " << q << " " << (lower_closed ? ">= " : "> ") << len(d.lower) << " (no upper edge)\n";
  } else {
    const bool open_low = !lower_closed;
    out << "window: " << len(d.lower) << (open_low ? " < " : " <= ") << q
        << ((finds_drop(d) ? !closed_by_touch(true, d.upper) : d.upper < d.search_hi) ? " < " : " <= ")
        << len(d.upper) << "; centre " << len(0.5 * (d.lower + d.upper)) << ", margin +- "
        << len(0.5 * (d.upper - d.lower)) << (tolerance ? " beyond the tolerance" : "") << "\n";
    if (!finds_drop(d) && (d.lower == d.search_lo || d.upper == d.search_hi)) {
      out << "  (" << (d.lower == d.search_lo ? d.upper == d.search_hi ? "both edges are" : "the lower edge is"
                                                                      : "the upper edge is")
          << " the range searched's, not a requirement's: widen it to see further)\n";
    }
  }
  for (const std::string& n : d.notes) out << "note: " << n << "\n";
}

}  // namespace punchsweep::report
