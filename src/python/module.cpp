// The compiled part of the Python package `punchsweep` (punchsweep._core): the engine's
// point, reference and regime evaluation, called in-process. `point` and `reference` take
// the command line's own arguments, read and checked by the commands' own code, so their
// numbers are `punchsweep point|reference --format json`'s bit for bit and their errors
// the commands' messages; `classify` evaluates arrays of points as a sweep does, sharing
// the parts of a summary between points (model::DhParts, model::SingleLevelEnds).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <functional>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "engine/design.hpp"
#include "engine/material_fitting.hpp"
#include "engine/periodic_tables.hpp"
#include "engine/point_evaluation.hpp"
#include "engine/reference_evaluation.hpp"
#include "engine/surface_evaluation.hpp"
#include "engine/texture_map.hpp"
#include "input/axis_parser.hpp"
#include "input/command_options.hpp"
#include "input/usage_error.hpp"
#include "input/scaled_value.hpp"
#include "map/quantities.hpp"
#include "model/problem/contact_problem.hpp"
#include "model/problem/localization.hpp"
#include "model/laws/creep_laws.hpp"
#include "model/load/creep_weighted_load.hpp"
#include "model/point/parameters.hpp"
#include "model/point/point_axes.hpp"
#include "model/point/point_evaluation.hpp"
#include "model/contact/regime.hpp"
#include "model/numerics/stop_request.hpp"
#include "model/point/validity.hpp"
#include "model/periodic/periodic_solution.hpp"
#include "model/surface/geometry_parts.hpp"
#include "model/surface/surface_history.hpp"
#include "report/design_output.hpp"
#include "report/point_output.hpp"
#include "report/surface_output.hpp"
#include "sweep/batch_evaluator.hpp"

namespace py = pybind11;
using namespace punchsweep;

