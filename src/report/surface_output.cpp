#include "report/surface_output.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "engine/surface_evaluation.hpp"
#include "input/command_options.hpp"
#include "model/laws/material.hpp"
#include "model/numerics/number_text.hpp"
#include "model/numerics/sample_statistics.hpp"
#include "model/surface/surface_advisory.hpp"

namespace punchsweep::report {

namespace {

std::string num(double v) { return input::json_number(v); }

/// A level's sites: how many, and their least and greatest drop.
struct DropRange {
  double least = std::numeric_limits<double>::infinity();
  double greatest = 0.0;
  int sites = 0;
};
DropRange drop_range(const model::CellGeometry& geometry, int level) {
  DropRange out;
  for (const model::Site& site : geometry.sites) {
    if (site.level != level) continue;
    out.least = std::min(out.least, site.drop);
    out.greatest = std::max(out.greatest, site.drop);
    ++out.sites;
  }
  return out;
}

/// "physical": the lengths, areas, loads and loads X in R's unit, its square, N and Pa,
/// where --R and a material give the scales (nothing otherwise).
void write_physical(std::ostream& out, const engine::SurfaceRun& run, const model::SurfaceAdvisories& advice) {
  const input::PhysicalScales& scales = run.inputs.scales;
  const std::optional<input::PhysicalUnit> length = input::physical_unit("R", scales);
  const std::optional<input::PhysicalUnit> pressure = input::physical_unit("E0/(1-nu^2)", scales);
  const std::optional<input::PhysicalUnit> load = input::physical_unit("R^2 E0/(1-nu^2)", scales);
  if (!length || !pressure || !load) return;
  const double area = length->per_scaled * length->per_scaled;
  const int L = run.curve.levels();
  out << "  \"physical\": {\n    \"units\": {\"X\": \"Pa\", \"area\": " << input::json_string(length->units + "^2")
      << ", \"load\": \"N\", \"drop\": " << input::json_string(length->units) << ", \"cell\": " << input::json_string(length->units)
      << ", \"contact_radius\": " << input::json_string(length->units)
      << "},\n    \"cell\": [" << num(run.geometry.Lx * length->per_scaled) << ", " << num(run.geometry.Ly * length->per_scaled)
      << "],\n    \"levels\": [";
  for (int level = 0; level < L; ++level) {
    const double drop = drop_range(run.geometry, level).least;
    out << (level ? ", " : "") << "{\"drop\": " << num(drop * length->per_scaled) << ", \"X_star\": "
        << num(run.history.levels[static_cast<std::size_t>(level)].X_star * pressure->per_scaled)
        << ", \"contact_radius\": " << num(advice.level[static_cast<std::size_t>(level)].a_max * length->per_scaled) << "}";
  }
  out << "],\n    \"caps\": {";
  // Each cap's place, drop, tip radius 1 / (2C) and touchdown load, in the units above.
  const auto caps = [&](const char* name, auto value, bool last) {
    out << "\"" << name << "\": [";
    for (std::size_t k = 0; k < run.geometry.sites.size(); ++k) out << (k ? ", " : "") << num(value(k));
    out << "]" << (last ? "" : ", ");
  };
  const std::vector<model::Site>& sites = run.geometry.sites;
  caps("x", [&](std::size_t k) { return sites[k].x * length->per_scaled; }, false);
  caps("y", [&](std::size_t k) { return sites[k].y * length->per_scaled; }, false);
  caps("drop", [&](std::size_t k) { return sites[k].drop * length->per_scaled; }, false);
  caps("tip_radius", [&](std::size_t k) { return 0.5 / sites[k].shape.C * length->per_scaled; }, false);
  caps("X_star", [&](std::size_t k) { return run.history.sites[k].X_star * pressure->per_scaled; }, true);
  out << "},\n    \"series\": {\n";
  const auto series = [&](const std::string& name, auto value, bool last) {
    out << "      \"" << name << "\": [";
    for (std::size_t k = 0; k < run.history.snapshots.size(); ++k) out << (k ? ", " : "") << num(value(run.history.snapshots[k]));
    out << "]" << (last ? "\n" : ",\n");
  };
  series("X", [&](const model::SurfaceSnapshot& s) { return s.X * pressure->per_scaled; }, false);
  for (int level = 0; level < L; ++level) {
    const std::size_t at = static_cast<std::size_t>(level);
    series("area_" + std::to_string(level), [&](const model::SurfaceSnapshot& s) { return s.state.level_area[at] * area; }, false);
  }
  for (int level = 0; level < L; ++level) {
    const std::size_t at = static_cast<std::size_t>(level);
    series("load_" + std::to_string(level), [&](const model::SurfaceSnapshot& s) { return s.level_load[at] * load->per_scaled; },
           level == L - 1);
  }
  out << "    }\n  },\n";
}

/// "check": the time stepping's touch times, areas and loads at the same times.
void write_check(std::ostream& out, const engine::SurfaceRun& run) {
  const reference::CellReference& r = *run.stepped;
  const int L = run.curve.levels();
  out << "  \"check\": {\n    \"seconds\": " << num(run.check_seconds) << ", \"steps\": " << r.steps << ", \"converged\": "
      << (r.converged ? "true" : "false") << ", \"t_star_resolution\": " << num(run.check_t_star_resolution)
      << ",\n    \"levels\": [";
  for (int level = 0; level < L; ++level) {
    const std::size_t at = static_cast<std::size_t>(level);
    out << (level ? ", " : "") << "{\"regime\": " << input::json_string(std::string(model::regime_name(r.level_regime[at])))
        << ", \"t_star\": " << num(r.level_t_star[at]) << "}";
  }
  out << "],\n    \"series\": {\n";
  const auto series = [&](const std::string& name, auto value, bool last) {
    out << "      \"" << name << "\": [";
    for (std::size_t k = 0; k < r.series.size(); ++k) out << (k ? ", " : "") << num(value(r.series[k]));
    out << "]" << (last ? "\n" : ",\n");
  };
  series("area_fraction", [](const reference::CellSnapshot& s) { return s.area_fraction; }, false);
  series("sites_touched", [](const reference::CellSnapshot& s) { return s.sites_touched; }, false);
  for (int level = 0; level < L; ++level) {
    const std::size_t at = static_cast<std::size_t>(level);
    series("area_" + std::to_string(level), [at](const reference::CellSnapshot& s) { return s.level_area[at]; }, false);
  }
  for (int level = 0; level < L; ++level) {
    const std::size_t at = static_cast<std::size_t>(level);
    series("load_" + std::to_string(level), [at](const reference::CellSnapshot& s) { return s.level_load[at]; }, level == L - 1);
  }
  out << "    }\n  },\n";
}

/// What gave a level's touchdown X*: "tallest" (level 0, X* = 0), "tables" (the periodic
/// model's), "small_spot_limit" (docs/model.md 17.6) or "curve" (the cell's boundary elements).
std::string touchdown_source(const engine::SurfaceRun& run, int level) {
  if (level == 0) return "tallest";
  if (run.curve_source == engine::CurveSource::tables) return "tables";
  const std::size_t at = static_cast<std::size_t>(level);
  return at < run.curve.level_small_spot.size() && run.curve.level_small_spot[at] != 0 ? "small_spot_limit" : "curve";
}

/// What gave cap k's touchdown, as touchdown_source says a level's ("tallest" for a tip at
/// drop 0 of level 0).
std::string cap_touchdown_source(const engine::SurfaceRun& run, std::size_t k) {
  const model::Site& site = run.geometry.sites[k];
  if (site.level == 0 && site.drop == 0.0) return "tallest";
  if (run.curve_source == engine::CurveSource::tables) return "tables";
  return k < run.curve.site_small_spot.size() && run.curve.site_small_spot[k] != 0 ? "small_spot_limit" : "curve";
}

/// Per level, whether every cap of it lies under the taller caps' surface
/// (model::tip_exposed); level 0 never does. One scan of the cell for all levels.
std::vector<char> hidden_levels(const engine::SurfaceRun& run) {
  const std::size_t L = static_cast<std::size_t>(run.curve.levels());
  std::vector<char> hidden(L, 0);
  if (run.measured) return hidden;  // a summit is the highest pixel about it
  const model::SurfaceLocator surface(run.geometry);
  for (std::size_t level = 1; level < L; ++level) hidden[level] = 1;
  for (std::size_t k = 0; k < run.geometry.sites.size(); ++k) {
    const std::size_t level = static_cast<std::size_t>(run.geometry.sites[k].level);
    if (level < L && hidden[level] && model::tip_exposed(run.geometry, surface, k)) hidden[level] = 0;
  }
  return hidden;
}

/// Why a level never touches, one rule whatever served the curve: its caps lie under the
/// taller ones' surface (hidden: their tips are not on the texture's surface, and the
/// contact reaches them only as the taller caps' spreads), or the load never reaches its
/// touchdown before full contact or the curve's end.
std::string never_reason(const engine::SurfaceRun& run, bool hidden) {
  std::ostringstream out;
  if (hidden) {
    out << "hidden: its tips lie under the taller caps' surface, so it never touches as a cap of its own";
  } else if (std::isfinite(run.curve.X_full)) {
    out << "untouched up to full contact, X = " << run.curve.X_full << " E0*";
  } else if (std::isfinite(run.X_reach) && run.curve.X_last() >= run.X_reach) {
    out << "untouched up to X = " << run.curve.X_last() << " E0*, where the curve stops: past X(inf) = " << run.X_reach
        << " E0*, the most the load reaches";
  } else {
    out << "untouched up to X = " << run.curve.X_last() << " E0*, where the curve ends";
  }
  return out.str();
}

/// The advisories' sentences ("" for none): the widest caps' radius and the largest strain,
/// and the level they are on (each level's radius is in the JSON).
std::string advisory_reason(const model::SurfaceAdvisories& advice) {
  if (advice.all.raised.empty()) return "";
  std::string text = "On the widest caps, level ";
  text += std::to_string(advice.widest());
  text += "'s, at the last time: ";
  text += advice.all.reason(0.0);
  return text;
}

/// Where the curve came from: "tables" (the periodic model's) or "cell" (the cell's own
/// boundary elements).
std::string curve_source_name(const engine::SurfaceRun& run) { return run.curve_source == engine::CurveSource::tables ? "tables" : "cell"; }

/// Site k's touch, unresolved where it is its level's first and the level is (the run
/// marks a level unresolved after its curve: --grid auto's hold, --check).
model::LevelTouch cap_touch(const engine::SurfaceRun& run, std::size_t k) {
  model::LevelTouch touch = run.history.sites[k];
  const model::LevelTouch& level = run.history.levels[static_cast<std::size_t>(run.geometry.sites[k].level)];
  if (touch.X_star == level.X_star) touch.resolved = touch.resolved && level.resolved;
  return touch;
}

/// A sample's statistics as a JSON object (null for a NaN or infinite value).
std::string stats_json(const model::SampleStatistics& s) {
  std::ostringstream o;
  o << "{\"n\": " << s.n << ", \"mean\": " << num(s.mean) << ", \"sd\": " << num(s.sd) << ", \"se\": " << num(s.se)
    << ", \"p5\": " << num(s.p5) << ", \"median\": " << num(s.median) << ", \"p95\": " << num(s.p95)
    << ", \"infinite\": " << s.infinite << "}";
  return o.str();
}

/// The JSON list of `values`, each by `text`.
template <class Values, class Text>
std::string json_list(const Values& values, Text text) {
  std::string o = "[";
  for (std::size_t k = 0; k < values.size(); ++k) o += (k ? ", " : "") + text(values[k]);
  return o + "]";
}

/// "ensemble": an ensemble's statistics and each draw's values (engine::SurfaceEnsemble).
void write_ensemble_json(std::ostream& out, const engine::SurfaceEnsemble& e) {
  out << "  \"ensemble\": {\n    \"seeds\": " << json_list(e.members, [](const auto& m) { return std::to_string(m.seed); })
      << ",\n    \"target_error\": " << (e.target_error > 0.0 ? num(e.target_error) : std::string("null"))
      << ", \"largest_error\": " << num(e.reached_error) << ",\n    \"levels\": [";
  for (std::size_t level = 0; level < e.levels.size(); ++level) {
    out << (level ? ",\n      " : "\n      ") << "{\"level\": " << level << ", \"first\": " << stats_json(e.levels[level].first)
        << ", \"median\": " << stats_json(e.levels[level].median) << ", \"last\": " << stats_json(e.levels[level].last) << "}";
  }
  out << "\n    ],\n    \"series\": {";
  for (std::size_t q = 0; q < e.series_names.size(); ++q) {
    const std::vector<model::SampleStatistics>& at = e.series[q];
    const auto column = [&](double model::SampleStatistics::*field) {
      return json_list(at, [field](const model::SampleStatistics& s) { return num(s.*field); });
    };
    out << (q ? ",\n      " : "\n      ") << input::json_string(e.series_names[q]) << ": {\"mean\": " << column(&model::SampleStatistics::mean)
        << ", \"sd\": " << column(&model::SampleStatistics::sd) << ", \"se\": " << column(&model::SampleStatistics::se)
        << ", \"p5\": " << column(&model::SampleStatistics::p5) << ", \"median\": " << column(&model::SampleStatistics::median)
        << ", \"p95\": " << column(&model::SampleStatistics::p95) << "}";
  }
  out << "\n    },\n    \"members\": [";
  for (std::size_t k = 0; k < e.members.size(); ++k) {
    const engine::SurfaceEnsemble::Member& m = e.members[k];
    out << (k ? ",\n      " : "\n      ") << "{\"seed\": " << m.seed << ", \"first\": " << json_list(m.first, num)
        << ", \"median\": " << json_list(m.median, num) << ", \"last\": " << json_list(m.last, num)
        << ", \"resolved\": " << json_list(m.resolved, [](char r) { return std::string(r ? "true" : "false"); })
        << ", \"valid\": " << json_list(m.valid, [](double v) { return std::string(v != 0.0 ? "true" : "false"); });
    for (std::size_t q = 0; q < e.series_names.size(); ++q) {
      out << ", " << input::json_string(e.series_names[q]) << ": " << json_list(m.series[q], num);
    }
    out << "}";
  }
  out << "\n    ]\n  },\n";
}

void write_json(std::ostream& out, const engine::SurfaceRun& run, const engine::SurfaceEnsemble* ensemble) {
  const int L = run.curve.levels();
  out << "{\n  \"inputs\": " << input::json_string(run.inputs.describe()) << ",\n";
  out << "  \"lattice\": " << input::json_string(run.measured ? "height map" : run.cell_file.empty() ? model::lattice_name(run.lattice) : "cell") << ",\n";
  if (!run.cell_file.empty()) {
    out << "  \"" << (run.measured ? "height_map" : "cell_file") << "\": " << input::json_string(run.cell_file) << ",\n";
  }
  out << "  \"notes\": [";
  for (std::size_t k = 0; k < run.inputs.notes.size(); ++k) out << (k ? ", " : "") << input::json_string(run.inputs.notes[k]);
  out << "],\n";
  out << "  \"cell\": [" << num(run.geometry.Lx) << ", " << num(run.geometry.Ly) << "],\n";
  out << "  \"grid\": [" << run.curve.nx << ", " << run.curve.ny << "],\n";
  out << "  \"supercell\": " << run.supercell << ",\n";
  if (run.supercell > 1) out << "  \"tallest_rise\": " << num(run.tallest_rise) << ",\n";
  if (run.part_caps > 0.0) {
    const auto band = [](const std::array<double, 3>& r) { return "[" + num(r[0]) + ", " + num(r[1]) + ", " + num(r[2]) + "]"; };
    out << "  \"part\": {\"caps\": " << num(run.part_caps) << ", \"tallest_rise\": " << band(run.part_rise)
        << ", \"supercell_tallest_rise\": " << band(run.supercell_rise) << "},\n";
  }
  out << "  \"caps\": " << run.geometry.sites.size() << ",\n";
  out << "  \"curve\": {\"source\": " << input::json_string(curve_source_name(run)) << ", \"samples\": " << run.curve.samples.size() << ", \"X_first\": " << num(run.curve.X_first())
      << ", \"X_resolved\": " << num(run.curve.X_resolved)
      << ", \"X_last\": " << num(run.curve.X_last()) << ", \"X_full\": " << num(run.curve.X_full)
      << ", \"X_reach\": " << num(run.X_reach)
      << ", \"seconds\": " << num(run.curve_seconds) << ", \"cached\": " << (run.curve_cached ? "true" : "false")
      << ", \"held_to_grid\": " << (run.grid_coarser > 0 ? std::to_string(run.grid_coarser) : std::string("null")) << "},\n";
  const model::SurfaceAdvisories advice = model::advise_surface(run.geometry, run.history);
  out << "  \"advisories\": " << input::json_string(advice.all.names()) << ",\n";
  out << "  \"advisory_reason\": " << input::json_string(advisory_reason(advice)) << ",\n";
  out << "  \"levels\": [";
  const std::vector<char> hidden = hidden_levels(run);
  for (int level = 0; level < L; ++level) {
    const model::LevelTouch& touch = run.history.levels[static_cast<std::size_t>(level)];
    const DropRange drops = drop_range(run.geometry, level);
    out << (level ? ",\n    " : "\n    ") << "{\"level\": " << level << ", \"drop\": " << num(drops.least)
        << ", \"drop_max\": " << num(drops.greatest)
        << ", \"sites\": " << drops.sites << ", \"regime\": " << input::json_string(std::string(model::regime_name(touch.regime)))
        << ", \"t_star\": " << num(touch.t_star) << ", \"X_star\": " << num(touch.X_star)
        << ", \"resolved\": " << (touch.resolved ? "true" : "false")
        << ", \"touchdown_from\": " << input::json_string(touchdown_source(run, level))
        << ", \"hidden\": " << (hidden[static_cast<std::size_t>(level)] ? "true" : "false")
        << ", \"t_star_grid_change\": "
        << (run.grid_t_star_change.empty() ? std::string("null") : num(run.grid_t_star_change[static_cast<std::size_t>(level)]))
        << ", \"share\": " << num(run.curve.level_share[static_cast<std::size_t>(level)])
        << ", \"contact_radius\": " << num(advice.level[static_cast<std::size_t>(level)].a_max)
        << ", \"advisories\": " << input::json_string(advice.level[static_cast<std::size_t>(level)].names());
    for (const model::TStarDerivative& d : run.derivatives[static_cast<std::size_t>(level)]) {
      out << ", \"dt_star_d" << d.parameter->name << "\": " << num(d.derivative) << ", \"dlog_t_star_dlog_" << d.parameter->name
          << "\": " << num(d.elasticity);
    }
    if (const std::optional<model::TStarRange>& r = run.ranges[static_cast<std::size_t>(level)]) {
      out << ", \"t_star_low\": " << num(r->low) << ", \"t_star_high\": " << num(r->high) << ", \"corners_immediate\": "
          << r->immediate << ", \"corners_delayed\": " << r->delayed << ", \"corners_never\": " << r->never;
    }
    out << "}";
  }
  out << "\n  ],\n";
  if (run.measured) {
    out << "  \"summits\": {\"least_prominence\": " << num(run.measured->least_prominence) << ", \"height_range\": "
        << num(run.measured->height_range) << ", \"below_prominence\": " << run.measured->summits_below << "},\n";
  }
  out << "  \"cap_list\": [";
  for (std::size_t k = 0; k < run.geometry.sites.size(); ++k) {
    const model::Site& site = run.geometry.sites[k];
    const model::LevelTouch touch = cap_touch(run, k);
    out << (k ? ",\n    " : "\n    ") << "{\"x\": " << num(site.x) << ", \"y\": " << num(site.y) << ", \"level\": " << site.level
        << ", \"drop\": " << num(site.drop) << ", \"s\": " << num(site.shape.s) << ", \"C\": " << num(site.shape.C);
    if (run.measured) out << ", \"prominence\": " << num(run.measured->prominence[k]);
    out << ", \"regime\": " << input::json_string(std::string(model::regime_name(touch.regime))) << ", \"t_star\": " << num(touch.t_star)
        << ", \"X_star\": " << num(touch.X_star) << ", \"resolved\": " << (touch.resolved ? "true" : "false")
        << ", \"touchdown_from\": " << input::json_string(cap_touchdown_source(run, k)) << "}";
  }
  out << (run.geometry.sites.empty() ? "],\n" : "\n  ],\n");
  out << "  \"series\": {\n";
  const auto series = [&](const char* name, auto value, bool last = false) {
    out << "    \"" << name << "\": [";
    for (std::size_t k = 0; k < run.history.snapshots.size(); ++k) out << (k ? ", " : "") << value(run.history.snapshots[k]);
    out << "]" << (last ? "\n" : ",\n");
  };
  series("t", [](const model::SurfaceSnapshot& s) { return num(s.t); });
  series("X", [](const model::SurfaceSnapshot& s) { return num(s.X); });
  series("area_fraction", [](const model::SurfaceSnapshot& s) { return num(s.state.area_fraction); });
  series("sites_touched", [](const model::SurfaceSnapshot& s) { return num(s.state.sites_touched); });
  for (int level = 0; level < L; ++level) {
    const std::string name = "area_" + std::to_string(level);
    series(name.c_str(), [&](const model::SurfaceSnapshot& s) { return num(s.state.level_area[static_cast<std::size_t>(level)]); });
  }
  for (int level = 0; level < L; ++level) {
    const std::string name = "touched_" + std::to_string(level);
    series(name.c_str(), [&](const model::SurfaceSnapshot& s) { return num(s.state.level_sites_touched[static_cast<std::size_t>(level)]); });
  }
  for (int level = 0; level < L; ++level) {
    const std::string name = "load_" + std::to_string(level);
    series(name.c_str(), [&](const model::SurfaceSnapshot& s) { return num(s.level_load[static_cast<std::size_t>(level)]); });
  }
  series("valid", [](const model::SurfaceSnapshot& s) { return s.validity == model::SurfaceValidity::valid ? "true" : "false"; });
  series("reason", [](const model::SurfaceSnapshot& s) { return input::json_string(std::string(model::surface_validity_name(s.validity))); }, true);
  out << "  },\n";
  write_physical(out, run, advice);
  if (run.stepped) write_check(out, run);
  if (ensemble) write_ensemble_json(out, *ensemble);
  out << "  \"units\": {\"t\": " << input::json_string(run.inputs.time_unit)
      << ", \"X\": \"E0*\", \"area\": \"R^2\", \"load\": \"R^2 E0*\", \"drop\": \"R\", \"cell\": \"R\", \"contact_radius\": \"R\"}\n}\n";
}

/// A measured map's summits: what a summit had to rise, and each cap's place, drop, shape,
/// prominence and touch (lengths in R's unit where the run has R; the tip radius of
/// curvature 1 / (2 C) of its paraboloid).
void write_measured_caps(std::ostream& out, const engine::SurfaceRun& run, bool csv) {
  const reference::MeasuredCell& measured = *run.measured;
  const auto [per, units] = input::physical_unit_or_scaled("R", run.inputs.scales);
  const char* lead = csv ? "# " : "  ";
  out << lead << "summits: those rising at least " << measured.least_prominence * per << " " << units
      << " above the highest saddle to higher ground (--prominence; the map's height range " << measured.height_range * per << " "
      << units << "); " << measured.summits_below << " lower ones are part of the ground they rise from\n";
  for (std::size_t k = 0; k < run.geometry.sites.size(); ++k) {
    const model::Site& site = run.geometry.sites[k];
    const model::LevelTouch touch = cap_touch(run, k);
    out << lead << "cap " << k << ": level " << site.level << " at (" << site.x * per << ", " << site.y * per << ") " << units
        << ", drop " << site.drop * per << " " << units << ", tip radius " << 0.5 / site.shape.C * per << " " << units << ", prominence "
        << (std::isfinite(measured.prominence[k]) ? model::number_text(measured.prominence[k] * per, 6) + " " + units : std::string("the highest")) << ": " << model::regime_name(touch.regime);
    if (touch.regime == model::Regime::delayed) out << " at t* = " << touch.t_star << " " << run.inputs.time_unit;
    out << (touch.resolved ? "" : " (below the curve's resolution)") << "\n";
  }
}

/// An ensemble's lines: each level's first, median and last cap's touch time over the
/// draws, then per time the area fraction and shares of caps in contact (mean, sd, 5-95%).
void write_ensemble_table(std::ostream& out, const engine::SurfaceRun& run, const engine::SurfaceEnsemble& e, bool csv) {
  const char* lead = csv ? "# " : "  ";
  const char* sep = csv ? "," : "  ";
  const std::size_t n = e.members.size();
  out << lead << "ensemble: " << n << " draws of the scatter, seeds " << e.members.front().seed << " to " << e.members.back().seed
      << " (the caps and levels above are seed " << e.members.front().seed << "'s; the rows below are over the draws)\n";
  if (e.target_error > 0.0) {
    out << lead << "ensemble: the largest standard error of a mean share or area fraction is " << e.reached_error
        << (e.reached_error <= e.target_error ? " (--target-error " : " (short of --target-error ") << e.target_error << ")\n";
  }
  const auto stats = [&](const model::SampleStatistics& s) {
    std::ostringstream o;
    if (s.infinite == s.n) return std::string("never in every draw");
    o << "mean " << s.mean;
    if (std::isfinite(s.sd)) o << " +- " << s.se << " (sd " << s.sd << ")";
    o << ", 5-95% " << s.p5 << " to " << s.p95;
    if (s.infinite > 0) o << " (never in " << s.infinite << " of " << s.n << " draws)";
    return o.str();
  };
  for (std::size_t level = 1; level < e.levels.size(); ++level) {
    const char* names[] = {"first", "median", "last"};
    const model::SampleStatistics* of[] = {&e.levels[level].first, &e.levels[level].median, &e.levels[level].last};
    std::size_t unresolved = 0;
    for (const engine::SurfaceEnsemble::Member& m : e.members) unresolved += m.resolved[level] ? 0 : 1;
    for (int k = 0; k < 3; ++k) {
      out << lead << "ensemble: level " << level << ", its " << names[k] << " cap's t*: " << stats(*of[k]) << " " << run.inputs.time_unit
          << "\n";
    }
    if (unresolved > 0) {
      out << lead << "ensemble: level " << level << " below the curve's resolution in " << unresolved << " of " << n
          << " draws (a finer --grid answers)\n";
    }
  }
  out << "t";
  for (const std::string& name : e.series_names) {
    for (const char* stat : {"mean", "sd", "p5", "p95"}) out << sep << name << "_" << stat;
  }
  out << sep << "valid_draws\n";
  for (std::size_t t = 0; t < run.history.snapshots.size(); ++t) {
    out << run.history.snapshots[t].t;
    for (const std::vector<model::SampleStatistics>& at : e.series) {
      out << sep << at[t].mean << sep << at[t].sd << sep << at[t].p5 << sep << at[t].p95;
    }
    double valid = 0.0;
    for (const engine::SurfaceEnsemble::Member& m : e.members) valid += m.valid[t];
    out << sep << valid << "\n";
  }
}

void write_table(std::ostream& out, const engine::SurfaceRun& run, bool csv, const engine::SurfaceEnsemble* ensemble) {
  const int L = run.curve.levels();
  const char* sep = csv ? "," : "  ";
  out << (csv ? "# " : "") << "punchsweep surface: "
      << (run.measured ? "height map " + run.cell_file + ", " : run.cell_file.empty() ? model::lattice_name(run.lattice) + " lattice, " : "cell " + run.cell_file + ", ")
      << run.inputs.describe() << "\n";
  if (run.inputs.material) out << (csv ? "# " : "  ") << "material: " << run.inputs.material->describe() << "\n";
  for (const std::string& note : run.inputs.notes) out << (csv ? "# " : "  ") << "note: " << note << "\n";
  out << (csv ? "# " : "  ") << "load curve: "
      << (run.curve_source == engine::CurveSource::tables ? "the periodic model's tables (with their small-spot table), " : "")
      << run.curve.nx << " x " << run.curve.ny << " nodes, "
      << run.curve.samples.size() << " samples from X = " << run.curve.X_first() << " to " << run.curve.X_last()
      << " E0*";
  if (std::isfinite(run.curve.X_full)) {
    out << " (full contact)";
  } else if (std::isfinite(run.X_reach) && run.curve.X_last() >= run.X_reach) {
    out << " (its first sample past X = " << run.X_reach << " E0*, the most the loads reach; --full-curve goes on)";
  }
  out << ", " << run.curve_seconds << " s"
      << (run.curve_cached ? " (from the table cache)" : "") << "\n";
  if (run.grid_coarser > 0) {
    double worst = 0.0;
    for (const double c : run.grid_t_star_change) worst = std::max(worst, c);
    out << (csv ? "# " : "  ") << "grid: --grid auto held it to " << run.grid_coarser << " nodes a pitch: t* moved by at most "
        << worst << " of itself\n";
  }
  const std::vector<char> hidden = hidden_levels(run);
  const model::SurfaceAdvisories advice = model::advise_surface(run.geometry, run.history);
  out << (csv ? "# " : "  ") << "caps: " << run.geometry.sites.size() << " in the cell (";
  for (int level = 0; level < L; ++level) {
    out << (level ? ", " : "") << drop_range(run.geometry, level).sites << " of level " << level;
  }
  out << ")\n";
  if (run.measured) write_measured_caps(out, run, csv);
  const auto [per, units] = input::physical_unit_or_scaled("R", run.inputs.scales);
  if (run.supercell > 1 && run.scatter.kind != model::HeightScatter::Kind::none) {
    out << (csv ? "# " : "  ") << "heights: drops from the tallest tip drawn, " << run.tallest_rise * per << " " << units
        << " above the tallest tips' design height (a larger supercell draws a taller one)\n";
  }
  if (run.part_caps > 0.0) {
    out << (csv ? "# " : "  ") << "part of " << run.part_caps << " caps: its tallest tip about " << run.part_rise[1] * per << " "
        << units << " above the design height (5-95%: " << run.part_rise[0] * per << " to " << run.part_rise[2] * per
        << "), this supercell's " << run.supercell_rise[0] * per << " to " << run.supercell_rise[2] * per << " (drawn: "
        << run.tallest_rise * per << "): the part's lower caps lie about " << (run.part_rise[1] - run.tallest_rise) * per << " "
        << units << " further below its tallest than here\n";
  }
  for (int level = 0; level < L; ++level) {
    const model::LevelTouch& t = run.history.levels[static_cast<std::size_t>(level)];
    out << (csv ? "# " : "  ") << "level " << level << ": " << model::regime_name(t.regime);
    if (t.regime == model::Regime::delayed) out << " at t* = " << t.t_star << " " << run.inputs.time_unit;
    if (!t.resolved && !std::isfinite(t.X_star)) {
      out << " (" << never_reason(run, hidden[static_cast<std::size_t>(level)] != 0)
          << "; below the curve's resolution: a finer --grid answers)\n";
    } else if (!t.resolved) {
      out << " (touches at X* = " << t.X_star << " E0*, below the curve's resolution: a finer --grid answers)\n";
    } else if (std::isfinite(t.X_star)) {
      out << " (touches at X* = " << t.X_star << " E0*)\n";
    } else {
      out << " (" << never_reason(run, hidden[static_cast<std::size_t>(level)] != 0) << ")\n";
    }
  }
  for (int level = 1; level < L; ++level) {
    const std::size_t at = static_cast<std::size_t>(level);
    for (const model::TStarDerivative& d : run.derivatives[at]) {
      if (!std::isfinite(d.derivative)) continue;
      out << (csv ? "# " : "  ") << "level " << level << ": d t*/d" << d.parameter->name << " = " << d.derivative << " "
          << run.inputs.time_unit << " per " << d.parameter->scale;
      if (std::isfinite(d.elasticity)) out << " (" << d.parameter->name << "/t* d t*/d" << d.parameter->name << " = " << d.elasticity << ")";
      out << "\n";
    }
    if (const std::optional<model::TStarRange>& r = run.ranges[at]) {
      out << (csv ? "# " : "  ") << "level " << level << ": t* from " << r->low << " to " << r->high << " " << run.inputs.time_unit
          << " over the tolerances (" << r->immediate << " corners immediate, " << r->delayed << " delayed, " << r->never
          << " never)\n";
    }
  }
  if (!advice.all.raised.empty()) {
    out << (csv ? "# " : "  ") << "advisories: " << advice.all.names() << ": " << advisory_reason(advice) << "\n";
  }
  if (run.stepped) {
    for (int level = 1; level < L; ++level) {
      const std::size_t at = static_cast<std::size_t>(level);
      out << (csv ? "# " : "  ") << "check: level " << level << " by time stepping: "
          << model::regime_name(run.stepped->level_regime[at]);
      if (std::isfinite(run.stepped->level_t_star[at]) && run.stepped->level_t_star[at] > 0.0) {
        out << " at t* = " << run.stepped->level_t_star[at] << " +- " << 0.5 * run.check_t_star_resolution << " "
            << run.inputs.time_unit;
      }
      out << "\n";
    }
    out << (csv ? "# " : "  ") << "check: " << run.stepped->steps << " time steps, " << run.check_seconds << " s\n";
  }
  if (ensemble) {
    write_ensemble_table(out, run, *ensemble, csv);
    return;
  }
  out << "t" << sep << "X" << sep << "area_fraction" << sep << "sites_touched";
  for (int level = 0; level < L; ++level) out << sep << "area_" << level;
  for (int level = 0; level < L; ++level) out << sep << "load_" << level;
  for (int level = 0; level < L; ++level) out << sep << "touched_" << level;
  if (run.stepped) out << sep << "check_area_fraction" << sep << "check_sites_touched";
  out << sep << "valid\n";
  for (std::size_t k = 0; k < run.history.snapshots.size(); ++k) {
    const model::SurfaceSnapshot& s = run.history.snapshots[k];
    out << s.t << sep << s.X << sep << s.state.area_fraction << sep << s.state.sites_touched;
    for (double a : s.state.level_area) out << sep << a;
    for (double P : s.level_load) out << sep << P;
    for (double share : s.state.level_sites_touched) out << sep << share;
    if (run.stepped) out << sep << run.stepped->series[k].area_fraction << sep << run.stepped->series[k].sites_touched;
    out << sep << model::surface_validity_name(s.validity) << "\n";
  }
}

}  // namespace

void write_surface(std::ostream& out, OutputFormat format, const engine::SurfaceRun& run, const engine::SurfaceEnsemble* ensemble) {
  if (format == OutputFormat::json) {
    write_json(out, run, ensemble);
  } else {
    write_table(out, run, format == OutputFormat::csv, ensemble);
  }
}

std::string surface_json(const input::Keywords& keywords) {
  std::ostringstream out;
  const auto [run, ensemble] = engine::evaluate_surface_ensemble(keywords);
  write_surface(out, OutputFormat::json, run, ensemble ? &*ensemble : nullptr);
  return out.str();
}

}  // namespace punchsweep::report
