#include "sweep/tile_evaluator.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include "model/point/point_evaluation.hpp"
#include "sweep/reproducible_fft.hpp"

namespace punchsweep::sweep {
namespace {

// Stores the per-point quantities of `source` that `summary` gives, at point i. Unrolled
// over kQuantities at compile time, so each is a direct (inlined) read of the result.
// In full mode (`full`) also those stored only there (Extent::point_full).
template <map::Source source, bool full = false, std::size_t... Q>
void store_point(const model::PointSummary& summary, std::size_t i, map::TileData* out,
                 std::index_sequence<Q...>) {
  const auto one = [&]<std::size_t q>() {
    constexpr map::QuantitySpec spec = map::kQuantities[q];
    if constexpr (spec.source == source &&
                  (spec.extent == map::Extent::point || (full && spec.extent == map::Extent::point_full))) {
      if constexpr (spec.kind == map::Kind::flag) {
        out->codes[q][i] = spec.code(summary);
      } else {
        out->reals[q][i] = spec.value(summary);
      }
    }
  };
  (one.template operator()<Q>(), ...);
}

// Stores the series quantities of `source` from `series` at point i.
template <map::Source source, std::size_t... Q>
void store_series(const std::vector<model::Snapshot>& series, std::size_t i, map::TileData* out,
                  std::index_sequence<Q...>) {
  const std::size_t nt = series.size();
  const auto one = [&]<std::size_t q>() {
    constexpr map::QuantitySpec spec = map::kQuantities[q];
    if constexpr (spec.source == source && spec.extent == map::Extent::series) {
      for (std::size_t it = 0; it < nt; ++it) out->reals[q][i * nt + it] = spec.series_value(series[it]);
    }
  };
  (one.template operator()<Q>(), ...);
}

constexpr auto kAll = std::make_index_sequence<map::kQuantityCount>{};

// The answer at each point (map::Source::answer): the BEM's where it ran, else the model's
// where the model is valid, else none.
void merge_answers(map::TileData* out) {
  using map::quantity;
  const std::vector<std::int8_t>& regime = out->codes[quantity("regime")];
  const std::vector<std::int8_t>& valid = out->codes[quantity("valid")];
  const std::vector<std::int8_t>& bem_regime = out->codes[quantity("bem_regime")];
  const std::vector<double>& t_star = out->reals[quantity("t_star")];
  const std::vector<double>& bem_t_star = out->reals[quantity("bem_t_star")];
  std::vector<std::int8_t>& answer = out->codes[quantity("answer_regime")];
  std::vector<double>& answer_t_star = out->reals[quantity("answer_t_star")];
  std::vector<std::int8_t>& source = out->codes[quantity("answer_source")];
  const auto code = [](map::AnswerSource s) { return static_cast<std::int8_t>(s); };
  for (std::size_t i = 0; i < regime.size(); ++i) {
    if (bem_regime[i] != map::kNotComputed) {
      answer[i] = bem_regime[i];
      answer_t_star[i] = bem_t_star[i];
      source[i] = code(map::AnswerSource::bem);
    } else if (valid[i] == static_cast<std::int8_t>(model::Validity::valid)) {
      answer[i] = regime[i];
      answer_t_star[i] = t_star[i];
      source[i] = code(map::AnswerSource::model);
    } else {
      source[i] = code(map::AnswerSource::none);  // answer_regime stays not_computed, answer_t_star NaN
    }
  }
}

std::size_t require_axis(const map::Grid& grid, std::string_view name) {
  const std::size_t a = grid.find(name);
  if (a == grid.rank()) throw std::invalid_argument("sweep: the grid has no axis " + std::string(name));
  return a;
}

}  // namespace

TileEvaluator::TileEvaluator(const map::Grid& grid, const model::CreepLawSpec& law, double C,
                             std::vector<double> times, map::Quantities quantities, const ReferenceConfig& reference,
                             model::LoadShape loading, model::Localization localization,
                             std::vector<model::StatedTolerance> tolerance)
    : grid_(grid),
      law_(law),
      C_(C),
      times_(std::move(times)),
      quantities_(quantities),
      axes_(law.parameters, grid.find(model::ramp_time_parameter().name) < grid.rank()),
      loading_(std::move(loading)),
      localization_(localization),
      tolerance_(std::move(tolerance)),
      batch_(law, C, localization, loading_) {
  for (const model::PointAxis& axis : axes_) grid_axis_.push_back(require_axis(grid, axis.parameter->name));
  if (grid.rank() != axes_.size()) {
    throw std::invalid_argument("sweep: the grid has axes beyond the model's and the creep law's parameters");
  }
  nesting_ = axes_.nesting();
  for (model::StatedTolerance& t : tolerance_) {
    for (const model::Parameter& p : law.parameters) {
      if (p.name == t.parameter->name) t.parameter = &p;
    }
  }
  if (reference.on()) {
    if (reference.rule == ReferenceConfig::SampleRule::count) {
      sample_.emplace(grid.points(), reference.sample, reference.seed);
    } else {
      sample_.emplace(grid.points(), chosen_by_model(reference.rule));
    }
    reference_options_.n = reference.grid;
    reference_options_.times = times_;
    use_reproducible_fft_plans();
  }
}

namespace {

// Stores each evaluated point of a tile at its place in the tile (index[k] for the k-th
// point of the columns): the summary's quantities, or in full mode the point's series too.
class TileSink final : public BatchSink {
 public:
  /// `tolerance`: the map's box of tolerances (empty: none), `law` the creep law and
  /// `columns` the points (their law values, for the box's corners).
  TileSink(map::TileData* out, const std::vector<std::size_t>& index, const model::EvaluationOptions* full,
           std::span<const model::StatedTolerance> tolerance, const model::CreepLawSpec& law,
           const PointColumns& columns)
      : out_(out), index_(index), full_(full), tolerance_(tolerance), law_(law), columns_(columns) {}
  void take(const BatchPoint& p) override {
    const std::size_t i = index_[p.k];
    if (!tolerance_.empty()) store_range(p, i);
    if (full_ != nullptr) {
      model::PointResult r = model::evaluate_point(p.problem, p.creep, *full_, p.summary, p.parts.branch());
      const double t_star = r.t_star.value_or(std::numeric_limits<double>::infinity());
      r.dt_star_ddh = model::t_star_derivative(p.problem, p.creep, model::kHeightDifference, t_star).derivative;
      r.dt_star_dpbar = model::t_star_derivative(p.problem, p.creep, model::kPressure, t_star).derivative;
      r.dt_star_dl = model::t_star_derivative(p.problem, p.creep, model::kPitch, t_star).derivative;
      store_point<map::Source::model, true>(r, i, out_, kAll);  // a series solve may flag the point
      store_series<map::Source::model>(r.series, i, out_, kAll);
    } else {
      store_point<map::Source::model>(p.summary, i, out_, kAll);
    }
  }