namespace {

/// Whether Ctrl-C was pressed, for work that runs without the GIL in the interpreter's main
/// thread: Python's handler only sets a flag that the interpreter looks at, so at most every
/// 0.1 s this takes the GIL and asks (PyErr_CheckSignals); once it says yes, the
/// KeyboardInterrupt is set for py::error_already_set to raise (made with the GIL held).
class CtrlC {
 public:
  bool pressed() {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(100)) return false;
    last_ = now;
    py::gil_scoped_acquire acquire;
    return PyErr_CheckSignals() != 0;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

/// A number as the JSON output has it: None where the JSON writes null (not computed).
py::object json_value(double v) { return std::isfinite(v) ? py::object(py::float_(v)) : py::none(); }

py::array_t<double> array(const std::vector<double>& values) {
  py::array_t<double> out(static_cast<py::ssize_t>(values.size()));
  if (!values.empty()) std::memcpy(out.mutable_data(), values.data(), values.size() * sizeof(double));
  return out;
}

/// The keys of `punchsweep point --format json`, read through the same visitor as the JSON
/// writer (report::visit_point): flags as names, valid as a bool, reals as floats (None where
/// the JSON has null), and the series as arrays (NaN where the JSON has null).
struct DictFields final : report::PointFields {
  py::dict out, columns;
  void text(std::string_view name, const std::string& value) override { out[py::str(name)] = value; }
  void boolean(std::string_view name, bool value) override { out[py::str(name)] = value; }
  void number(std::string_view name, double value) override { out[py::str(name)] = json_value(value); }
  void series(std::string_view name, const std::vector<double>& values) override {
    columns[py::str(name)] = array(values);
  }
};

py::dict point_dict(const model::PointResult& r, const std::string& time_unit) {
  DictFields fields;
  report::visit_point(r, time_unit, fields);
  fields.out["series"] = fields.columns;
  return fields.out;
}

py::dict point_command(const input::Keywords& keywords) {
  const engine::PointRun run = engine::evaluate_point(keywords);
  py::dict out = point_dict(run.result, run.inputs.time_unit);
  out["localization"] = run.inputs.problem.localization.spelling();
  out["time_unit"] = run.inputs.time_unit;
  out["notes"] = py::tuple(py::cast(run.inputs.notes));
  py::dict physical, series, units;
  for (const report::PhysicalField& f : report::physical_fields(run.inputs, run.result)) {
    if (f.series) {
      series[py::str(f.name)] = array(f.values);
    } else {
      physical[py::str(f.name)] = json_value(f.values.front());
    }
    units[py::str(f.name)] = f.units;
  }
  if (!units.empty()) {  // as the JSON: only where a scale is known
    physical["series"] = series;
    out["physical"] = physical;
    out["units"] = units;
  }
  return out;
}

/// `punchsweep reference --format json`'s keys, with the model's point keys it has.
py::dict reference_command(const input::Keywords& keywords) {
  // Ctrl-C between the BEM's time steps; the KeyboardInterrupt it sets is raised below.
  CtrlC ctrl_c;
  const model::StopRequest interrupted([&ctrl_c] { return ctrl_c.pressed(); });
  std::optional<engine::ReferenceRun> solved;
  {
    py::gil_scoped_release release;
    try {
      solved.emplace(engine::evaluate_reference(keywords, interrupted));
    } catch (const model::Stopped&) {
    }
  }
  if (!solved) throw py::error_already_set();
  const engine::ReferenceRun& run = *solved;
  const reference::ReferenceResult& r = run.result;
  py::dict out;
  out["regime"] = std::string(model::regime_name(r.regime));
  out["t_star"] = r.t_star ? py::object(py::float_(*r.t_star)) : py::none();
  out["t_star_lower"] = json_value(r.t_star_lower);
  out["t_star_upper"] = json_value(r.t_star_upper);
  out["converged"] = r.converged;
  out["cg_iterations"] = r.cg_iterations;
  out["max_residual"] = json_value(r.max_residual);
  out["bem_grid"] = run.options.n;
  out["spacing"] = json_value(r.spacing);
  out["steps"] = r.steps;
  out["solves"] = r.solves;
  out["seconds"] = run.seconds;
  out["time_unit"] = run.inputs.time_unit;
  py::dict series;
  const auto column = [&](auto field) {
    std::vector<double> v;
    for (const auto& s : r.series) v.push_back(field(s));
    return array(v);
  };
  series["t"] = column([](const auto& s) { return s.t; });
  series["a1"] = column([](const auto& s) { return s.a1; });
  series["a2"] = column([](const auto& s) { return s.a2; });
  series["P1"] = column([](const auto& s) { return s.P1; });
  series["P2"] = column([](const auto& s) { return s.P2; });
  series["area_fraction"] = column([](const auto& s) { return s.area_fraction; });
  series["h"] = column([](const auto& s) { return s.h; });
  out["series"] = series;
  return out;
}

/// A value as point() hands it to the command line, so that classify's message is the
/// command's for the same keyword: Python's repr of a float (shortest exact digits, ".0"
/// on a whole number), a whole number as an integer for an integer parameter.
std::string value_text(double v, bool integer) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  if (integer && v == std::floor(v) && std::abs(v) < 1e15) return std::to_string(static_cast<long long>(v));
  std::string text = input::json_number(v);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

/// The command line's message for a value of `p` outside its range, else empty.
std::string check(const model::Parameter& p, double value) {
  if (p.admits(value)) return {};
  return input::out_of_range(p, value_text(value, p.integer));
}

using Column = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// A material file read by the engine's reader (its checks and messages), for classify's
/// material= and punchsweep.Material.
std::shared_ptr<const model::Material> read_material(const std::string& path) {
  if (path.find('\0') != std::string::npos) throw input::UsageError("--material: the file name has a NUL byte");
  return input::read_material_file(path);
}

/// `text` for the parameter called `name` in its scale (input/scaled_value.hpp: the command
/// line's rule), the scales coming from the material file `material` and `R` (each may be
/// ""). ValueError naming the keyword for a unit mistake or a value out of range.
double scaled_value(const std::string& text, const std::string& name, const std::string& material,
                    const std::string& R) {
  const model::Parameter* p = model::find_parameter(name);
  if (p == nullptr) throw input::UsageError("no parameter " + name);
  const std::string key = name == model::kPressure ? std::string("pressure") : name;
  const std::shared_ptr<const model::Material> file = material.empty() ? nullptr : read_material(material);
  input::PhysicalScales scales;
  try {
    scales = input::scales_of(file.get(), R.empty() ? std::nullopt : std::optional(input::read_length_scale(R)));
  } catch (const std::invalid_argument& e) {
    throw input::UsageError("R = " + std::string(e.what()));
  }
  const std::optional<input::Scale> scale = input::scale_of(p->scale, scales);
  double value = 0.0;
  try {
    if (!scale) throw std::invalid_argument("'" + text + "': " + name + " is a pure number");
    value = input::read_scaled(text, *scale);
  } catch (const std::invalid_argument& e) {
    throw input::UsageError(key + " = " + e.what() + "; valid range: " + std::string(p->range));
  }
  if (!p->admits(value)) {
    throw input::UsageError(key + " = " + text + " (" + input::json_number(value) + " " + std::string(p->scale) +
                          ") is outside its range: " + std::string(p->range));
  }
  return value;
}

/// The message for a temperature given to a material (`who`: its file or name) without a [shift].
std::string no_shift(const std::string& who) {
  return "the material " + who + " has no temperature shift, so it takes no temperature";
}

/// A law's parameters at the point command's defaults (a material's T_ref).
std::vector<double> point_defaults(std::span<const model::Parameter> parameters) {
  std::vector<double> values;
  for (const model::Parameter& p : parameters) {
    if (p.point_default.empty()) throw input::UsageError(std::string(p.name) + " is required");
    values.push_back(std::stod(std::string(p.point_default)));
  }
  return values;
}

/// What classify returns: the registry's per-point quantities of the model (map::kQuantities:
/// Source::model, Extent::point), so that a new one reaches Python with its entry; those
/// `named` only where some are (each output array costs a grid about 8% of its time).
std::vector<const map::QuantitySpec*> classify_outputs(const std::vector<std::string>& named) {
  std::vector<const map::QuantitySpec*> out;
  std::string valid;
  for (const map::QuantitySpec& q : map::kQuantities) {
    if (q.source != map::Source::model || q.extent != map::Extent::point) continue;
    valid += (valid.empty() ? "" : ", ") + std::string(q.name);
    if (named.empty() || std::find(named.begin(), named.end(), q.name) != named.end()) out.push_back(&q);
  }
  for (const std::string& name : named) {
    if (std::none_of(out.begin(), out.end(), [&](const map::QuantitySpec* q) { return q->name == name; })) {
      throw input::UsageError("classify: quantities: '" + name + "' is not one of: " + valid);
    }
  }
  return out;
}

/// classify_outputs(quantities) of n points (the map's codes and units: the regime, t*, h(0), h(inf),
/// validity, long-term radii and area fraction), each
/// a pure function of its point: sweep::BatchEvaluator, as a sweep's tile evaluates its
/// points, over the points sorted by (s, l, dh) so that the parts those share are computed
/// once. `law` holds the creep law's parameters (the standard linear solid's T, or a
/// material file's temperature where it has a shift), `ramp_time` the load's rise time
/// (empty: a step).
/// Python's columns of points by coordinate name ("l", "dh", "T", "pbar", "s", "ramp_time", ...).
using Columns = std::map<std::string, Column>;

/// The columns of n points, one per coordinate of `axes` (model::PointAxes), from `given`:
/// a law parameter left out at the point command's default where it has one (a material's
/// T_ref); the texture's coordinates (l, dh, s) skipped where `texture` is true. Every value
/// is checked against its parameter's range, axis by axis in the command line's order.
/// UsageError (`who`: the call) naming a coordinate that is not among `axes` (`unknown`
/// says why, where it knows better), one missing, arrays of unequal size, or the first
/// value out of range.
struct AxisColumns {
  std::vector<std::vector<double>> defaults;  ///< the columns made of defaults
  std::vector<const double*> values;          ///< one per axis; nullptr where skipped
  std::size_t n = 0;
};
AxisColumns axis_columns(const Columns& given, const model::PointAxes& axes, bool texture, const std::string& who,
                         const std::function<std::string(const std::string&)>& unknown = {}) {
  const auto skipped = [&](const model::PointAxis& axis) {
    return texture && axis.coordinate <= model::Coordinate::height_difference;
  };
  std::string valid;
  for (const model::PointAxis& axis : axes) {
    if (!skipped(axis)) valid += (valid.empty() ? "" : ", ") + std::string(axis.parameter->name);
  }
  AxisColumns out;
  bool first = true;
  for (const auto& [name, column] : given) {
    const std::size_t j = axes.find(name);
    if (j == axes.size() || skipped(axes[j])) {
      const std::string why = unknown ? unknown(name) : std::string();
      throw input::UsageError(who + ": " + (why.empty() ? name + " is no coordinate of these points; valid: " + valid : why));
    }
    if (!first && static_cast<std::size_t>(column.size()) != out.n) {
      throw std::invalid_argument(who + ": the arrays must have the same size (broadcast first)");
    }
    out.n = static_cast<std::size_t>(column.size());
    first = false;
  }
  for (const model::PointAxis& axis : axes) {
    const model::Parameter& p = *axis.parameter;
    if (skipped(axis)) {
      out.values.push_back(nullptr);
    } else if (const auto found = given.find(std::string(p.name)); found != given.end()) {
      out.values.push_back(found->second.data());
    } else if (axis.coordinate == model::Coordinate::law && !p.point_default.empty()) {
      out.defaults.emplace_back(out.n, std::stod(std::string(p.point_default)));
      out.values.push_back(out.defaults.back().data());
    } else {
      throw input::UsageError(who + ": " + std::string(p.name) + " is required (" + std::string(p.meaning) + ")");
    }
  }
  for (std::size_t j = 0; j < axes.size(); ++j) {
    if (out.values[j] == nullptr) continue;
    for (std::size_t i = 0; i < out.n; ++i) {
      // admits() first: the message's string costs a scattered call 3% of its time.
      if (!axes[j].parameter->admits(out.values[j][i])) throw input::UsageError(check(*axes[j].parameter, out.values[j][i]));
    }
  }
  return out;
}

py::dict classify(const Columns& given, double C, const std::string& localization, const std::string& material_file,
                  const std::vector<std::string>& quantities) {
  const std::vector<const map::QuantitySpec*> wanted = classify_outputs(quantities);
  std::shared_ptr<const model::Material> material;
  if (!material_file.empty()) material = read_material(material_file);
  model::Localization model_localization;
  try {
    model_localization = model::parse_localization(localization);
  } catch (const std::invalid_argument& e) {
    throw input::UsageError(std::string("--localization: ") + e.what());  // as input::read_localization says it
  }
  const model::CreepLawSpec spec = material ? material->spec() : model::creep_laws().front();
  if (const std::string e = check(*model::find_parameter(model::kShapeConstant), C); !e.empty()) {
    throw input::UsageError(e);
  }
  const model::PointAxes axes(spec.parameters, given.contains(std::string(model::ramp_time_parameter().name)));
  // A law's parameters left out take the point command's defaults (a material's T_ref).
  const AxisColumns columns = axis_columns(given, axes, false, "classify", [&](const std::string& name) {
    return material && name == model::temperature_parameter().name ? no_shift(material_file) : std::string();
  });
  const auto n = static_cast<py::ssize_t>(columns.n);

  // classify's outputs: every per-point quantity of the model in the registry, in its order,
  // each under its registry name: a real as float64, a flag as its codes (the map's); the
  // validity flag as Python reads it everywhere (point()'s `valid`), a bool, with its codes
  // beside it as NAME_code. Each array is written once, at the point's own position.
  struct Output {
    const map::QuantitySpec* quantity;
    std::optional<py::array_t<double>> values;
    std::optional<py::array_t<std::int8_t>> codes;
    std::optional<py::array_t<bool>> mask;
    double* value_data = nullptr;  // their memory, taken while the interpreter lock is held
    std::int8_t* code_data = nullptr;
    bool* mask_data = nullptr;
  };
  std::vector<Output> outputs;
  for (const map::QuantitySpec* q : wanted) {
    Output o{q, {}, {}, {}};
    if (q->kind == map::Kind::flag) {
      o.code_data = o.codes.emplace(n).mutable_data();
      if (q->flags == map::Flags::validity) o.mask_data = o.mask.emplace(n).mutable_data();
    } else {
      o.value_data = o.values.emplace(n).mutable_data();
    }
    outputs.push_back(std::move(o));
  }
  {
    py::gil_scoped_release release;
    // The points sorted by (s, l, dh), their columns copied in that order: each (s, l, dh)
    // is then one run that shares its touchdown and branch, and the evaluator reads and
    // this writes memory in order (scattered points went at 5.6e5 points/s read through
    // the permutation, 6.6e5 sorted; issue 23).
    // The points sorted by the coordinates a batch's runs are made of (l, s, dh: their
    // touchdown and branch), their columns copied in that order: each run then shares its
    // parts, and the evaluator reads and this writes memory in order (scattered points went
    // at 5.6e5 points/s read through the permutation, 6.6e5 sorted; issue 23).
    const auto N = static_cast<std::size_t>(n);
    const std::vector<std::size_t> nesting = axes.nesting();
    constexpr std::size_t R = model::kRunCoordinates;
    // The keys sorted with the points' positions (within a run the points keep their order:
    // a grid's then runs over its later axes), held together so that the sort reads memory
    // in order (sorting positions through the arrays took 12% of a scattered call).
    struct Key {
      std::array<double, R> run;
      std::size_t i;
    };
    std::vector<Key> keys(N);
    for (std::size_t q = 0; q < R; ++q) {
      const double* column = columns.values[nesting[q]];
      for (std::size_t i = 0; i < N; ++i) keys[i].run[q] = column[i];
    }
    for (std::size_t i = 0; i < N; ++i) keys[i].i = i;
    std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) { return std::tie(a.run, a.i) < std::tie(b.run, b.i); });
    const std::size_t width = axes.size();
    // Every element is written below: left uninitialized (zeroing them cost 2% of a call).
    const auto sorted = std::make_unique_for_overwrite<double[]>(width * N);
    const auto order = std::make_unique_for_overwrite<std::size_t[]>(N);
    for (std::size_t k = 0; k < N; ++k) {
      order[k] = keys[k].i;
      for (std::size_t q = 0; q < R; ++q) sorted[nesting[q] * N + k] = keys[k].run[q];
    }
    std::vector<Key>().swap(keys);
    for (std::size_t q = R; q < width; ++q) {
      const double* from = columns.values[nesting[q]];
      double* column = &sorted[nesting[q] * N];
      for (std::size_t k = 0; k < N; ++k) column[k] = from[order[k]];
    }
    sweep::PointColumns points{&axes, {}};
    for (std::size_t j = 0; j < width; ++j) points.columns.emplace_back(&sorted[j * N], N);

