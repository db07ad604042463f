#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "input/material_file.hpp"
#include "model/laws/creep_laws.hpp"
#include "model/problem/load_shape.hpp"
#include "model/laws/material.hpp"
#include "model/point/point_evaluation.hpp"
#include "sweep/batch_evaluator.hpp"
#include "sweep/tile_evaluator.hpp"
#include "map/quantities.hpp"
#include "model/point/point_axes.hpp"

using namespace punchsweep;
using sweep::BatchEvaluator;

namespace {

bool bits_equal(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Every field a map or classify stores, compared bit for bit.
void expect_same(const model::PointSummary& a, const model::PointSummary& b, const std::string& where) {
  EXPECT_EQ(a.regime, b.regime) << where;
  EXPECT_EQ(a.validity, b.validity) << where;
  EXPECT_EQ(a.t_star.has_value(), b.t_star.has_value()) << where;
  if (a.t_star && b.t_star) {
    EXPECT_TRUE(bits_equal(*a.t_star, *b.t_star)) << where;
  }
  for (const auto& [x, y] : {std::pair{a.h_0, b.h_0}, {a.h_inf, b.h_inf}, {a.a1_inf, b.a1_inf}, {a.a2_inf, b.a2_inf},
                             {a.area_fraction_inf, b.area_fraction_inf}, {a.start.a1, b.start.a1},
                             {a.start.a2, b.start.a2}, {a.start.Q1, b.start.Q1}, {a.start.Q2, b.start.Q2},
                             {a.invalid_at, b.invalid_at}}) {
    EXPECT_TRUE(bits_equal(x, y)) << where << ": " << x << " against " << y;
  }
}

/// A creep law under test: the registry's (the standard linear solid) or a shipped material's.
struct Law {
  std::string name;
  model::CreepLawSpec spec;
  std::vector<std::vector<double>> values;  ///< per parameter, the values to draw from
  double ramp = 1.0;                        ///< a ramp time of the law's time scale
};

std::vector<model::Material>& materials() {
  static std::vector<model::Material> kept;
  return kept;
}

/// Every law the engine knows: the registry's and each shipped material (materials/*.ini:
/// a Prony series with a WLF shift, a Kelvin series, a power law ...), so that a law added
/// to either is covered here.
std::vector<Law> every_law() {
  std::vector<Law> laws;
  for (const model::CreepLawSpec& spec : model::creep_laws()) {
    Law law{std::string(spec.name), spec, {}, 1.0};
    for (std::size_t p = 0; p < spec.parameters.size(); ++p) law.values.push_back({1.0, 2.5, 6.0});
    laws.push_back(law);
  }
  const std::filesystem::path folder = std::filesystem::path(PUNCHSWEEP_SOURCE_DIR) / "materials";
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() == ".ini") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  materials().reserve(files.size());  // the specs refer to the materials
  for (const std::filesystem::path& file : files) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    const model::Material& m = materials().emplace_back(punchsweep::input::read_material_text(text.str(), file.string()));
    Law law{file.filename().string(), m.spec(), {}, 10.0};
    for (const model::Parameter& p : law.spec.parameters) {
      const double T_ref = std::stod(std::string(p.point_default));
      law.values.push_back({T_ref, T_ref + 5.0, T_ref + 12.0});
    }
    laws.push_back(law);
  }
  return laws;
}

struct Points {
  std::vector<double> l, dh, pbar, s, ramp;
  std::vector<std::vector<double>> law;
  std::optional<model::PointAxes> axes;
  /// The columns in the order of `axes`.
  sweep::PointColumns columns() const {
    sweep::PointColumns c{&*axes, {}};
    for (const model::PointAxis& a : *axes) {
      switch (a.coordinate) {
        case model::Coordinate::pitch: c.columns.emplace_back(l); break;
        case model::Coordinate::exponent: c.columns.emplace_back(s); break;
        case model::Coordinate::height_difference: c.columns.emplace_back(dh); break;
        case model::Coordinate::law: c.columns.emplace_back(law[a.law_index]); break;
        case model::Coordinate::ramp_time: c.columns.emplace_back(ramp); break;
        case model::Coordinate::pressure: c.columns.emplace_back(pbar); break;
      }
    }
    return c;
  }
  std::size_t size() const { return l.size(); }
};

