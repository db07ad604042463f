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
#include <bit>
#include <cmath>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <memory>
#include <numeric>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "app/command_options.hpp"
#include "app/point_command.hpp"
#include "app/point_output.hpp"
#include "app/reference_command.hpp"
#include "app/table_cache.hpp"
#include "app/usage_error.hpp"
#include "map/quantities.hpp"
#include "model/contact_problem.hpp"
#include "model/creep_laws.hpp"
#include "model/creep_weighted_load.hpp"
#include "model/parameters.hpp"
#include "model/point_evaluation.hpp"
#include "model/regime.hpp"
#include "model/stop_request.hpp"
#include "model/validity.hpp"

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
/// writer (app::visit_point): flags as names, valid as a bool, reals as floats (None where
/// the JSON has null), and the series as arrays (NaN where the JSON has null).
struct DictFields final : app::PointFields {
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
  app::visit_point(r, time_unit, fields);
  fields.out["series"] = fields.columns;
  return fields.out;
}

py::dict point_command(const std::vector<std::string>& args) {
  const app::PointRun run = app::evaluate_point_command(args);
  py::dict out = point_dict(run.result, run.inputs.time_unit);
  out["localization"] = run.inputs.problem.localization.spelling();
  out["time_unit"] = run.inputs.time_unit;
  return out;
}