    // Each point's answers read off its summary as the registry says, in sorted order, then
    // put back in the points' order: writing each straight to its point's position took
    // scattered points 20% longer (a cache miss per array and point). (The evaluator hands
    // on every point once.)
    struct Answers final : sweep::BatchSink {
      std::vector<std::int8_t (*)(const model::PointSummary&)> code_of;
      std::vector<double (*)(const model::PointSummary&)> value_of;
      std::vector<std::unique_ptr<std::int8_t[]>> codes;
      std::vector<std::unique_ptr<double[]>> values;
      void take(const sweep::BatchPoint& p) override {
        for (std::size_t j = 0; j < codes.size(); ++j) codes[j][p.k] = code_of[j](p.summary);
        for (std::size_t j = 0; j < values.size(); ++j) values[j][p.k] = value_of[j](p.summary);
      }
    } answers;
    for (const Output& o : outputs) {
      if (o.values) {
        answers.value_of.push_back(o.quantity->value);
        answers.values.push_back(std::make_unique_for_overwrite<double[]>(N));
      } else {
        answers.code_of.push_back(o.quantity->code);
        answers.codes.push_back(std::make_unique_for_overwrite<std::int8_t[]>(N));
      }
    }
    // Ctrl-C as the batch evaluator asks (every 64 points, and before building a run's
    // parts); the KeyboardInterrupt it sets is raised below.
    CtrlC ctrl_c;
    const model::StopRequest interrupted([&ctrl_c] { return ctrl_c.pressed(); });
    sweep::BatchEvaluator evaluator(spec, C, model_localization, {}, sweep::BatchEvaluator::Memory::call);
    try {
      evaluator.summarize(points, answers, interrupted);
    } catch (const model::Stopped&) {
      py::gil_scoped_acquire acquire;  // error_already_set takes the error under the GIL
      throw py::error_already_set();
    }
    std::size_t c = 0, v = 0;
    for (const Output& o : outputs) {
      if (o.values) {
        const double* from = answers.values[v++].get();
        for (std::size_t k = 0; k < N; ++k) o.value_data[order[k]] = from[k];
        continue;
      }
      const std::int8_t* from = answers.codes[c++].get();
      for (std::size_t k = 0; k < N; ++k) o.code_data[order[k]] = from[k];
      if (o.mask_data != nullptr) {
        for (std::size_t k = 0; k < N; ++k) o.mask_data[order[k]] = from[k] == static_cast<std::int8_t>(model::Validity::valid);
      }
    }
  }
  py::dict out;
  for (const Output& o : outputs) {
    const std::string name(o.quantity->name);
    if (o.values) {
      out[name.c_str()] = *o.values;
    } else if (o.mask) {
      out[name.c_str()] = *o.mask;
      out[(name + "_code").c_str()] = *o.codes;
    } else {
      out[name.c_str()] = *o.codes;
    }
  }
  out["time_unit"] = material ? material->time_unit() : std::string("T_eps");
  return out;
}

