#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <optional>

#include "model/point_evaluation.hpp"
#include "model/standard_linear_solid.hpp"
#include "reference/reference_point.hpp"
#include "sweep/tile_evaluator.hpp"
#include "sweep/tiling.hpp"

using namespace punchsweep;
using namespace punchsweep::sweep;

namespace {

Grid small_grid() {
  Grid g;
  g.axes[kAxisL].values = {0.5, 0.75, 1.0};
  g.axes[kAxisDh].values = {0.0, 0.03, 0.05, 0.075, 0.1};
  g.axes[kAxisT].values = {1.0, 2.5, 6.0};
  g.axes[kAxisPbar].values = {0.01, 0.025, 0.06};
  g.axes[kAxisS].values = {1, 2, 3};
  return g;
}

bool bits_equal(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST(TileEvaluator, every_value_equals_evaluate_point_bit_for_bit) {
  const Grid g = small_grid();
  const std::vector<double> times{0.0, 1.0, 5.0};
  const TileEvaluator evaluator(g, 0.5, times, Quantities::full);
  const Tiling tiling(g.shape(), 50);
  io::TileData data;
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
              ASSERT_EQ(data.regime[i], static_cast<std::int8_t>(r.regime));
              ASSERT_EQ(data.valid[i], static_cast<std::int8_t>(r.validity));
              ASSERT_TRUE(bits_equal(data.t_star[i], r.t_star.value_or(std::nan(""))) || r.regime == model::Regime::never);
              ASSERT_TRUE(bits_equal(data.h_0[i], r.h_0));
              ASSERT_TRUE(bits_equal(data.h_inf[i], r.h_inf));
              ASSERT_TRUE(bits_equal(data.a1_inf[i], r.a1_inf));
              ASSERT_TRUE(bits_equal(data.a2_inf[i], r.a2_inf));
              for (std::size_t it = 0; it < times.size(); ++it) {
                ASSERT_TRUE(bits_equal(data.a2[i * times.size() + it], r.series[it].a2));
                ASSERT_TRUE(bits_equal(data.P1[i * times.size() + it], r.series[it].P1));
              }
            }
  }
}

TEST(TileEvaluator, regime_quantities_equal_the_full_ones_and_leave_no_series) {
  const Grid g = small_grid();
  const Tiling tiling(g.shape(), 1000000);  // one tile
  io::TileData full;
  io::TileData regime;
  TileEvaluator(g, 0.5, {0.0, 2.0}, Quantities::full).evaluate(tiling.box(0), &full);
  TileEvaluator(g, 0.5, {0.0, 2.0}, Quantities::regime).evaluate(tiling.box(0), &regime);
  EXPECT_TRUE(regime.a1.empty() && regime.P2.empty());
  EXPECT_EQ(regime.regime, full.regime);
  for (std::size_t i = 0; i < full.regime.size(); ++i) {
    ASSERT_TRUE(bits_equal(regime.a1_inf[i], full.a1_inf[i]));
    ASSERT_TRUE(bits_equal(regime.h_inf[i], full.h_inf[i]));
  }
}

