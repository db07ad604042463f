#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <optional>

#include "model/point/point_evaluation.hpp"
#include "model/laws/standard_linear_solid.hpp"
#include "reference/reference_point.hpp"
#include "sweep/tile_evaluator.hpp"
#include "map/test_grid.hpp"
#include "map/tiling.hpp"
#include "model/laws/creep_laws.hpp"

using namespace punchsweep;
using namespace punchsweep::sweep;
using namespace punchsweep::map::testing;
using punchsweep::map::Quantities;
using punchsweep::map::Tiling;
using punchsweep::map::TileBox;

namespace {
const punchsweep::model::CreepLawSpec& sls() { return punchsweep::model::creep_laws().front(); }
}  // namespace

namespace {

map::Grid small_grid() {
  map::Grid g = sls_grid();
  g.axes[kL].values = {0.5, 0.75, 1.0};
  g.axes[kDh].values = {0.0, 0.03, 0.05, 0.075, 0.1};
  g.axes[kT].values = {1.0, 2.5, 6.0};
  g.axes[kPbar].values = {0.01, 0.025, 0.06};
  g.axes[kS].values = {1, 2, 3};
  return g;
}

bool bits_equal(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST(TileEvaluator, every_value_equals_evaluate_point_bit_for_bit) {
  const map::Grid g = small_grid();
  const std::vector<double> times{0.0, 1.0, 5.0};
  const TileEvaluator evaluator(g, sls(), 0.5, times, Quantities::full);
  const Tiling tiling(g.shape(), 50);
  map::TileData data;
  for (std::size_t k = 0; k < tiling.tiles(); ++k) {
    const TileBox b = tiling.box(k);
    evaluator.evaluate(b, &data);
    std::size_t i = 0;
    for (std::size_t il = 0; il < b.count[0]; ++il)
      for (std::size_t idh = 0; idh < b.count[1]; ++idh)
        for (std::size_t iT = 0; iT < b.count[2]; ++iT)
          for (std::size_t ip = 0; ip < b.count[3]; ++ip)
            for (std::size_t is = 0; is < b.count[4]; ++is, ++i) {
              const model::ContactProblem p{g.axes[0].values[b.start[0] + il], g.axes[1].values[b.start[1] + idh],
                                            g.axes[3].values[b.start[3] + ip],
                                            model::Shape{static_cast<int>(g.axes[4].values[b.start[4] + is]), 0.5}};
              const model::StandardLinearSolid creep(g.axes[2].values[b.start[2] + iT]);
              const model::PointResult r = model::evaluate_point(p, creep, {times, {}});
              ASSERT_EQ(flag(data, "regime")[i], static_cast<std::int8_t>(r.regime));
              ASSERT_EQ(flag(data, "valid")[i], static_cast<std::int8_t>(r.validity));
              ASSERT_TRUE(bits_equal(real(data, "t_star")[i], r.t_star.value_or(std::nan(""))) || r.regime == model::Regime::never);
              ASSERT_TRUE(bits_equal(real(data, "h_0")[i], r.h_0));
              ASSERT_TRUE(bits_equal(real(data, "h_inf")[i], r.h_inf));
              ASSERT_TRUE(bits_equal(real(data, "a1_inf")[i], r.a1_inf));
              ASSERT_TRUE(bits_equal(real(data, "a2_inf")[i], r.a2_inf));
              for (std::size_t it = 0; it < times.size(); ++it) {
                ASSERT_TRUE(bits_equal(real(data, "a2")[i * times.size() + it], r.series[it].a2));
                ASSERT_TRUE(bits_equal(real(data, "P1")[i * times.size() + it], r.series[it].P1));
              }
            }
  }
}

TEST(TileEvaluator, regime_quantities_equal_the_full_ones_and_leave_no_series) {
  const map::Grid g = small_grid();
  const Tiling tiling(g.shape(), 1000000);  // one tile
  map::TileData full;
  map::TileData regime;
  TileEvaluator(g, sls(), 0.5, {0.0, 2.0}, Quantities::full).evaluate(tiling.box(0), &full);
  TileEvaluator(g, sls(), 0.5, {0.0, 2.0}, Quantities::regime).evaluate(tiling.box(0), &regime);
  EXPECT_TRUE(real(regime, "a1").empty() && real(regime, "P2").empty());
  EXPECT_EQ(flag(regime, "regime"), flag(full, "regime"));
  for (std::size_t i = 0; i < flag(full, "regime").size(); ++i) {
    ASSERT_TRUE(bits_equal(real(regime, "a1_inf")[i], real(full, "a1_inf")[i]));
    ASSERT_TRUE(bits_equal(real(regime, "h_inf")[i], real(full, "h_inf")[i]));
  }
}

namespace {

map::Grid reference_grid() {
  map::Grid g = sls_grid();
  g.axes[kL].values = {0.75, 1.0};
  g.axes[kDh].values = {0.02, 0.06};
  g.axes[kT].values = {2.5, 6.0};
  g.axes[kPbar].values = {0.025, 0.06};
  g.axes[kS].values = {1, 2};
  return g;
}

ReferenceConfig small_reference(std::optional<std::uint64_t> sample) {
  ReferenceConfig reference;
  reference.method = ReferenceMethod::bem;
  reference.grid = 16;
  reference.sample = sample;
  reference.seed = 3;
  return reference;
}

/// Every tile of `tiling` evaluated and put back together, row-major over the grid.
map::TileData whole_grid(const TileEvaluator& evaluator, const map::Grid& g, const Tiling& tiling, std::size_t nt) {
  const auto n = g.shape();
  map::TileData all;
  all.resize(g.points(), nt, Quantities::regime, true);
  map::TileData data;
  for (std::size_t k = 0; k < tiling.tiles(); ++k) {
    const TileBox b = tiling.box(k);
    evaluator.evaluate(b, &data);
    for (std::size_t i = 0; i < b.points(); ++i) {
      std::size_t rest = i;
      std::size_t gi = 0;
      map::Index at(kAxes);
      for (std::size_t a = kAxes; a-- > 0; rest /= b.count[a]) at[a] = b.start[a] + rest % b.count[a];
      for (std::size_t a = 0; a < kAxes; ++a) gi = gi * n[a] + at[a];
      flag(all, "regime")[gi] = flag(data, "regime")[i];
      flag(all, "bem_regime")[gi] = flag(data, "bem_regime")[i];
      real(all, "bem_t_star")[gi] = real(data, "bem_t_star")[i];
      for (std::size_t it = 0; it < nt; ++it) real(all, "bem_P2")[gi * nt + it] = real(data, "bem_P2")[i * nt + it];
    }
  }
  return all;
}

}  // namespace

TEST(TileEvaluator, reference_values_equal_evaluate_reference_point_at_sampled_points_only) {
  const map::Grid g = reference_grid();
  const std::vector<double> times{0.0, 1.0, 5.0};
  const std::size_t nt = times.size();
  const TileEvaluator evaluator(g, sls(), 0.5, times, Quantities::regime, small_reference(5));
  const TileEvaluator model_only(g, sls(), 0.5, times, Quantities::regime);
  ASSERT_TRUE(evaluator.reference_sample().has_value());
  EXPECT_FALSE(model_only.reference_sample().has_value());
  const Tiling tiling(g.shape(), 1000);  // one tile
  map::TileData data;
  map::TileData model;
  evaluator.evaluate(tiling.box(0), &data);
  model_only.evaluate(tiling.box(0), &model);
  EXPECT_TRUE(flag(model, "bem_regime").empty() && real(model, "bem_a1").empty());
  EXPECT_EQ(flag(data, "regime"), flag(model, "regime"));  // the reference leaves the model's values alone
  for (std::size_t i = 0; i < real(model, "t_star").size(); ++i) ASSERT_TRUE(bits_equal(real(data, "t_star")[i], real(model, "t_star")[i]));
  // The same evaluator with its reference skipped gives the model-only tile exactly.
  map::TileData skipped;
  evaluator.evaluate(tiling.box(0), &skipped, TileEvaluator::Reference::skipped);
  EXPECT_TRUE(flag(skipped, "bem_regime").empty() && real(skipped, "bem_t_star").empty());
  EXPECT_TRUE(same_bits(skipped, model));

  const ReferenceSample& sample = *evaluator.reference_sample();
  std::size_t i = 0;
  std::size_t sampled = 0;
  for (std::size_t il = 0; il < 2; ++il)
    for (std::size_t idh = 0; idh < 2; ++idh)
      for (std::size_t iT = 0; iT < 2; ++iT)
        for (std::size_t ip = 0; ip < 2; ++ip)
          for (std::size_t is = 0; is < 2; ++is, ++i) {
            if (!sample.contains(i)) {
              ASSERT_EQ(flag(data, "bem_regime")[i], -1) << i;
              ASSERT_TRUE(std::isnan(real(data, "bem_t_star")[i])) << i;
              for (std::size_t it = 0; it < nt; ++it) ASSERT_TRUE(std::isnan(real(data, "bem_a2")[i * nt + it])) << i;
              continue;
            }
            ++sampled;
            const model::ContactProblem p{g.axes[kL].values[il], g.axes[kDh].values[idh],
                                          g.axes[kPbar].values[ip],
                                          model::Shape{static_cast<int>(g.axes[kS].values[is]), 0.5}};
            const model::StandardLinearSolid creep(g.axes[kT].values[iT]);
            reference::ReferenceOptions options;
            options.n = 16;
            options.times = times;
            const reference::ReferenceResult r = reference::evaluate_reference_point(p, creep, options);
            ASSERT_EQ(flag(data, "bem_regime")[i], static_cast<std::int8_t>(r.regime)) << i;
            ASSERT_TRUE(bits_equal(real(data, "bem_t_star")[i], r.t_star.value_or(std::nan("")))) << i;
            for (std::size_t it = 0; it < nt; ++it) {
              ASSERT_TRUE(bits_equal(real(data, "bem_a1")[i * nt + it], r.series[it].a1)) << i;
              ASSERT_TRUE(bits_equal(real(data, "bem_a2")[i * nt + it], r.series[it].a2)) << i;
              ASSERT_TRUE(bits_equal(real(data, "bem_P1")[i * nt + it], r.series[it].P1)) << i;
              ASSERT_TRUE(bits_equal(real(data, "bem_P2")[i * nt + it], r.series[it].P2)) << i;
              ASSERT_TRUE(bits_equal(real(data, "bem_area_fraction")[i * nt + it], r.series[it].area_fraction)) << i;
            }
          }
  EXPECT_EQ(sampled, 5u);
}

TEST(TileEvaluator, reference_values_do_not_depend_on_the_tiling) {
  const map::Grid g = reference_grid();
  const std::vector<double> times{0.0, 2.0};
  const TileEvaluator evaluator(g, sls(), 0.5, times, Quantities::regime, small_reference(6));
  const map::TileData whole = whole_grid(evaluator, g, Tiling(g.shape(), 1000), times.size());
  const map::TileData tiles = whole_grid(evaluator, g, Tiling(g.shape(), 3), times.size());
  EXPECT_EQ(flag(tiles, "bem_regime"), flag(whole, "bem_regime"));
  EXPECT_EQ(std::count_if(flag(whole, "bem_regime").begin(), flag(whole, "bem_regime").end(), [](std::int8_t r) { return r >= 0; }),
            6);
  for (std::size_t i = 0; i < real(whole, "bem_t_star").size(); ++i) {
    ASSERT_TRUE(bits_equal(real(tiles, "bem_t_star")[i], real(whole, "bem_t_star")[i])) << i;
  }
  for (std::size_t i = 0; i < real(whole, "bem_P2").size(); ++i) ASSERT_TRUE(bits_equal(real(tiles, "bem_P2")[i], real(whole, "bem_P2")[i])) << i;
}