/// A material file as the engine reads it (input::read_material_file: its checks, its
/// messages), for punchsweep.Material.
struct MaterialHandle {
  std::shared_ptr<const model::Material> material;

  /// The file's description and constants: name, law, time unit, E_0 and E0* in Pa, nu,
  /// the shift's description and T_ref (None without a shift).
  py::dict info() const {
    const model::Material& m = *material;
    py::dict out;
    out["name"] = m.name();
    out["law"] = m.law();
    out["time_unit"] = m.time_unit();
    out["E0_Pa"] = m.instantaneous_modulus_Pa();
    out["plane_strain_modulus_Pa"] = m.plane_strain_modulus_Pa();
    out["poisson"] = m.poisson();
    out["description"] = m.describe();
    out["shift"] = m.shift() ? py::object(py::str(m.shift()->describe())) : py::none();
    out["reference_temperature"] = m.shift() ? py::object(py::float_(m.shift()->T_ref)) : py::none();
    return out;
  }

  /// The law at `temperature` (degC; NaN: the file's own, at T_ref where it has a shift).
  std::unique_ptr<model::CreepLaw> law_at(double temperature) const {
    const model::Material& m = *material;
    if (std::isnan(temperature) || m.parameters().empty()) {
      if (!std::isnan(temperature)) throw input::UsageError(no_shift(m.name()));
      return m.make(point_defaults(m.parameters()));
    }
    const double values[] = {temperature};
    try {
      return m.make(values);
    } catch (const std::invalid_argument& e) {
      throw input::UsageError(e.what());
    }
  }