/// n points over a few values of each coordinate (so that parts repeat), in random order.
Points draw(const Law& law, std::size_t n, bool ramp, std::mt19937& rng) {
  const auto pick = [&](const std::vector<double>& v) { return v[rng() % v.size()]; };
  Points p;
  p.axes.emplace(law.spec.parameters, ramp);
  p.law.resize(law.values.size());
  for (std::size_t i = 0; i < n; ++i) {
    p.l.push_back(pick({0.6, 0.75, 1.0}));
    p.dh.push_back(pick({0.0, 0.02, 0.05, 0.09}));
    p.pbar.push_back(pick({0.01, 0.03, 0.06}));
    p.s.push_back(pick({1.0, 2.0, 3.0}));
    for (std::size_t k = 0; k < law.values.size(); ++k) p.law[k].push_back(pick(law.values[k]));
    if (ramp) p.ramp.push_back(pick({0.0, 0.3 * law.ramp, 3.0 * law.ramp}));
  }
  return p;
}

/// What the model says at point i, computing every part itself.
model::PointSummary alone(const Law& law, const Points& p, std::size_t i, model::Localization localization,
                          const model::LoadShape& loading) {
  model::ContactProblem problem;
  problem.l = p.l[i];
  problem.dh = p.dh[i];
  problem.pbar0 = p.pbar[i];
  problem.shape = model::Shape{static_cast<int>(p.s[i]), 0.5};
  problem.localization = localization;
  problem.loading = p.ramp.empty() ? loading : model::LoadShape::ramp(p.ramp[i]);
  std::vector<double> values;
  for (const std::vector<double>& v : p.law) values.push_back(v[i]);
  return model::summarize_point(problem, *model::make_creep_law(law.spec, values));
}

struct Collect final : sweep::BatchSink {
  std::vector<model::PointSummary> out;
  std::size_t offset = 0;
  void take(const sweep::BatchPoint& p) override { out[offset + p.k] = p.summary; }
};

}  // namespace

TEST(BatchEvaluator, every_law_and_model_equals_summarize_point_in_any_order_and_batching) {
  std::mt19937 rng(23);
  const std::vector<Law> laws = every_law();
  ASSERT_GE(laws.size(), 5u);  // the standard linear solid and the shipped materials
  for (const Law& law : laws) {
    for (const char* name : {"paper", "refined"}) {
      const model::Localization localization = model::parse_localization(name);
      for (const bool ramp : {false, true}) {
        const model::LoadShape step;
        const Points p = draw(law, 40, ramp, rng);
        std::vector<model::PointSummary> expected;
        for (std::size_t i = 0; i < p.size(); ++i) expected.push_back(alone(law, p, i, localization, step));
        for (const BatchEvaluator::Memory memory : {BatchEvaluator::Memory::run, BatchEvaluator::Memory::call}) {
          // In random order (runs of one), and sorted by (s, l, dh) in batches of 1 to 50
          // through one evaluator: its caches carry over from batch to batch.
          BatchEvaluator evaluator(law.spec, 0.5, localization, step, memory);
          Collect all;
          all.out.resize(p.size());
          evaluator.summarize(p.columns(), all);
          std::vector<std::size_t> order(p.size());
          std::iota(order.begin(), order.end(), std::size_t{0});
          std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return std::tie(p.s[a], p.l[a], p.dh[a]) < std::tie(p.s[b], p.l[b], p.dh[b]);
          });
          Points sorted;
          sorted.axes = p.axes;
          sorted.law.resize(p.law.size());
          for (const std::size_t i : order) {
            sorted.l.push_back(p.l[i]);
            sorted.dh.push_back(p.dh[i]);
            sorted.pbar.push_back(p.pbar[i]);
            sorted.s.push_back(p.s[i]);
            if (ramp) sorted.ramp.push_back(p.ramp[i]);
            for (std::size_t k = 0; k < p.law.size(); ++k) sorted.law[k].push_back(p.law[k][i]);
          }
          Collect batched;
          batched.out.resize(p.size());
          const sweep::PointColumns columns = sorted.columns();
          for (std::size_t begin = 0; begin < p.size();) {
            const std::size_t count = std::min<std::size_t>(1 + rng() % 50, p.size() - begin);
            sweep::PointColumns part{columns.axes, {}};
            for (const auto column : columns.columns) part.columns.push_back(column.subspan(begin, count));
            batched.offset = begin;
            evaluator.summarize(part, batched);
            begin += count;
          }
          for (std::size_t i = 0; i < p.size(); ++i) {
            const std::string where = law.name + " " + name + (ramp ? " ramp" : " step") + " point ";
            expect_same(all.out[i], expected[i], where + std::to_string(i) + " (random order)");
            expect_same(batched.out[i], expected[order[i]], where + std::to_string(order[i]) + " (sorted, in batches)");
          }
        }
      }
    }
  }
}

