#include "sweep/tile_evaluator.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "model/point_evaluation.hpp"
#include "model/single_level.hpp"
#include "model/standard_linear_solid.hpp"
#include "sweep/reproducible_fft.hpp"

namespace punchsweep::sweep {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Copies a series of snapshots (the model's or the reference's: each has a1, a2, P1, P2 and
// area_fraction) into the tile's arrays a1, a2, P1, P2, area_fraction at point i.
template <class Snapshots>
void store_series(const Snapshots& series, std::size_t i, const std::array<std::vector<double>*, 5>& arrays) {
  const std::size_t nt = series.size();
  for (std::size_t it = 0; it < nt; ++it) {
    const auto& snap = series[it];
    const double values[5] = {snap.a1, snap.a2, snap.P1, snap.P2, snap.area_fraction};
    for (std::size_t v = 0; v < 5; ++v) (*arrays[v])[i * nt + it] = values[v];
  }
}

// Above this many entries the run-wide caches would cost more memory than they save.
constexpr std::size_t kMaxCacheEntries = std::size_t{1} << 24;

}  // namespace

TileEvaluator::TileEvaluator(const Grid& grid, double C, std::vector<double> times,
                             Quantities quantities, const ReferenceConfig& reference)
    : grid_(grid), C_(C), times_(std::move(times)), quantities_(quantities) {
  if (reference.on()) {
    sample_.emplace(grid.points(), reference.sample, reference.seed);
    reference_options_.n = reference.grid;
    reference_options_.times = times_;
    use_reproducible_fft_plans();
  }
  const auto n = grid.shape();
  const std::size_t ends = n[kAxisL] * n[kAxisS] * n[kAxisT] * n[kAxisPbar];
  const std::size_t touch = n[kAxisL] * n[kAxisS] * n[kAxisDh];
  cache_ = ends <= kMaxCacheEntries && touch <= kMaxCacheEntries;
  if (cache_) {
    ends_.resize(ends);
    touch_.resize(touch);
  }
}

void TileEvaluator::evaluate(const TileBox& box, io::TileData* out) const {
  const bool full = quantities_ == Quantities::full;
  const std::size_t nt = times_.size();
  out->resize(box.points(), nt, full, sample_.has_value());
  const auto& c = box.count;
  const auto value = [&](std::size_t axis, std::size_t i) {
    return grid_.axes[axis].values[box.start[axis] + i];
  };

  std::vector<model::StandardLinearSolid> creep;
  creep.reserve(c[kAxisT]);
  for (std::size_t iT = 0; iT < c[kAxisT]; ++iT) creep.emplace_back(value(kAxisT, iT));
  const model::EvaluationOptions options{times_, {}};

  const auto n = grid_.shape();
  std::vector<model::Touchdown> touch(c[kAxisDh]);
  std::vector<std::shared_ptr<const model::LongTermGuide>> guide(c[kAxisDh]);
  std::vector<Ends> ends(c[kAxisT] * c[kAxisPbar]);
  std::vector<std::optional<model::ElasticTwoLevel>> elastic(c[kAxisDh] * c[kAxisPbar]);

  for (std::size_t il = 0; il < c[kAxisL]; ++il) {
    for (std::size_t is = 0; is < c[kAxisS]; ++is) {
      model::ContactProblem problem;
      problem.l = value(kAxisL, il);
      problem.shape = model::Shape{static_cast<int>(value(kAxisS, is)), C_};
      const model::SingleLevel single(problem.l, problem.shape);
      const std::size_t gl = box.start[kAxisL] + il;
      const std::size_t gs = box.start[kAxisS] + is;
      for (std::size_t idh = 0; idh < c[kAxisDh]; ++idh) {
        Touch scratch;
        Touch& t = cache_ ? touch_[(gl * n[kAxisS] + gs) * n[kAxisDh] + box.start[kAxisDh] + idh] : scratch;
        if (!t.ready) {
          const model::Touchdown computed = model::touchdown(single, value(kAxisDh, idh));
          model::ContactProblem at_dh = problem;
          at_dh.dh = value(kAxisDh, idh);
          t = Touch{computed, std::make_shared<const model::LongTermGuide>(at_dh), true};
        }
        touch[idh] = t.touchdown;
        guide[idh] = t.guide;
      }
      for (std::size_t iT = 0; iT < c[kAxisT]; ++iT) {
        for (std::size_t ip = 0; ip < c[kAxisPbar]; ++ip) {
          Ends& e = ends[iT * c[kAxisPbar] + ip];
          const std::size_t g =
              ((gl * n[kAxisS] + gs) * n[kAxisT] + box.start[kAxisT] + iT) * n[kAxisPbar] + box.start[kAxisPbar] + ip;
          if (cache_ && ends_[g].ready) {
            e = ends_[g];
            continue;
          }
          problem.pbar0 = value(kAxisPbar, ip);
          model::single_level_ends(problem, creep[iT], &e.h_0, &e.h_inf, &e.a1_inf_single);
          e.ready = true;
          if (cache_) ends_[g] = e;
        }
      }
      for (auto& e : elastic) e.reset();

      for (std::size_t idh = 0; idh < c[kAxisDh]; ++idh) {
        problem.dh = value(kAxisDh, idh);
        for (std::size_t iT = 0; iT < c[kAxisT]; ++iT) {
          for (std::size_t ip = 0; ip < c[kAxisPbar]; ++ip) {
            problem.pbar0 = value(kAxisPbar, ip);
            const Ends& e = ends[iT * c[kAxisPbar] + ip];
            model::SummaryParts parts;
            parts.classification = model::classify(touch[idh], problem.pbar0, creep[iT]);
            parts.h_0 = e.h_0;
            parts.h_inf = e.h_inf;
            parts.a1_inf_single = e.a1_inf_single;
            parts.guide = guide[idh].get();
            if (parts.classification.regime == model::Regime::immediate) {
              auto& cached = elastic[idh * c[kAxisPbar] + ip];
              if (!cached) {
                cached = model::solve_elastic_two_level(problem, 1.0 / creep[iT].creep_initial(), guide[idh].get());
              }
              parts.elastic = &*cached;
            }
            const model::PointSummary summary = model::summarize_point(problem, creep[iT], parts);

            const std::size_t i =
                (((il * c[kAxisDh] + idh) * c[kAxisT] + iT) * c[kAxisPbar] + ip) * c[kAxisS] + is;
            out->regime[i] = static_cast<std::int8_t>(summary.regime);
            out->valid[i] = static_cast<std::int8_t>(summary.validity);
            out->t_star[i] = summary.t_star.value_or(kNaN);
            out->h_0[i] = summary.h_0;
            out->h_inf[i] = summary.h_inf;
            out->a1_inf[i] = summary.a1_inf;
            out->a2_inf[i] = summary.a2_inf;
            out->area_fraction_inf[i] = summary.area_fraction_inf;
            if (full) {
              const model::PointResult r = model::evaluate_point(problem, creep[iT], options, summary);
              out->valid[i] = static_cast<std::int8_t>(r.validity);  // a series solve may fail
              store_series(r.series, i, {&out->a1, &out->a2, &out->P1, &out->P2, &out->area_fraction});
            }
          }
        }
      }
    }
  }
  if (sample_) evaluate_reference(box, out);
}

void TileEvaluator::evaluate_reference(const TileBox& box, io::TileData* out) const {
  const auto n = grid_.shape();
  for (std::size_t i = 0; i < box.points(); ++i) {
    // The tile's i-th point (row-major over the box) and its flat index in the grid.
    std::array<std::size_t, kAxes> at{};
    for (std::size_t a = kAxes, rest = i; a-- > 0; rest /= box.count[a]) at[a] = box.start[a] + rest % box.count[a];
    std::uint64_t g = 0;
    for (std::size_t a = 0; a < kAxes; ++a) g = g * n[a] + at[a];
    if (!sample_->contains(g)) continue;

    model::ContactProblem problem;
    problem.l = grid_.axes[kAxisL].values[at[kAxisL]];
    problem.dh = grid_.axes[kAxisDh].values[at[kAxisDh]];
    problem.pbar0 = grid_.axes[kAxisPbar].values[at[kAxisPbar]];
    problem.shape = model::Shape{static_cast<int>(grid_.axes[kAxisS].values[at[kAxisS]]), C_};
    const model::StandardLinearSolid creep(grid_.axes[kAxisT].values[at[kAxisT]]);
    const reference::ReferenceResult r = reference::evaluate_reference_point(problem, creep, reference_options_);
    out->bem_regime[i] = static_cast<std::int8_t>(r.regime);
    out->bem_t_star[i] = r.t_star.value_or(kNaN);
    store_series(r.series, i, {&out->bem_a1, &out->bem_a2, &out->bem_P1, &out->bem_P2, &out->bem_area_fraction});
  }
}

}  // namespace punchsweep::sweep