  /// J(t) (in 1/E0*, as the engine holds it) or E(t) (in E0*) at times t in the file's unit.
  py::array_t<double> evaluate(Column t, double temperature, bool relaxation) const {
    const std::unique_ptr<model::CreepLaw> law = law_at(temperature);
    py::array_t<double> out(t.size());
    const double* in = t.data();
    double* values = out.mutable_data();
    for (py::ssize_t i = 0; i < t.size(); ++i) {
      if (!(in[i] >= 0.0)) throw input::UsageError("material: times must be >= 0 (in the file's time unit)");
      values[i] = relaxation ? law->relaxation(in[i]) : law->creep(in[i]);
    }
    return out;
  }

  /// log10 a_T(temperature); ValueError naming the shift's range outside it.
  double log10_shift(double temperature) const {
    const model::Material& m = *material;
    if (!m.shift()) throw input::UsageError("the material " + m.name() + " has no temperature shift");
    if (!m.shift()->admits(temperature)) {
      throw input::UsageError("temperature = " + input::json_number(temperature) + " is outside the shift's range: " +
                            m.shift()->range());
    }
    return m.shift()->log10_factor(temperature);
  }
};

/// The map's regime codes and names (model::Regime), for decoding classify's codes.
py::dict regime_codes() {
  py::dict out;
  for (const model::Regime r : {model::Regime::immediate, model::Regime::delayed, model::Regime::never}) {
    out[py::int_(static_cast<int>(r))] = std::string(model::regime_name(r));
  }
  return out;
}