TEST(BatchEvaluator, refuses_columns_that_do_not_fit_the_law) {
  const model::CreepLawSpec& sls = model::creep_laws().front();
  BatchEvaluator evaluator(sls, 0.5, model::Localization{});
  const std::vector<double> one{0.75}, two{0.05, 0.06};
  Collect sink;
  sink.out.resize(2);
  const model::PointAxes axes(sls.parameters, false);  // l, dh, T, pbar, s
  ASSERT_EQ(axes.size(), 5u);
  // A column missing, one too many, unequal lengths.
  EXPECT_THROW(evaluator.summarize(sweep::PointColumns{&axes, {one, one, one, one}}, sink), std::invalid_argument);
  EXPECT_THROW(evaluator.summarize(sweep::PointColumns{&axes, {one, one, one, one, one, one}}, sink),
               std::invalid_argument);
  EXPECT_THROW(evaluator.summarize(sweep::PointColumns{&axes, {one, two, one, one, one}}, sink), std::invalid_argument);
  // The axes of a law with other parameters.
  for (const model::CreepLawSpec& other : model::creep_laws()) {
    if (other.parameters.size() == sls.parameters.size() && other.parameters[0].name == sls.parameters[0].name) continue;
    const model::PointAxes others(other.parameters, false);
    const sweep::PointColumns columns{&others, std::vector<std::span<const double>>(others.size(), one)};
    EXPECT_THROW(evaluator.summarize(columns, sink), std::invalid_argument) << other.name;
  }
  const std::vector<double> T{2.5}, pbar{0.03}, s{2.0}, dh{0.05};
  evaluator.summarize(sweep::PointColumns{&axes, {one, dh, T, pbar, s}}, sink);  // fits
  EXPECT_TRUE(std::isfinite(sink.out[0].h_inf));
}

TEST(BatchEvaluator, stops_on_request_between_points) {
  const model::CreepLawSpec& sls = model::creep_laws().front();
  BatchEvaluator evaluator(sls, 0.5, model::Localization{});
  const std::vector<double> l(1000, 0.75), T(1000, 2.5), s(1000, 2.0);
  std::vector<double> dh(1000), pbar(1000, 0.03);
  for (std::size_t i = 0; i < dh.size(); ++i) dh[i] = 0.01 + 1e-4 * static_cast<double>(i);
  Collect sink;
  sink.out.resize(1000);
  int asked = 0;
  const model::StopRequest stop([&] { return ++asked > 3; });
  const model::PointAxes axes(sls.parameters, false);
  EXPECT_THROW(evaluator.summarize(sweep::PointColumns{&axes, {l, dh, T, pbar, s}}, sink, stop), model::Stopped);
  EXPECT_EQ(asked, 4);
}