/// `punchsweep reference --format json`'s keys, with the model's point keys it has.
py::dict reference_command(const std::vector<std::string>& args) {
  // Ctrl-C between the BEM's time steps; the KeyboardInterrupt it sets is raised below.
  CtrlC ctrl_c;
  const model::StopRequest interrupted([&ctrl_c] { return ctrl_c.pressed(); });
  std::optional<app::ReferenceRun> solved;
  {
    py::gil_scoped_release release;
    try {
      solved.emplace(app::evaluate_reference_command(args, interrupted));
    } catch (const model::Stopped&) {
    }
  }
  if (!solved) throw py::error_already_set();
  const app::ReferenceRun& run = *solved;
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
  std::string text = app::json_number(v);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

/// The command line's message for a value of `p` outside its range, else empty.
std::string check(const model::Parameter& p, double value) {
  if (p.admits(value)) return {};
  return app::out_of_range(p, value_text(value, p.integer));
}

/// The regime, t*, h(0), h(inf) and validity of n points of the standard linear solid (the
/// map's codes and units), each a pure function of its point, with the parts that depend
/// on fewer coordinates computed once per distinct value (as a sweep's tile does): the
/// touchdown and the guide or branch per (l, s, dh), the single-level state per (l, s, X).
py::dict classify(py::array_t<double, py::array::c_style | py::array::forcecast> l,
                  py::array_t<double, py::array::c_style | py::array::forcecast> dh,
                  py::array_t<double, py::array::c_style | py::array::forcecast> T,
                  py::array_t<double, py::array::c_style | py::array::forcecast> pbar,
                  py::array_t<double, py::array::c_style | py::array::forcecast> s, double C,
                  const std::string& localization, const std::string& material_file) {
  const py::ssize_t n = l.size();
  for (const auto* a : {&dh, &T, &pbar, &s}) {
    if (a->size() != n) throw std::invalid_argument("classify: the arrays must have the same size (broadcast first)");
  }
  // The creep law: the standard linear solid at T, or a material file's law at its one
  // parameter (the temperature, where it has a shift; none otherwise: T is then not read).
  std::shared_ptr<const model::Material> material;
  if (!material_file.empty()) {
    if (material_file.find('\0') != std::string::npos) throw app::UsageError("--material: the file name has a NUL byte");
    material = app::read_material_file(material_file);
  }
  model::ContactProblem base;
  try {
    base.localization = model::parse_localization(localization);
  } catch (const std::invalid_argument& e) {
    throw app::UsageError(std::string("--localization: ") + e.what());  // as read_localization says it
  }
  const model::CreepLawSpec law = material ? material->spec() : model::creep_laws().front();
  const bool law_has_value = !law.parameters.empty();
  if (const std::string e = check(*model::find_parameter(model::kShapeConstant), C); !e.empty()) {
    throw app::UsageError(e);
  }
  // The first value outside its range, axis by axis in the command line's order.
  const std::pair<const model::Parameter*, const double*> axes[] = {
      {model::find_parameter(model::kPitch), l.data()},
      {model::find_parameter(model::kHeightDifference), dh.data()},
      {law_has_value ? &law.parameters.front() : nullptr, T.data()},
      {model::find_parameter(model::kPressure), pbar.data()},
      {model::find_parameter(model::kExponent), s.data()}};
  for (const auto& [parameter, values] : axes) {
    if (parameter == nullptr) continue;
    for (py::ssize_t i = 0; i < n; ++i) {
      if (const std::string e = check(*parameter, values[i]); !e.empty()) throw app::UsageError(e);
    }
  }
  const double* L = l.data();
  const double* DH = dh.data();
  const double* TT = T.data();
  const double* P = pbar.data();
  const double* S = s.data();

  py::array_t<std::int8_t> regime(n);
  py::array_t<bool> valid(n);
  py::array_t<double> t_star(n), h_0(n), h_inf(n);
  std::int8_t* R = regime.mutable_data();
  bool* V = valid.mutable_data();
  double* TS = t_star.mutable_data();
  double* H0 = h_0.mutable_data();
  double* HI = h_inf.mutable_data();
  {
    py::gil_scoped_release release;
    // The points in order of (s, l, dh), each group of equal (s, l, dh) sharing its touchdown
    // and guide or branch: no table of them to look up, so scattered points (every group of
    // one) cost no more than their own work (issue 23: 6.1e4 points/s with a hash table per
    // part, 200,000 scattered points under the periodic model).
    struct Entry {
      double s, l, dh;
      py::ssize_t i;
    };
    std::vector<Entry> entries(static_cast<std::size_t>(n));
    for (py::ssize_t i = 0; i < n; ++i) entries[static_cast<std::size_t>(i)] = {S[i], L[i], DH[i], i};
    // Stable: within a group the points keep their order (a grid's then runs over its later axes).
    std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
      return std::tie(a.s, a.l, a.dh) < std::tie(b.s, b.l, b.dh);
    });
    std::vector<py::ssize_t> order(static_cast<std::size_t>(n));
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = entries[k].i;
    std::vector<Entry>().swap(entries);
    // The single-level state depends on (l, s) and X alone: h(0) at X(0) = pbar J(0) is
    // shared across T and dh, h(inf) at X(inf) = pbar J(inf) across dh. Kept per (s, l)
    // group, and only for groups of more than one dh (a grid's), where it is reused.
    std::unordered_map<double, model::SingleLevelState> single_cache;  // X, within one (s, l)
    // The creep laws of the last values met: a grid's points come in runs of one T (its
    // pressures), so the last one is tried first; scattered T miss and make their own.
    constexpr std::size_t kLawCache = 16;
    std::vector<std::pair<double, std::unique_ptr<model::CreepLaw>>> laws;
    std::size_t next_law = 0, last_law = 0;
    const auto same = [](double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); };
    const auto law_at = [&](double value) -> const model::CreepLaw& {
      if (last_law < laws.size() && same(laws[last_law].first, value)) return *laws[last_law].second;
      for (std::size_t k = 0; k < laws.size(); ++k) {
        if (same(laws[k].first, value)) {
          last_law = k;
          return *laws[k].second;
        }
      }
      auto made = model::make_creep_law(law, std::span<const double>(&value, law_has_value ? 1 : 0));
      if (laws.size() < kLawCache) {
        laws.emplace_back(value, std::move(made));
        last_law = laws.size() - 1;
      } else {
        last_law = next_law++ % kLawCache;
        laws[last_law] = {value, std::move(made)};
      }
      return *laws[last_law].second;
    };
    // The elastic start at t = 0 has modulus 1/J(0) = 1 for every T: per (l, s, dh, pbar),
    // within a dh group. Kept for the paper's model, whose start is a Newton solve (3 us: the
    // cache doubled its rate); the others read their branch, no dearer than the lookup.
    const bool share_elastic = base.localization.is_paper();
    std::unordered_map<double, std::optional<model::ElasticTwoLevel>> elastic_cache;  // pbar, within one dh group
    // Ctrl-C, asked every 16 points (a point takes at most a curve's budgeted build).
    CtrlC ctrl_c;
    std::size_t done = 0;
    for (std::size_t g = 0; g < order.size();) {
      // The (s, l) group [g, sl_end) and, inside it, dh groups.
      const py::ssize_t first = order[g];
      std::size_t sl_end = g;
      while (sl_end < order.size() && S[order[sl_end]] == S[first] && L[order[sl_end]] == L[first]) ++sl_end;
      single_cache.clear();
      const bool reuse_single = DH[order[sl_end - 1]] != DH[first];  // more than one dh
      for (std::size_t d = g; d < sl_end;) {
        const py::ssize_t head = order[d];
        std::size_t dh_end = d;
        while (dh_end < sl_end && DH[order[dh_end]] == DH[head]) ++dh_end;
        model::ContactProblem problem = base;
        problem.l = L[head];
        problem.dh = DH[head];
        problem.shape = model::Shape{static_cast<int>(S[head]), C};
        const model::DhParts parts = model::dh_parts(problem);
        elastic_cache.clear();
        for (std::size_t k = d; k < dh_end; ++k, ++done) {
          const py::ssize_t i = order[k];
          if ((done & 15) == 0 && ctrl_c.pressed()) {
            py::gil_scoped_acquire acquire;  // error_already_set takes the error under the GIL
            throw py::error_already_set();
          }
          problem.pbar0 = P[i];
          const model::CreepLaw& creep = law_at(law_has_value ? TT[i] : 0.0);
          const model::CreepWeightedLoad load(creep, problem.pbar0, problem.loading);
          const auto single_at = [&](double X) {
            if (!reuse_single) return model::single_level_at(problem, X);
            auto [it, fresh] = single_cache.try_emplace(X);
            if (fresh) it->second = model::single_level_at(problem, X);
            return it->second;
          };
          const model::SingleLevelState end = single_at(load.final());
          const model::SingleLevelEnds ends{single_at(load.initial()).h, end.h, end.a1};
          std::optional<model::ElasticTwoLevel>* elastic = share_elastic ? &elastic_cache[P[i]] : nullptr;
          const model::PointSummary summary = model::summarize_point(problem, creep, parts, ends, elastic);
          R[i] = map::quantity_access::regime(summary);
          V[i] = summary.valid();
          TS[i] = map::quantity_access::t_star(summary);
          H0[i] = summary.h_0;
          HI[i] = summary.h_inf;
        }
        d = dh_end;
      }
      g = sl_end;
    }
  }
  py::dict out;
  out["regime"] = regime;
  out["t_star"] = t_star;
  out["h_0"] = h_0;
  out["h_inf"] = h_inf;
  out["valid"] = valid;
  out["time_unit"] = material ? material->time_unit() : std::string("T_eps");
  return out;
}