/// `punchsweep fit` of keywords: the .fit.json's text (the one writer of the fit's numbers),
/// the report, the material file's text, and the paths written ("" for none).
py::dict fit_command(const input::Keywords& keywords) {
  const engine::FitRun run = engine::fit_material(keywords);
  py::dict out;
  out["details"] = run.details_json;
  out["report"] = run.report;
  out["material_text"] = run.material_text;
  out["output"] = run.output;
  out["details_path"] = run.details;
  return out;
}

}  // namespace

namespace {

/// A value the parameter `p` admits, where a texture's curve is read without a point
/// (surface_classify of an empty input): the point command's default, else the first value of
/// a sweep's (pbar 0.005, T 2).
std::string nominal_value(const model::Parameter& p) {
  if (!p.point_default.empty()) return std::string(p.point_default);
  if (p.sweep_default.empty()) {
    throw input::UsageError("surface_classify: no points, and " + std::string(p.name) + " has no default to read the "
                            "texture's curve at; give at least one point");
  }
  return input::json_number(input::parse_axis(std::string(p.sweep_default), p.integer).values.front());
}

}  // namespace

/// One texture's answers at its points (surface_classify's, of one geometry).
struct TextureAnswers {
  std::size_t levels = 0;
  std::vector<double> t_star;        ///< n x levels, row-major
  std::vector<std::int8_t> regime;   ///< n x levels
  std::vector<double> X_star;        ///< per level
  std::vector<char> resolved;        ///< per level
  std::string time_unit;
  std::array<int, 2> grid{};
  std::size_t caps = 0;
};

/// Each level's regime and t* of the texture of `texture`'s keywords at the points of
/// `given` (the load's coordinates: pbar, the law's parameters, ramp_time): one load curve
/// (as far as the points reach, cached; from a run at the least pressure, whose grid
/// --grid auto takes), then the classification at each point from the levels' touchdown
/// loads. No points read the curve at a nominal load (nominal_value), for the levels.
TextureAnswers classify_texture(const input::Keywords& texture, const Columns& given) {
  const input::PointMaterial material = input::find_point_material(texture);
  const model::CreepLawSpec& spec = material.spec;
  const model::PointAxes axes(spec.parameters, given.contains(std::string(model::ramp_time_parameter().name)));
  const AxisColumns columns = axis_columns(given, axes, true, "surface_classify");
  const std::size_t n = columns.n;
  const double* pbar = columns.values[axes.find(model::Coordinate::pressure)];
  std::vector<const double*> law_values;
  for (const std::size_t j : axes.law()) law_values.push_back(columns.values[j]);
  std::size_t least = 0;
  for (std::size_t i = 1; i < n; ++i) least = pbar[i] < pbar[least] ? i : least;
  input::Keywords keywords = texture;
  keywords.emplace_back("pbar", n > 0 ? input::json_number(pbar[least])
                                      : nominal_value(*model::find_parameter(model::kPressure)));
  for (std::size_t j = 0; j < law_values.size(); ++j) {
    keywords.emplace_back(std::string(spec.parameters[j].name),
                          n > 0 ? input::json_number(law_values[j][least]) : nominal_value(spec.parameters[j]));
  }
  keywords.emplace_back("times", "0");
  // The texture's parts: the paper's lattice by the periodic model, any other by its curve,
  // as far as the points reach (the whole curve for no points: their X_star are the
  // texture's, as any call that reaches them gives).
  engine::MoreLoadPoints points = engine::MoreLoadPoints::any_load();
  if (n > 0) {
    const double reach = model::largest_final_load(spec, axes, columns.values, columns.n);
    points.X_reach = [reach](const engine::SurfaceRun&) { return reach; };
  }
  const engine::TextureParts texture_parts = engine::texture_parts(keywords, points);
  const engine::SurfaceRun& run = texture_parts.run;
  const model::GeometryParts& parts = *texture_parts.parts;
  TextureAnswers out;
  out.levels = static_cast<std::size_t>(parts.levels());
  out.t_star.resize(n * out.levels);
  out.regime.resize(n * out.levels);
  parts.touches_at(spec, axes, columns.values, columns.n, out.t_star.data(), out.regime.data());
  for (const model::LevelTouch& touch : parts.touches(model::CreepWeightedLoad(*run.inputs.creep, run.inputs.problem.pbar0))) {
    out.X_star.push_back(touch.X_star);
    out.resolved.push_back(touch.resolved ? 1 : 0);
  }
  out.time_unit = run.inputs.time_unit;
  // The grid: the curve's, or the periodic tables' own (nodes a pitch).
  if (const model::LoadCurve* curve = parts.curve()) {
    out.grid = {curve->nx, curve->ny};
  } else {
    const int tables = model::periodic_solution(run.inputs.problem.shape.s).tables().n;
    out.grid = {tables, tables};
  }
  out.caps = run.geometry.sites.size();
  return out;
}