namespace {

/// The model's summary at `values` (one per coordinate of `axes`), each value put into the
/// point by its parameter's name as the model declares the names (not through
/// model::set_coordinate, which this checks).
model::PointSummary by_hand(const Law& law, const model::PointAxes& axes, const std::vector<double>& values) {
  model::ContactProblem problem;
  problem.localization = model::parse_localization("paper");
  std::vector<double> law_values(law.spec.parameters.size());
  for (std::size_t j = 0; j < axes.size(); ++j) {
    const std::string_view name = axes[j].parameter->name;
    const double v = values[j];
    if (name == model::kPitch) {
      problem.l = v;
    } else if (name == model::kHeightDifference) {
      problem.dh = v;
    } else if (name == model::kPressure) {
      problem.pbar0 = v;
    } else if (name == model::kExponent) {
      problem.shape = model::Shape{static_cast<int>(v), 0.5};
    } else if (name == model::ramp_time_parameter().name) {
      problem.loading = model::LoadShape::ramp(v);
    } else {
      std::size_t p = 0;
      while (p < law_values.size() && law.spec.parameters[p].name != name) ++p;
      if (p == law_values.size()) ADD_FAILURE() << name << " is no coordinate of " << law.name;
      if (p < law_values.size()) law_values[p] = v;
    }
  }
  return model::summarize_point(problem, *model::make_creep_law(law.spec, law_values));
}

}  // namespace