/// The map's regime codes and names (model::Regime), for decoding classify's codes.
py::dict regime_codes() {
  py::dict out;
  for (const model::Regime r : {model::Regime::immediate, model::Regime::delayed, model::Regime::never}) {
    out[py::int_(static_cast<int>(r))] = std::string(model::regime_name(r));
  }
  return out;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "punchsweep's engine (the compiled part of the package punchsweep; use the package's functions)";
  // The refined model's tables from the same cache as the command line's ($PUNCHSWEEP_CACHE,
  // $XDG_CACHE_HOME/punchsweep, ~/.cache/punchsweep; off turns it off).
  app::use_table_cache();
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const app::UsageError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  m.def("point", &point_command, py::arg("args"),
        "punchsweep point ARGS, evaluated in-process: a dict of its JSON keys");
  m.def("reference", &reference_command, py::arg("args"),
        "punchsweep reference ARGS, solved in-process: a dict of its JSON keys");
  m.def("classify", &classify, py::arg("l"), py::arg("dh"), py::arg("T"), py::arg("pbar"), py::arg("s"),
        py::arg("C"), py::arg("localization"), py::arg("material"),
        "regime, t_star, h_0, h_inf, valid of equal-sized 1-D arrays of points (the GIL released)");
  m.def("regime_codes", &regime_codes, "the map's regime codes and their names");
}