/// The texture's geometry that surface_classify takes as columns of points (each distinct
/// combination one load curve): surface's keywords.
constexpr std::array<const char*, 4> kGeometryColumns{"l", "dh", "dh2", "s"};

/// `surface_classify`: each level's regime and t* of a texture (the keywords of `punchsweep
/// surface`, without the load's) at many points of pressure, law parameters and ramp, and of
/// its geometry where `given` has columns of it (l, dh, dh2, s, each value as the keyword
/// reads it: in R, or a whole s): the points are grouped by geometry, each group's texture
/// read as classify_texture reads one (its curve built once, cached), and the answers put
/// back in the points' order. With geometry columns X_star, resolved and grid are per point
/// (n x levels, n x 2); without, per level and one grid, as the one texture's.
py::dict surface_classify(const input::Keywords& texture, const Columns& given) {
  Columns load = given;
  std::vector<std::pair<std::string, Column>> geometry;
  for (const char* name : kGeometryColumns) {
    if (const auto found = load.find(name); found != load.end()) {
      if (std::any_of(texture.begin(), texture.end(), [&](const auto& kv) { return kv.first == name; })) {
        throw input::UsageError(std::string("surface_classify: ") + name + " given both as a keyword and as a column");
      }
      geometry.emplace_back(name, found->second);
      load.erase(found);
    }
  }
  if (geometry.empty()) {
    TextureAnswers a;
    {
      py::gil_scoped_release release;  // (the curve, and the points' reading)
      a = classify_texture(texture, load);
    }
    const auto L = static_cast<py::ssize_t>(a.levels);
    const auto n = static_cast<py::ssize_t>(a.levels == 0 ? 0 : a.t_star.size() / a.levels);
    py::array_t<double> t_star({n, L});
    py::array_t<std::int8_t> regime({n, L});
    std::copy(a.t_star.begin(), a.t_star.end(), t_star.mutable_data());
    std::copy(a.regime.begin(), a.regime.end(), regime.mutable_data());
    py::list X_star, resolved;
    for (std::size_t k = 0; k < a.levels; ++k) {
      X_star.append(a.X_star[k]);
      resolved.append(a.resolved[k] != 0);
    }
    py::dict out;
    out["t_star"] = t_star;
    out["regime"] = regime;
    out["X_star"] = X_star;
    out["resolved"] = resolved;
    out["time_unit"] = a.time_unit;
    out["grid"] = py::make_tuple(a.grid[0], a.grid[1]);
    out["caps"] = a.caps;
    return out;
  }
  const auto n = static_cast<std::size_t>(geometry.front().second.size());
  for (const auto& [name, column] : geometry) {
    if (static_cast<std::size_t>(column.size()) != n) {
      throw std::invalid_argument("surface_classify: the arrays must have the same size (broadcast first)");
    }
  }
  if (n == 0) {
    throw input::UsageError("surface_classify: no points, so the geometry's columns (" + geometry.front().first +
                            ", ...) name no texture to read; give at least one point");
  }
  // The points of each distinct geometry, in the points' order.
  std::map<std::vector<double>, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<double> key;
    for (const auto& [name, column] : geometry) key.push_back(column.data()[i]);
    groups[key].push_back(i);
  }
  py::dict out;
  std::size_t L = 0;
  std::vector<double> t_star, X_star;
  std::vector<std::int8_t> regime;
  std::vector<char> resolved;
  std::vector<int> grid(2 * n);
  for (const auto& [values, points] : groups) {
    input::Keywords keywords = texture;
    for (std::size_t q = 0; q < geometry.size(); ++q) keywords.emplace_back(geometry[q].first, input::json_number(values[q]));
    // The group's load columns, copied in its points' order.
    Columns subset;
    for (const auto& [name, column] : load) {
      Column part(static_cast<py::ssize_t>(points.size()));
      double* to = part.mutable_data();
      for (std::size_t k = 0; k < points.size(); ++k) to[k] = column.data()[points[k]];
      subset.emplace(name, std::move(part));
    }
    TextureAnswers a;
    {
      py::gil_scoped_release release;
      a = classify_texture(keywords, subset);
    }
    if (L == 0) {
      L = a.levels;
      t_star.resize(n * L);
      regime.resize(n * L);
      X_star.resize(n * L);
      resolved.resize(n * L);
      out["time_unit"] = a.time_unit;
      out["caps"] = a.caps;
    } else if (a.levels != L) {
      throw input::UsageError("surface_classify: the geometries have " + std::to_string(L) + " and " +
                              std::to_string(a.levels) + " levels; one call takes textures of as many levels");
    }
    for (std::size_t k = 0; k < points.size(); ++k) {
      const std::size_t i = points[k];
      for (std::size_t level = 0; level < L; ++level) {
        t_star[i * L + level] = a.t_star[k * L + level];
        regime[i * L + level] = a.regime[k * L + level];
        X_star[i * L + level] = a.X_star[level];
        resolved[i * L + level] = a.resolved[level];
      }
      grid[2 * i] = a.grid[0];
      grid[2 * i + 1] = a.grid[1];
    }
  }
  const auto N = static_cast<py::ssize_t>(n), levels = static_cast<py::ssize_t>(L);
  py::array_t<double> t_out({N, levels}), X_out({N, levels});
  py::array_t<std::int8_t> regime_out({N, levels});
  py::array_t<bool> resolved_out({N, levels});
  py::array_t<int> grid_out({N, py::ssize_t{2}});
  std::copy(t_star.begin(), t_star.end(), t_out.mutable_data());
  std::copy(X_star.begin(), X_star.end(), X_out.mutable_data());
  std::copy(regime.begin(), regime.end(), regime_out.mutable_data());
  std::transform(resolved.begin(), resolved.end(), resolved_out.mutable_data(), [](char c) { return c != 0; });
  std::copy(grid.begin(), grid.end(), grid_out.mutable_data());
  out["t_star"] = t_out;
  out["regime"] = regime_out;
  out["X_star"] = X_out;
  out["resolved"] = resolved_out;
  out["grid"] = grid_out;
  return out;
}

