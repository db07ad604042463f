#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "model/point_evaluation.hpp"
#include "model/standard_linear_solid.hpp"
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