// Every coordinate of every law's points (model::PointAxes), swept alone over three values,
// reaches the point alike in a sweep's tile (sweep::TileEvaluator, the grid's axes named as
// the coordinates), in a batch (Python's classify's path), through PointAxes::set (the point
// commands' and the reference points' path) and put in by hand; and each one changes the
// answer (none is dropped on the way).
TEST(PointAxes, every_coordinate_reaches_the_point_alike_in_a_tile_a_batch_and_by_hand) {
  for (const Law& law : every_law()) {
    for (const bool ramp : {false, true}) {
      const model::PointAxes axes(law.spec.parameters, ramp);
      ASSERT_EQ(axes.size(), 4 + law.spec.parameters.size() + (ramp ? 1 : 0)) << law.name;
      // A base point between its h(0) and h(inf) (near h(inf)), so that it is delayed and every
      // coordinate moves t* (a temperature shift moves nothing else).
      std::vector<std::vector<double>> choices(axes.size());
      for (std::size_t j = 0; j < axes.size(); ++j) {
        switch (axes[j].coordinate) {
          case model::Coordinate::pitch: choices[j] = {0.75, 0.6, 1.0}; break;
          case model::Coordinate::exponent: choices[j] = {2.0, 1.0, 3.0}; break;
          case model::Coordinate::height_difference: choices[j] = {1.0, 1.0, 1.0}; break;  // past h(inf)
          case model::Coordinate::law: {  // the middle first: the standard linear solid creeps at T > 1
            const std::vector<double>& v = law.values[axes[j].law_index];
            choices[j] = {v[1], v[0], v[2]};
            break;
          }
          case model::Coordinate::ramp_time: choices[j] = {0.0, 0.0, 0.0}; break;  // below
          case model::Coordinate::pressure: choices[j] = {0.03, 0.01, 0.06}; break;
        }
      }
      std::vector<double> base(axes.size());
      for (std::size_t j = 0; j < axes.size(); ++j) base[j] = choices[j][0];
      const std::size_t dh = axes.find(model::Coordinate::height_difference);
      std::vector<double> step = base;  // h(0) of the step: a ramp's is 0
      if (ramp) step[axes.find(model::Coordinate::ramp_time)] = 0.0;
      const model::PointSummary flat = by_hand(law, axes, step);
      const double middle = flat.h_0 + 0.9 * (flat.h_inf - flat.h_0);  // late: after a ramp
      choices[dh] = {middle, 0.97 * middle, 1.03 * middle};
      base[dh] = middle;
      if (ramp) {  // ramps shorter than the step's t*: the touch comes after the rise
        step[dh] = middle;
        const double t_star = by_hand(law, axes, step).t_star.value_or(0.0);
        const std::size_t r = axes.find(model::Coordinate::ramp_time);
        choices[r] = {0.3 * t_star, 0.0, 0.6 * t_star};
        base[r] = choices[r][0];
      }
      ASSERT_EQ(by_hand(law, axes, base).regime, model::Regime::delayed) << law.name << (ramp ? " ramp" : " step");

      for (std::size_t j = 0; j < axes.size(); ++j) {
        const std::string where = law.name + (ramp ? " ramp, " : " step, ") + std::string(axes[j].parameter->name);
        map::Grid grid;
        std::vector<std::vector<double>> points(3, base);
        for (std::size_t a = 0; a < axes.size(); ++a) {
          std::vector<double> values{base[a]};
          if (a == j) values = choices[j];
          std::sort(values.begin(), values.end());
          grid.axes.push_back(map::Axis{std::string(axes[a].parameter->name), values, "", false, {}});
        }
        for (std::size_t k = 0; k < 3; ++k) points[k][j] = grid.axes[j].values[k];
        std::vector<model::PointSummary> expected;
        for (const std::vector<double>& p : points) expected.push_back(by_hand(law, axes, p));

        const sweep::TileEvaluator tile(grid, law.spec, 0.5, {}, map::Quantities::regime, {}, {},
                                        model::parse_localization("paper"));
        map::TileData data;
        tile.evaluate(map::TileBox{map::Index(axes.size(), 0), grid.shape()}, &data);
        BatchEvaluator batch(law.spec, 0.5, model::parse_localization("paper"), {}, BatchEvaluator::Memory::call);
        std::vector<std::vector<double>> columns(axes.size());
        for (const std::vector<double>& p : points) {
          for (std::size_t a = 0; a < axes.size(); ++a) columns[a].push_back(p[a]);
        }
        sweep::PointColumns batch_columns{&axes, {}};
        for (const std::vector<double>& c : columns) batch_columns.columns.emplace_back(c);
        Collect batched;
        batched.out.resize(3);
        batch.summarize(batch_columns, batched);

        for (std::size_t k = 0; k < 3; ++k) {
          const model::PointSummary& e = expected[k];
          EXPECT_EQ(data.codes[map::quantity("regime")][k], static_cast<std::int8_t>(e.regime)) << where;
          EXPECT_TRUE(bits_equal(data.reals[map::quantity("t_star")][k], e.t_star.value_or(std::nan(""))) ||
                      !e.t_star)
              << where;
          EXPECT_TRUE(bits_equal(data.reals[map::quantity("h_0")][k], e.h_0)) << where;
          EXPECT_TRUE(bits_equal(data.reals[map::quantity("h_inf")][k], e.h_inf)) << where;
          expect_same(batched.out[k], e, where + " (batch)");
          model::PointValues point;  // as the point commands and the reference's points
          point.problem.localization = model::parse_localization("paper");
          axes.set(points[k], &point);
          expect_same(model::summarize_point(point.problem, *model::make_creep_law(law.spec, point.law)), e,
                      where + " (PointAxes::set)");
        }
        const auto differ = [](const model::PointSummary& a, const model::PointSummary& b) {
          return a.regime != b.regime || a.t_star != b.t_star || a.h_0 != b.h_0 || a.h_inf != b.h_inf;
        };
        EXPECT_TRUE(differ(expected[0], expected[1]) && differ(expected[1], expected[2])) << where << " changes nothing";
      }
    }
  }
}