namespace {

Grid reference_grid() {
  Grid g;
  g.axes[kAxisL].values = {0.75, 1.0};
  g.axes[kAxisDh].values = {0.02, 0.06};
  g.axes[kAxisT].values = {2.5, 6.0};
  g.axes[kAxisPbar].values = {0.025, 0.06};
  g.axes[kAxisS].values = {1, 2};
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
io::TileData whole_grid(const TileEvaluator& evaluator, const Grid& g, const Tiling& tiling, std::size_t nt) {
  const auto n = g.shape();
  io::TileData all;
  all.resize(g.points(), nt, false, true);
  io::TileData data;
  for (std::size_t k = 0; k < tiling.tiles(); ++k) {
    const TileBox b = tiling.box(k);
    evaluator.evaluate(b, &data);
    for (std::size_t i = 0; i < b.points(); ++i) {
      std::size_t rest = i;
      std::size_t gi = 0;
      std::array<std::size_t, kAxes> at{};
      for (std::size_t a = kAxes; a-- > 0; rest /= b.count[a]) at[a] = b.start[a] + rest % b.count[a];
      for (std::size_t a = 0; a < kAxes; ++a) gi = gi * n[a] + at[a];
      all.regime[gi] = data.regime[i];
      all.bem_regime[gi] = data.bem_regime[i];
      all.bem_t_star[gi] = data.bem_t_star[i];
      for (std::size_t it = 0; it < nt; ++it) all.bem_P2[gi * nt + it] = data.bem_P2[i * nt + it];
    }
  }
  return all;
}

}  // namespace

TEST(TileEvaluator, reference_values_equal_evaluate_reference_point_at_sampled_points_only) {
  const Grid g = reference_grid();
  const std::vector<double> times{0.0, 1.0, 5.0};
  const std::size_t nt = times.size();
  const TileEvaluator evaluator(g, 0.5, times, Quantities::regime, small_reference(5));
  const TileEvaluator model_only(g, 0.5, times, Quantities::regime);
  ASSERT_TRUE(evaluator.reference_sample().has_value());
  EXPECT_FALSE(model_only.reference_sample().has_value());
  const Tiling tiling(g.shape(), 1000);  // one tile
  io::TileData data;
  io::TileData model;
  evaluator.evaluate(tiling.box(0), &data);
  model_only.evaluate(tiling.box(0), &model);
  EXPECT_TRUE(model.bem_regime.empty() && model.bem_a1.empty());
  EXPECT_EQ(data.regime, model.regime);  // the reference leaves the model's values alone
  for (std::size_t i = 0; i < model.t_star.size(); ++i) ASSERT_TRUE(bits_equal(data.t_star[i], model.t_star[i]));

  const ReferenceSample& sample = *evaluator.reference_sample();
  std::size_t i = 0;
  std::size_t sampled = 0;
  for (std::size_t il = 0; il < 2; ++il)
    for (std::size_t idh = 0; idh < 2; ++idh)
      for (std::size_t iT = 0; iT < 2; ++iT)
        for (std::size_t ip = 0; ip < 2; ++ip)
          for (std::size_t is = 0; is < 2; ++is, ++i) {
            if (!sample.contains(i)) {
              ASSERT_EQ(data.bem_regime[i], -1) << i;
              ASSERT_TRUE(std::isnan(data.bem_t_star[i])) << i;
              for (std::size_t it = 0; it < nt; ++it) ASSERT_TRUE(std::isnan(data.bem_a2[i * nt + it])) << i;
              continue;
            }
            ++sampled;
            const model::ContactProblem p{g.axes[kAxisL].values[il], g.axes[kAxisDh].values[idh],
                                          g.axes[kAxisPbar].values[ip],
                                          model::Shape{static_cast<int>(g.axes[kAxisS].values[is]), 0.5}};
            const model::StandardLinearSolid creep(g.axes[kAxisT].values[iT]);
            reference::ReferenceOptions options;
            options.n = 16;
            options.times = times;
            const reference::ReferenceResult r = reference::evaluate_reference_point(p, creep, options);
            ASSERT_EQ(data.bem_regime[i], static_cast<std::int8_t>(r.regime)) << i;
            ASSERT_TRUE(bits_equal(data.bem_t_star[i], r.t_star.value_or(std::nan("")))) << i;
            for (std::size_t it = 0; it < nt; ++it) {
              ASSERT_TRUE(bits_equal(data.bem_a1[i * nt + it], r.series[it].a1)) << i;
              ASSERT_TRUE(bits_equal(data.bem_a2[i * nt + it], r.series[it].a2)) << i;
              ASSERT_TRUE(bits_equal(data.bem_P1[i * nt + it], r.series[it].P1)) << i;
              ASSERT_TRUE(bits_equal(data.bem_P2[i * nt + it], r.series[it].P2)) << i;
              ASSERT_TRUE(bits_equal(data.bem_area_fraction[i * nt + it], r.series[it].area_fraction)) << i;
            }
          }
  EXPECT_EQ(sampled, 5u);
}

TEST(TileEvaluator, reference_values_do_not_depend_on_the_tiling) {
  const Grid g = reference_grid();
  const std::vector<double> times{0.0, 2.0};
  const TileEvaluator evaluator(g, 0.5, times, Quantities::regime, small_reference(6));
  const io::TileData whole = whole_grid(evaluator, g, Tiling(g.shape(), 1000), times.size());
  const io::TileData tiles = whole_grid(evaluator, g, Tiling(g.shape(), 3), times.size());
  EXPECT_EQ(tiles.bem_regime, whole.bem_regime);
  EXPECT_EQ(std::count_if(whole.bem_regime.begin(), whole.bem_regime.end(), [](std::int8_t r) { return r >= 0; }),
            6);
  for (std::size_t i = 0; i < whole.bem_t_star.size(); ++i) {
    ASSERT_TRUE(bits_equal(tiles.bem_t_star[i], whole.bem_t_star[i])) << i;
  }
  for (std::size_t i = 0; i < whole.bem_P2.size(); ++i) ASSERT_TRUE(bits_equal(tiles.bem_P2[i], whole.bem_P2[i])) << i;
}