PYBIND11_MODULE(_core, m) {
  m.doc() = "punchsweep's engine (the compiled part of the package punchsweep; use the package's functions)";
  // The refined model's tables from the same cache as the command line's ($PUNCHSWEEP_CACHE,
  // $XDG_CACHE_HOME/punchsweep, ~/.cache/punchsweep; off turns it off).
  engine::use_table_cache();
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const input::UsageError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  m.def("point", &point_command, py::arg("keywords"),
        "punchsweep point of (option name, value text) pairs, evaluated in-process: a dict of its JSON keys");
  m.def("reference", &reference_command, py::arg("keywords"),
        "punchsweep reference of (option name, value text) pairs, solved in-process: a dict of its JSON keys");
  m.def("fit", &fit_command, py::arg("keywords"),
        "punchsweep fit of (option name, value text) pairs: the fit's JSON, report and material text");
  m.def(
      "design", [](const input::Keywords& keywords) { return report::design_json(engine::design(keywords)); },
      py::arg("keywords"), "punchsweep design of (option name, value text) pairs (require may repeat): its JSON text");
  m.def("surface_map", &engine::surface_map_file, py::arg("keywords"),
        "punchsweep surface-map of (option name, value text) pairs on this process alone: writes the map to the "
        "keyword output and returns its path");
  m.def("surface", &report::surface_json, py::arg("keywords"),
        "punchsweep surface of (option name, value text) pairs, in-process: its JSON text");
  m.def("surface_classify", &surface_classify, py::arg("texture"), py::arg("columns"),
        "each level's regime and t* of a texture (surface's keywords without the load's) at points given as "
        "equal-sized 1-D arrays by coordinate name (pbar, the law's parameters, ramp_time: point_axes without the "
        "texture's; and l, dh, dh2, s of the texture, one curve per distinct geometry)");
  m.def("classify", &classify, py::arg("columns"), py::arg("C"), py::arg("localization"), py::arg("material"),
        py::arg("quantities"),
        "the map's per-point quantities (those named in quantities; all where it is empty) of points given as "
        "equal-sized 1-D arrays by coordinate name (point_axes: l, dh, the law's parameters, pbar, s, ramp_time "
        "for a ramp; a law's parameter left out at its default where it has one; the GIL released)");
  m.def("regime_codes", &regime_codes, "the map's regime codes and their names");
  m.def("has_unit", &input::has_unit, py::arg("text"),
        "whether TEXT carries a unit (2kPa yes, 0.5 and 1e-3 no): the engine's rule for a physical value");
  m.def("scaled", &scaled_value, py::arg("text"), py::arg("parameter"), py::arg("material"), py::arg("R"),
        "the value of parameter NAME given as TEXT (a bare number in its scale, or a number with a unit) in "
        "its scale, with the scales of the material file (or '') and R (or ''): the command line's rule");
  m.attr("default_localization") = std::string(model::kDefaultLocalization);
  py::class_<MaterialHandle>(m, "MaterialFile", "a material file as the engine reads it (use punchsweep.Material)")
      .def("info", &MaterialHandle::info)
      .def("evaluate", &MaterialHandle::evaluate, py::arg("t"), py::arg("temperature"), py::arg("relaxation"))
      .def("log10_shift", &MaterialHandle::log10_shift, py::arg("temperature"));
  m.def(
      "material",
      [](const std::string& path) { return MaterialHandle{read_material(path)}; },
      py::arg("path"), "reads a material file (ValueError with the engine's message)");
}
