#include "app/surface_command.hpp"

#include <boost/program_options.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <ostream>
#include <sstream>

#include "app/curve_cache.hpp"
#include "input/cell_file.hpp"
#include "input/height_map.hpp"
#include "input/scaled_value.hpp"
#include "input/usage_error.hpp"
#include "model/surface/surface_sensitivity.hpp"
#include "reference/cell_stepping.hpp"
#include "reference/load_curve.hpp"
#include "reference/measured_cell.hpp"
#include "reference/reference_point.hpp"
#include "reference/periodic_grid.hpp"
#include "sweep/reproducible_fft.hpp"

namespace po = boost::program_options;

namespace punchsweep::app {
namespace {

constexpr const char* kUsage =
    "usage: punchsweep surface --lattice square|hexagonal --l L --dh DH [--dh2 DH2] --T T --pbar P --s S [options]";

/// The grid's range (nodes per pitch), and --grid auto's: the least nodes that give the
/// smallest spot the times meet a radius of kAutoSpotRadius node spacings, within
/// [kAutoMin, kAutoMax] (past it the snapshots below the curve's resolution are flagged).
constexpr int kMaxGrid = 2048;
constexpr int kAutoMin = 64;
constexpr int kAutoMax = 512;
constexpr double kAutoSpotRadius = 12.0;
/// The largest supercell: K x K lattice cells.
constexpr int kMaxSupercell = 32;

/// --scatter's text: normal:SD, uniform:HALFWIDTH (lengths, >= 0) or list:V1,V2,...
model::HeightScatter read_scatter(const std::string& text, const input::PhysicalScales& scales) {
  const std::string valid = "normal:SD, uniform:HALFWIDTH (a length >= 0) or list:V1,V2,... (lengths)";
  const std::size_t colon = text.find(':');
  const std::string kind = text.substr(0, colon), rest = colon == std::string::npos ? "" : text.substr(colon + 1);
  const std::optional<input::Scale> scale = input::scale_of("R", scales);
  const auto length = [&](const std::string& value) {
    try {
      return input::read_scaled(value, *scale);
    } catch (const std::invalid_argument& e) {
      throw input::UsageError("--scatter = '" + text + "': " + e.what());
    }
  };
  model::HeightScatter out;
  if (kind == "normal" || kind == "uniform") {
    out.kind = kind == "normal" ? model::HeightScatter::Kind::normal : model::HeightScatter::Kind::uniform;
    out.width = length(rest);
    if (!(std::isfinite(out.width) && out.width >= 0.0)) {
      throw input::UsageError("--scatter = '" + text + "' is outside its range: " + valid);
    }
  } else if (kind == "list") {
    out.kind = model::HeightScatter::Kind::list;
    std::stringstream items(rest);
    for (std::string item; std::getline(items, item, ',');) {
      const double v = length(item);
      if (!std::isfinite(v)) throw input::UsageError("--scatter = '" + text + "': " + item + " is not finite");
      out.values.push_back(v);
    }
  } else {
    throw input::UsageError("--scatter = '" + text + "' is not one of: " + valid);
  }
  return out;
}

po::options_description surface_options(const input::PointMaterial& material) {
  po::options_description opts(
      "punchsweep surface: when each level of a periodic texture touches a creeping material, and\n"
      "the contact areas in time, from the elastic load curve of the texture's cell (boundary\n"
      "elements continued from first to full contact; docs/model.md, section 17).\n\n"
      "Units: lengths in R (punch size), pressures in E0* = E0/(1-nu^2), areas in R^2 and loads\n"
      "in R^2 E0* per cell, time in T_eps (creep time), or in the material file's time_unit.\n\nOptions");
  input::add_point_options(opts, material.spec);
  input::add_material_options(opts);
  input::add_tolerance_option(opts);
  opts.add_options()
      ("lattice", po::value<std::string>()->value_name("KIND")->default_value("square"),
       "square: level 1 at the squares' centres, level 2 at the edges' midpoints; hexagonal: the "
       "densest packing, level 1 at the triangles' centres (with --dh2: the upward ones, level 2 the "
       "downward ones)")
      ("dh2", po::value<std::string>()->value_name("DH2"),
       "a third level, this far below the tallest tips (R, or a length with --R); >= 0")
      ("cell", po::value<std::string>()->value_name("FILE"),
       "any rectangular periodic cell instead of a lattice: a [cell] file of Lx, Ly, s, C and one "
       "'site = x, y, drop, level[, s, C]' line per punch (docs/cli.md); --grid then counts nodes along Lx")
      ("height-map", po::value<std::string>()->value_name("FILE"),
       "a measured period of a texture: a height map (CSV rows along y, or a 2-D float .npy), one "
       "boundary-element node per pixel (an even count each way); its summits are the caps followed")
      ("pixel", po::value<std::string>()->value_name("SIZE"), "the height map's pixel (a length: 0.5um with --R, or in R)")
      ("height-unit", po::value<std::string>()->value_name("UNIT")->default_value("R"),
       "the unit of the map's heights: R, or a length unit with --R (um, nm)")
      ("summit-radius", po::value<std::string>()->value_name("L"),
       "a summit is higher than every pixel within this length (default 3 pixels)")
      ("level-gap", po::value<std::string>()->value_name("L"),
       "summits sorted by depth start a new level where the depth jumps by more than L (default: one level)")
      ("supercell", po::value<int>()->value_name("K")->default_value(1),
       "K x K lattice cells as one periodic cell, each cap's height scattered by --scatter: an integer "
       "in [1, 32]")
      ("scatter", po::value<std::string>()->value_name("DIST"),
       "each cap's height change (a positive one lowers the cap): normal:SD, uniform:HALFWIDTH (lengths "
       "in R, or with a unit and --R; >= 0) or list:V1,V2,... (one per cap of the supercell, in R); "
       "needs --supercell")
      ("seed", po::value<unsigned long long>()->value_name("N")->default_value(1),
       "the seed of --scatter's draws (std::mt19937_64; the same caps on every machine)")
      ("check", po::bool_switch(),
       "also step the same cell in time (the time-stepping boundary elements, which assume nothing of the "
       "contact's history) and print its touch times, areas and loads beside the curve's")
      ("grid", po::value<std::string>()->value_name("N")->default_value("auto"),
       "boundary-element nodes per pitch: an even integer in [4, 2048], or auto (the smallest spot the "
       "times meet spans a radius of 12 nodes; 64 to 512)")
      ("format", po::value<std::string>()->value_name("FMT")->default_value("table"),
       "output format: table, json or csv");
  return opts;
}

/// --height-map FILE with --pixel, --height-unit, --summit-radius and --level-gap: the
/// measured cell, lengths in R.
reference::MeasuredCell read_measured(const po::variables_map& vm, const input::PhysicalScales& scales) {
  const std::string path = vm["height-map"].as<std::string>();
  const input::HeightMap map = input::read_height_map(path);
  const std::optional<input::Scale> length = input::scale_of("R", scales);
  const auto read_length = [&](const char* option, const std::string& text) {
    double value = 0.0;
    try {
      value = input::read_scaled(text, *length);
    } catch (const std::invalid_argument& e) {
      throw input::UsageError(std::string("--") + option + " = " + e.what());
    }
    if (!(std::isfinite(value) && value > 0.0)) {
      throw input::UsageError(std::string("--") + option + " = " + text + " is outside its range: a length > 0");
    }
    return value;
  };
  if (!vm.count("pixel")) throw input::UsageError("--height-map needs --pixel SIZE, the map's pixel (a length: 0.5um with --R, or in R)");
  const double pixel = read_length("pixel", vm["pixel"].as<std::string>());
  const std::string unit = vm["height-unit"].as<std::string>();
  const double per_unit = unit == "R" ? 1.0 : read_length("height-unit", "1" + unit);
  if (map.nx % 2 != 0 || map.ny % 2 != 0) {
    throw input::UsageError(path + ": " + std::to_string(map.nx) + " x " + std::to_string(map.ny) +
                            " pixels; the boundary elements need an even count each way (crop a row or column)");
  }
  const double radius = vm.count("summit-radius") ? read_length("summit-radius", vm["summit-radius"].as<std::string>()) : 3.0 * pixel;
  if (radius < pixel) throw input::UsageError("--summit-radius is under one pixel: a summit needs neighbours to be above");
  const double gap = vm.count("level-gap") ? read_length("level-gap", vm["level-gap"].as<std::string>())
                                           : std::numeric_limits<double>::infinity();
  std::vector<double> z = map.height;
  for (double& v : z) v *= per_unit;
  return reference::make_measured_cell(z, map.nx, map.ny, pixel, radius, gap);
}

SurfaceRun read_surface(const po::variables_map& given, const input::PointMaterial& material) {
  SurfaceRun run;
  po::variables_map vm = given;
  std::optional<model::CellGeometry> cell;
  const bool measured = given.count("height-map") > 0;
  if (given.count("cell") || measured) {
    const std::string source = measured ? "--height-map" : "--cell";
    if (given.count("cell") && measured) throw input::UsageError("--cell beside --height-map: give one texture");
    for (const char* name : {"l", "dh", "dh2", "s", "C", "lattice"}) {
      if (given.count(name) && !given[name].defaulted()) {
        throw input::UsageError(std::string("--") + name + " beside " + source + ": the " +
                                (measured ? "height map" : "cell file") + " gives the cell, its sites and their shapes");
      }
    }
    const input::PhysicalScales scales = input::read_physical_scales(given, material.material.get());
    if (measured) {
      for (const char* name : {"grid", "supercell", "scatter"}) {
        if (given.count(name) && !given[name].defaulted()) {
          throw input::UsageError(std::string("--") + name + " beside --height-map: the map's pixels are the grid and its caps");
        }
      }
      run.measured = read_measured(given, scales);
      cell = run.measured->geometry;
      run.cell_file = given["height-map"].as<std::string>();
    } else {
      run.cell_file = given["cell"].as<std::string>();
      cell = input::read_cell_file(run.cell_file, scales);
    }
    // The point's reading of the material and the load reads a cell too: the texture's
    // (taken out of the inputs' echo below).
    const model::Site& first = cell->sites.front();
    const auto put = [&vm](const char* name, const std::string& text) {
      vm.erase(name);
      vm.emplace(name, po::variable_value(boost::any(text), false));
    };
    put("l", input::json_number(cell->Lx));
    put("dh", "0");
    put("s", std::to_string(first.shape.s));
    put("C", input::json_number(first.shape.C));
  }
  run.inputs = input::read_point_inputs(vm, material);
  if (cell) {
    std::erase_if(run.inputs.values, [](const auto& v) { return v.first->name == "l" || v.first->name == "dh" || v.first->name == "s" || v.first->name == "C"; });
  }
  run.times = input::read_times(vm, run.inputs.scales);
  run.tolerances = input::read_tolerances(vm, run.inputs);
  for (const model::Tolerance& t : run.tolerances) {
    if (t.parameter->name == "l" || t.parameter->name == "dh" || t.parameter->name == "C") {
      throw input::UsageError("--tolerance " + std::string(t.parameter->name) +
                              ": a tolerance on the texture's geometry needs a load curve per corner; surface takes "
                              "tolerances on the pressure and the creep law's parameters (pressure, T, temperature)");
    }
  }
  run.lattice = input::read_choice(vm, "lattice", {"square", "hexagonal"}) == "square" ? model::LatticeKind::square
                                                                                       : model::LatticeKind::hexagonal;
  std::vector<double> drops{run.inputs.problem.dh};
  if (vm.count("dh2")) {
    // --dh2 is dh's parameter under its own name: the same range and units.
    model::Parameter dh2 = *std::find_if(run.inputs.values.begin(), run.inputs.values.end(), [](const auto& v) {
                              return v.first->name == "dh";
                            })->first;
    dh2.name = "dh2";
    dh2.range = "dh2 >= 0 (in R)";
    drops.push_back(input::read_parameter(vm, dh2, &run.inputs.scales));
  }
  const std::string grid = vm["grid"].as<std::string>();
  if (grid != "auto") {
    const std::string range = "an even integer in [4, " + std::to_string(kMaxGrid) + "], or auto";
    try {
      std::size_t used = 0;
      run.grid_nodes = std::stoi(grid, &used);
      if (used != grid.size()) run.grid_nodes = -1;
    } catch (const std::exception&) {
      run.grid_nodes = -1;
    }
    if (run.grid_nodes < 4 || run.grid_nodes > kMaxGrid || run.grid_nodes % 2 != 0) {
      throw input::UsageError("--grid = " + grid + " is outside its range: " + range);
    }
  }
  run.check = vm.count("check") && vm["check"].as<bool>();
  run.geometry = cell ? *cell : model::lattice_cell(run.lattice, run.inputs.problem.l, run.inputs.problem.shape, drops);
  run.supercell = vm["supercell"].as<int>();
  if (run.supercell < 1 || run.supercell > kMaxSupercell) {
    throw input::UsageError("--supercell = " + std::to_string(run.supercell) + " is outside its range: an integer in [1, " +
                            std::to_string(kMaxSupercell) + "]");
  }
  if (vm.count("scatter")) {
    if (run.supercell == 1 && vm["supercell"].defaulted()) {
      throw input::UsageError("--scatter needs --supercell K (the caps whose heights scatter: K x K cells)");
    }
    run.scatter = read_scatter(vm["scatter"].as<std::string>(), run.inputs.scales);
    run.scatter.seed = vm["seed"].as<unsigned long long>();
    const std::size_t caps = static_cast<std::size_t>(run.supercell) * run.supercell * run.geometry.sites.size();
    if (run.scatter.kind == model::HeightScatter::Kind::list && run.scatter.values.size() != caps) {
      throw input::UsageError("--scatter list has " + std::to_string(run.scatter.values.size()) + " values: it needs one per cap, " +
                              std::to_string(caps) + " for " + std::to_string(run.supercell) + " x " +
                              std::to_string(run.supercell) + " cells of " + std::to_string(run.geometry.sites.size()) +
                              " caps");
    }
  }
  if (run.supercell > 1) run.geometry = model::supercell(run.geometry, run.supercell, run.scatter);
  return run;
}

/// --grid auto: nodes per pitch that give the tallest sites' spot, as an isolated punch's, a
/// radius of kAutoSpotRadius spacings at the least positive load the times meet.
int auto_grid(const SurfaceRun& run, const model::CreepWeightedLoad& load) {
  double X = std::numeric_limits<double>::infinity();
  for (const double t : run.times) {
    const double x = t > 0.0 ? load(t) : load.initial();
    if (x > 0.0) X = std::min(X, x);
  }
  if (!std::isfinite(X)) return kAutoMin;
  // The load spread over the tallest level's caps (all of them: in a scattered supercell
  // the nearly tallest touch at once, each with a small spot).
  double count = 0.0;
  for (const model::Site& site : run.geometry.sites) count += site.level == 0 ? 1.0 : 0.0;
  const model::Shape& shape = run.geometry.sites.front().shape;
  const double a = std::pow(X * run.geometry.Lx * run.geometry.Ly / count / model::load_coefficient(shape), 1.0 / (shape.s + 1));
  const double n = std::ceil(kAutoSpotRadius * run.geometry.Lx / run.supercell / a / 2.0) * 2.0;
  return static_cast<int>(std::clamp(n, static_cast<double>(kAutoMin), static_cast<double>(kAutoMax)));
}

/// The curve as far as the times reach, and the history on it.
void evaluate(SurfaceRun& run, bool progress) {
  const model::CreepWeightedLoad load(*run.inputs.creep, run.inputs.problem.pbar0, run.inputs.problem.loading);
  if (run.grid_nodes == 0 && !run.measured) run.grid_nodes = auto_grid(run, load);
  reference::PeriodicGrid grid;
  if (run.measured) {
    grid = run.measured->cell.grid;
  } else if (run.cell_file.empty()) {
    grid = reference::lattice_grid(run.geometry, run.lattice, run.grid_nodes, run.supercell);
  } else {
    // A cell file's tips go to their nearest nodes: the move is reported.
    grid = reference::cell_grid(run.geometry, run.grid_nodes * run.supercell);
    double moved = 0.0;
    run.geometry = reference::snap_tips(run.geometry, grid, &moved);
    if (grid.mirrored() && !model::mirror_symmetric(run.geometry)) grid.symmetry = reference::Symmetry::none;
    if (moved > 1e-9 * std::min(grid.hx(), grid.hy())) {
      std::ostringstream note;
      note.precision(3);
      note << "the tips were moved to the nearest nodes of the " << grid.nx << " x " << grid.ny << " grid, by at most "
           << moved << " R (" << moved / std::min(grid.hx(), grid.hy()) << " node spacings)";
      run.inputs.notes.push_back(note.str());
    }
  }
  const reference::Cell cell = run.measured ? run.measured->cell : reference::make_cell(run.geometry, grid);
  reference::LoadCurveOptions options;
  // To full contact, where every level that can touch has: the curve is then the
  // geometry's alone, whatever the material, temperature, pressure and times, and one
  // cached curve serves them all. FFTW's plans are its estimate's, so that a curve and
  // every answer read off it have the same bits in every process.
  sweep::use_reproducible_fft_plans();
  const auto start = std::chrono::steady_clock::now();
  auto last = start;
  if (progress) {
    options.progress = [&](int solves, double X) {
      const auto now = std::chrono::steady_clock::now();
      if (std::chrono::duration<double>(now - last).count() < 2.0) return;
      last = now;
      std::cerr << "punchsweep surface: load curve, " << solves << " solves, X = " << X << " E0* on the way to full contact\n";
    };
  }
  CurveOrigin origin = CurveOrigin::built;
  run.curve = load_curve_for(run.geometry, cell, options, &origin);
  run.curve_cached = origin == CurveOrigin::cache;
  run.curve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.history = model::surface_history(run.curve, load, run.times);
  // Each level's sensitivity of t* to the load's inputs, and its range over the tolerances.
  const model::SurfaceLoad surface_load{run.inputs.problem.pbar0, run.inputs.law, run.inputs.law_values,
                                        run.inputs.problem.loading};
  run.derivatives.resize(static_cast<std::size_t>(run.curve.levels()));
  run.ranges.resize(static_cast<std::size_t>(run.curve.levels()));
  for (int level = 1; level < run.curve.levels(); ++level) {
    const model::LevelTouch& touch = run.history.levels[static_cast<std::size_t>(level)];
    run.derivatives[static_cast<std::size_t>(level)] =
        model::level_t_star_derivatives(run.curve, level, surface_load, touch.t_star);
    if (!run.tolerances.empty()) {
      try {
        run.ranges[static_cast<std::size_t>(level)] = model::level_t_star_range(run.curve, level, surface_load, run.tolerances);
      } catch (const std::invalid_argument& e) {
        throw input::UsageError(std::string("--tolerance: ") + e.what());
      }
    }
  }
  if (run.check) {
    // The time stepping of the same cell, steps scaled to the law as `reference` scales them.
    reference::ReferenceOptions scaled;
    reference::scale_steps_to_law(*run.inputs.creep, &scaled);
    reference::CellReferenceOptions check;
    check.times = run.times;
    check.steps = scaled.steps;
    check.t_star_resolution = scaled.t_star_resolution;
    const auto check_start = std::chrono::steady_clock::now();
    run.stepped = reference::evaluate_cell_reference(run.geometry, cell, run.inputs.problem.pbar0, *run.inputs.creep,
                                                     run.inputs.problem.loading, check);
    run.check_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - check_start).count();
  }
}

std::string num(double v) { return input::json_number(v); }

/// "physical": the lengths, areas, loads and loads X in R's unit, its square, N and Pa,
/// where --R and a material give the scales (nothing otherwise).
void write_physical(std::ostream& out, const SurfaceRun& run) {
  const input::PhysicalScales& scales = run.inputs.scales;
  const std::optional<input::PhysicalUnit> length = input::physical_unit("R", scales);
  const std::optional<input::PhysicalUnit> pressure = input::physical_unit("E0/(1-nu^2)", scales);
  const std::optional<input::PhysicalUnit> load = input::physical_unit("R^2 E0/(1-nu^2)", scales);
  if (!length || !pressure || !load) return;
  const double area = length->per_scaled * length->per_scaled;
  const int L = run.curve.levels();
  out << "  \"physical\": {\n    \"units\": {\"X\": \"Pa\", \"area\": " << input::json_string(length->units + "^2")
      << ", \"load\": \"N\", \"drop\": " << input::json_string(length->units) << ", \"cell\": " << input::json_string(length->units)
      << "},\n    \"cell\": [" << num(run.geometry.Lx * length->per_scaled) << ", " << num(run.geometry.Ly * length->per_scaled)
      << "],\n    \"levels\": [";
  for (int level = 0; level < L; ++level) {
    double drop = std::numeric_limits<double>::infinity();
    for (const model::Site& site : run.geometry.sites) {
      if (site.level == level) drop = std::min(drop, site.drop);
    }
    out << (level ? ", " : "") << "{\"drop\": " << num(drop * length->per_scaled) << ", \"X_star\": "
        << num(run.history.levels[static_cast<std::size_t>(level)].X_star * pressure->per_scaled) << "}";
  }
  out << "],\n    \"series\": {\n";
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
void write_check(std::ostream& out, const SurfaceRun& run) {
  const reference::CellReference& r = *run.stepped;
  const int L = run.curve.levels();
  out << "  \"check\": {\n    \"seconds\": " << num(run.check_seconds) << ", \"steps\": " << r.steps << ", \"converged\": "
      << (r.converged ? "true" : "false") << ",\n    \"levels\": [";
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

void write_json(std::ostream& out, const SurfaceRun& run) {
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
  out << "  \"caps\": " << run.geometry.sites.size() << ",\n";
  out << "  \"curve\": {\"samples\": " << run.curve.samples.size() << ", \"X_first\": " << num(run.curve.X_first())
      << ", \"X_last\": " << num(run.curve.X_last()) << ", \"X_full\": " << num(run.curve.X_full)
      << ", \"seconds\": " << num(run.curve_seconds) << ", \"cached\": " << (run.curve_cached ? "true" : "false") << "},\n";
  out << "  \"levels\": [";
  for (int level = 0; level < L; ++level) {
    const model::LevelTouch& touch = run.history.levels[static_cast<std::size_t>(level)];
    double drop = std::numeric_limits<double>::infinity(), drop_max = 0.0;
    int sites = 0;
    for (const model::Site& site : run.geometry.sites) {
      if (site.level == level) {
        drop = std::min(drop, site.drop);
        drop_max = std::max(drop_max, site.drop);
        ++sites;
      }
    }
    out << (level ? ",\n    " : "\n    ") << "{\"level\": " << level << ", \"drop\": " << num(drop)
        << ", \"drop_max\": " << num(drop_max)
        << ", \"sites\": " << sites << ", \"regime\": " << input::json_string(std::string(model::regime_name(touch.regime)))
        << ", \"t_star\": " << num(touch.t_star) << ", \"X_star\": " << num(touch.X_star)
        << ", \"resolved\": " << (touch.resolved ? "true" : "false")
        << ", \"share\": " << num(run.curve.level_share[static_cast<std::size_t>(level)]);
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
  out << "\n  ],\n  \"series\": {\n";
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
  write_physical(out, run);
  if (run.stepped) write_check(out, run);
  out << "  \"units\": {\"t\": " << input::json_string(run.inputs.time_unit)
      << ", \"X\": \"E0*\", \"area\": \"R^2\", \"load\": \"R^2 E0*\", \"drop\": \"R\", \"cell\": \"R\"}\n}\n";
}

void write_table(std::ostream& out, const SurfaceRun& run, bool csv) {
  const int L = run.curve.levels();
  const char* sep = csv ? "," : "  ";
  out << (csv ? "# " : "") << "punchsweep surface: "
      << (run.measured ? "height map " + run.cell_file + ", " : run.cell_file.empty() ? model::lattice_name(run.lattice) + " lattice, " : "cell " + run.cell_file + ", ")
      << run.inputs.describe() << "\n";
  if (run.inputs.material) out << (csv ? "# " : "  ") << "material: " << run.inputs.material->describe() << "\n";
  for (const std::string& note : run.inputs.notes) out << (csv ? "# " : "  ") << "note: " << note << "\n";
  out << (csv ? "# " : "  ") << "load curve: " << run.curve.nx << " x " << run.curve.ny << " nodes, "
      << run.curve.samples.size() << " samples from X = " << run.curve.X_first() << " to " << run.curve.X_last()
      << " E0*" << (std::isfinite(run.curve.X_full) ? " (full contact)" : "") << ", " << run.curve_seconds << " s"
      << (run.curve_cached ? " (from the table cache)" : "") << "\n";
  for (int level = 0; level < L; ++level) {
    const model::LevelTouch& t = run.history.levels[static_cast<std::size_t>(level)];
    out << (csv ? "# " : "  ") << "level " << level << ": " << model::regime_name(t.regime);
    if (t.regime == model::Regime::delayed) out << " at t* = " << t.t_star << " " << run.inputs.time_unit;
    if (!t.resolved) {
      out << " (touches at X* = " << t.X_star << " E0*, below the curve's resolution: a finer --grid answers)\n";
    } else if (std::isfinite(t.X_star)) {
      out << " (touches at X* = " << t.X_star << " E0*)\n";
    } else {
      out << " (untouched up to X = " << run.curve.X_last() << " E0*, past X(inf))\n";
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
  if (run.stepped) {
    for (int level = 1; level < L; ++level) {
      const std::size_t at = static_cast<std::size_t>(level);
      out << (csv ? "# " : "  ") << "check: level " << level << " by time stepping: "
          << model::regime_name(run.stepped->level_regime[at]);
      if (std::isfinite(run.stepped->level_t_star[at]) && run.stepped->level_t_star[at] > 0.0) {
        out << " at t* = " << run.stepped->level_t_star[at] << " " << run.inputs.time_unit;
      }
      out << "\n";
    }
    out << (csv ? "# " : "  ") << "check: " << run.stepped->steps << " time steps, " << run.check_seconds << " s\n";
  }
  out << "t" << sep << "X" << sep << "area_fraction" << sep << "sites_touched";
  for (int level = 0; level < L; ++level) out << sep << "area_" << level;
  for (int level = 0; level < L; ++level) out << sep << "load_" << level;
  if (run.stepped) out << sep << "check_area_fraction" << sep << "check_sites_touched";
  out << sep << "valid\n";
  for (std::size_t k = 0; k < run.history.snapshots.size(); ++k) {
    const model::SurfaceSnapshot& s = run.history.snapshots[k];
    out << s.t << sep << s.X << sep << s.state.area_fraction << sep << s.state.sites_touched;
    for (double a : s.state.level_area) out << sep << a;
    for (double P : s.level_load) out << sep << P;
    if (run.stepped) out << sep << run.stepped->series[k].area_fraction << sep << run.stepped->series[k].sites_touched;
    out << sep << model::surface_validity_name(s.validity) << "\n";
  }
}

}  // namespace

int run_surface_command(const std::vector<std::string>& args, std::ostream& out) {
  const input::PointMaterial material = input::find_point_material(args);
  const po::options_description opts = surface_options(material);
  const po::variables_map vm = input::parse_command(args, opts, "surface");
  if (vm.count("help")) {
    out << kUsage << "\n\n" << opts << "\n"
        << "Example: punchsweep surface --lattice hexagonal --l 1.2 --dh 0.05 --T 2.5 --pbar 0.02 --s 2 --format json\n"
        << "Exit codes: 0 success (a flagged snapshot is still a success: see 'valid'), 2 bad input.\n";
    return 0;
  }
  SurfaceRun run = read_surface(vm, material);
  const std::string format = input::read_choice(vm, "format", {"table", "json", "csv"});
  evaluate(run, true);
  if (format == "json") {
    write_json(out, run);
  } else {
    write_table(out, run, format == "csv");
  }
  return 0;
}

SurfaceRun evaluate_surface(const input::Keywords& keywords) {
  const input::PointMaterial material = input::find_point_material(keywords);
  SurfaceRun run = read_surface(input::parse_keywords(keywords, surface_options(material), "surface"), material);
  evaluate(run, false);
  return run;
}

std::string surface_json(const input::Keywords& keywords) {
  std::ostringstream out;
  write_json(out, evaluate_surface(keywords));
  return out.str();
}

}  // namespace punchsweep::app