 private:
  // t* over the box about the point, and the regimes at its ends (map::Source::tolerance).
  void store_range(const BatchPoint& p, std::size_t i) {
    law_values_.clear();
    for (const std::size_t j : columns_.axes->law()) law_values_.push_back(columns_.columns[j][p.k]);
    model::PointSummary range;
    try {
      range.t_star_range = model::t_star_range(p.problem, law_, law_values_, tolerance_);
    } catch (const std::invalid_argument&) {
      // A corner outside a parameter's range (a temperature beyond the shift's): not computed.
    }
    store_point<map::Source::tolerance>(range, i, out_, kAll);
  }

  map::TileData* out_;
  const std::vector<std::size_t>& index_;
  const model::EvaluationOptions* full_;
  std::span<const model::StatedTolerance> tolerance_;
  const model::CreepLawSpec& law_;
  const PointColumns& columns_;
  std::vector<double> law_values_;
};

}  // namespace

void TileEvaluator::evaluate(const map::TileBox& box, map::TileData* out, Reference reference,
                             const model::StopRequest& stop) const {
  const bool full = quantities_ == map::Quantities::full;
  const bool bem = sample_.has_value() && reference == Reference::evaluated;
  out->resize(box.points(), times_.size(), quantities_, bem, !tolerance_.empty());
  const map::Index& c = box.count;
  const auto value = [&](std::size_t axis, std::size_t i) { return grid_.axes[axis].values[box.start[axis] + i]; };

  // The box's points as columns, one per coordinate, in the order of a batch's runs
  // (model::PointAxes::nesting: l, s, dh, the law's parameters, ramp_time, pbar), so that
  // each (l, s, dh) is one run for the batch evaluator; index maps them to the tile's
  // row-major positions.
  map::Index stride(c.size(), 1);
  for (std::size_t a = c.size() - 1; a-- > 0;) stride[a] = stride[a + 1] * c[a + 1];
  const std::size_t points = box.points();
  const std::size_t width = axes_.size();
  columns_.resize(points * width);
  index_.resize(points);
  std::vector<std::size_t> at(width, 0);  // each coordinate's position within the box
  for (std::size_t k = 0; k < points; ++k) {
    std::size_t index = 0;
    for (std::size_t j = 0; j < width; ++j) {
      const std::size_t a = grid_axis_[j];
      columns_[j * points + k] = value(a, at[j]);
      index += at[j] * stride[a];
    }
    index_[k] = index;
    for (std::size_t q = width; q-- > 0;) {  // the next point: the innermost coordinate first
      const std::size_t j = nesting_[q];
      if (++at[j] < c[grid_axis_[j]]) break;
      at[j] = 0;
    }
  }
  PointColumns batch{&axes_, {}};
  for (std::size_t j = 0; j < width; ++j) batch.columns.emplace_back(&columns_[j * points], points);
  const model::EvaluationOptions options{times_, {}};
  TileSink sink(out, index_, full ? &options : nullptr, tolerance_, law_, batch);
  batch_.summarize(batch, sink, stop);
  if (bem) {
    evaluate_reference(box, out, stop);
    merge_answers(out);
  }
}

std::vector<std::uint64_t> TileEvaluator::chosen_by_model(ReferenceConfig::SampleRule rule) const {
  // The model alone, regime quantities, one slab of the first axis at a time.
  const TileEvaluator model(grid_, law_, C_, {}, map::Quantities::regime, {}, loading_, localization_);
  const map::Index n = grid_.shape();
  const std::size_t points = grid_.points();
  const std::size_t slab = points / n[0];
  std::vector<std::int8_t> regime(points);
  std::vector<std::int8_t> valid(points);
  map::TileData data;
  for (std::size_t i = 0; i < n[0]; ++i) {
    map::TileBox box{map::Index(n.size(), 0), n};
    box.start[0] = i;
    box.count[0] = 1;
    model.evaluate(box, &data, Reference::skipped);
    std::copy(data.codes[map::quantity("regime")].begin(), data.codes[map::quantity("regime")].end(),
              regime.begin() + static_cast<std::ptrdiff_t>(i * slab));
    std::copy(data.codes[map::quantity("valid")].begin(), data.codes[map::quantity("valid")].end(),
              valid.begin() + static_cast<std::ptrdiff_t>(i * slab));
  }
  std::vector<std::uint64_t> chosen;
  if (rule == ReferenceConfig::SampleRule::invalid) {
    for (std::size_t p = 0; p < points; ++p) {
      if (valid[p] != static_cast<std::int8_t>(model::Validity::valid)) chosen.push_back(p);
    }
    return chosen;
  }
  // Row-major strides; a point is on a boundary if a neighbour along any axis has another regime.
  map::Index stride(n.size(), 1);
  for (std::size_t a = n.size() - 1; a-- > 0;) stride[a] = stride[a + 1] * n[a + 1];
  for (std::size_t p = 0; p < points; ++p) {
    bool boundary = false;
    for (std::size_t a = 0; a < n.size() && !boundary; ++a) {
      const std::size_t index = p / stride[a] % n[a];
      boundary = (index > 0 && regime[p - stride[a]] != regime[p]) ||
                 (index + 1 < n[a] && regime[p + stride[a]] != regime[p]);
    }
    if (boundary) chosen.push_back(p);
  }
  return chosen;
}

model::PointValues TileEvaluator::point_at(const map::Index& at) const {
  model::PointValues point;
  point.problem.shape.C = C_;
  point.problem.localization = localization_;
  point.problem.loading = loading_;
  std::vector<double> values;
  for (const std::size_t a : grid_axis_) values.push_back(grid_.axes[a].values[at[a]]);
  axes_.set(values, &point);
  return point;
}

void TileEvaluator::evaluate_reference(const map::TileBox& box, map::TileData* out,
                                       const model::StopRequest& stop) const {
  for (std::size_t i = 0; i < box.points(); ++i) {
    const map::Index at = box.position(i);
    if (!sample_->contains(grid_.flat_index(at))) continue;
    const model::PointValues point = point_at(at);
    const model::ContactProblem& problem = point.problem;
    const std::unique_ptr<model::CreepLaw> creep = model::make_creep_law(law_, point.law);
    reference::ReferenceOptions options = reference_options_;
    reference::scale_steps_to_law(*creep, &options);
    options.stop = stop;
    const model::PointResult r =
        reference::as_point_result(reference::evaluate_reference_point(problem, *creep, options));
    store_point<map::Source::bem>(r, i, out, kAll);
    store_series<map::Source::bem>(r.series, i, out, kAll);
  }
}

}  // namespace punchsweep::sweep
