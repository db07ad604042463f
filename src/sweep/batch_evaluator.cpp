#include "sweep/batch_evaluator.hpp"

#include <array>
#include <bit>
#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "model/load/creep_weighted_load.hpp"
#include "model/problem/load_shape.hpp"

namespace punchsweep::sweep {

/// PointColumns' columns by what they set: each part of a point depends on its own few.
struct BatchEvaluator::Columns {
  std::span<const double> l, dh, pbar, s;
  std::vector<std::span<const double>> law;
  std::span<const double> ramp_time;  ///< empty: every point has the evaluator's loading
};

namespace {

// Bounds on the caches (entries). A run's parts for the paper's model hold a long-term
// guide each (a few kB); the others are small.
constexpr std::size_t kMaxParts = std::size_t{1} << 16;
constexpr std::size_t kMaxStates = std::size_t{1} << 18;
constexpr std::size_t kMaxRuns = std::size_t{1} << 10;
constexpr int kLog2Elastic = 12;  // the paper's elastic starts: one per pbar of a run
constexpr std::size_t kMaxMaterials = std::size_t{1} << 12;
// Points between two questions to a StopRequest (the Python module's reads the clock), and
// before building a run's parts.
constexpr std::size_t kStopEvery = 64;
constexpr std::size_t kStopBeforeParts = 8;

bool same(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

// Appends what tells point k's material from another's: its creep-law values, then its
// ramp_time (0 where every point has the evaluator's loading).
template <class Columns>
void append_material_key(const Columns& points, std::size_t k, std::vector<double>* key) {
  for (const std::span<const double> column : points.law) key->push_back(column[k]);
  key->push_back(points.ramp_time.empty() ? 0.0 : points.ramp_time[k]);
}

}  // namespace

BatchEvaluator::BatchEvaluator(const model::CreepLawSpec& law, double C, model::Localization localization,
                               model::LoadShape loading, Memory memory)
    : law_(law),
      C_(C),
      localization_(localization),
      loading_(std::move(loading)),
      memory_(memory),
      touch_(3, kMaxParts),
      single_(3, kMaxStates),
      materials_(law.parameters.size() + 1, kMaxMaterials),
      elastic_(kLog2Elastic),
      runs_(5 + law.parameters.size(), kMaxRuns) {}

const BatchEvaluator::Material& BatchEvaluator::material_at(const Columns& points, std::size_t k) {
  key_.clear();
  append_material_key(points, k, &key_);
  const bool cached = memory_ == Memory::run;
  if (cached) {
    if (Material* found = materials_.find(key_)) return *found;
  }
  Material made{model::make_creep_law(law_, std::span<const double>(key_).first(points.law.size())),
                points.ramp_time.empty() ? loading_ : model::LoadShape::ramp(key_.back())};
  if (cached) return materials_.insert(key_, std::move(made));
  // One call's points come sorted by (s, l, dh): a grid's repeat a law run after run (a
  // pbar's worth of points each), scattered points never, and there keeping each in the
  // cache cost 5% of the call.
  last_ = std::move(made);
  return last_;
}

model::SingleLevelState BatchEvaluator::single_at(const model::ContactProblem& problem, double X, bool cached) {
  if (!cached) return model::single_level_at(problem, X);
  const double key[] = {static_cast<double>(problem.shape.s), problem.l, X};
  if (const model::SingleLevelState* found = single_.find(key)) return *found;
  return single_.insert(key, model::single_level_at(problem, X));
}

model::SingleLevelEnds BatchEvaluator::ends_at(const model::ContactProblem& problem, const model::CreepLaw& creep,
                                               bool cached) {
  const model::CreepWeightedLoad load(creep, problem.pbar0, problem.loading);
  const model::SingleLevelState final_state = single_at(problem, load.final(), cached);
  return {single_at(problem, load.initial(), cached).h, final_state.h, final_state.a1};
}

void BatchEvaluator::summarize(const PointColumns& columns, BatchSink& sink, const model::StopRequest& stop) {
  const model::PointAxes& axes = *columns.axes;
  const std::size_t n = columns.size();
  bool fits = columns.columns.size() == axes.size() && axes.law().size() == law_.parameters.size();
  for (std::size_t j = 0; fits && j < axes.law().size(); ++j) {
    fits = axes[axes.law()[j]].parameter->name == law_.parameters[j].name;
  }
  if (!fits) {
    throw std::invalid_argument("batch: the creep law " + std::string(law_.name) + " has " +
                                std::to_string(law_.parameters.size()) + " parameters, the points " +
                                std::to_string(axes.law().size()) + " and " + std::to_string(columns.columns.size()) +
                                " columns for " + std::to_string(axes.size()) + " coordinates");
  }
  bool equal = true;
  for (const std::span<const double> column : columns.columns) equal = equal && column.size() == n;
  if (!equal) throw std::invalid_argument("batch: the point columns differ in length");
  const auto column = [&](model::Coordinate c) {
    const std::size_t j = axes.find(c);
    return j < axes.size() ? columns.columns[j] : std::span<const double>();
  };
  Columns points{column(model::Coordinate::pitch), column(model::Coordinate::height_difference),
                 column(model::Coordinate::pressure), column(model::Coordinate::exponent), {},
                 column(model::Coordinate::ramp_time)};
  for (const std::size_t j : axes.law()) points.law.push_back(columns.columns[j]);

  model::ContactProblem problem;
  problem.localization = localization_;
  problem.loading = loading_;
  const bool paper = localization_.is_paper();
  const bool run_memory = memory_ == Memory::run;
  const Material* material = nullptr;
  std::size_t material_k = 0;  // a point that has `material`
  const auto same_material = [&](std::size_t a, std::size_t b) {
    for (const std::span<const double> column : points.law) {
      if (!same(column[a], column[b])) return false;
    }
    return points.ramp_time.empty() || same(points.ramp_time[a], points.ramp_time[b]);
  };
  bool cache_single = run_memory;
  const std::size_t width = 2 + points.law.size();  // a point's keys in Run::keys
  std::optional<model::LocalizationParts> own;
  std::size_t unchecked = kStopEvery;  // points since `stop` was last asked
  for (std::size_t begin = 0; begin < n;) {
    const double s = points.s[begin], l = points.l[begin], dh = points.dh[begin];
    std::size_t end = begin + 1;
    while (end < n && same(points.s[end], s) && same(points.l[end], l) && same(points.dh[end], dh)) ++end;
    if (!run_memory && (begin == 0 || !same(points.s[begin - 1], s) || !same(points.l[begin - 1], l))) {
      // A new (s, l): its single-level states are met again only if another dh follows.
      cache_single = end < n && same(points.s[end], s) && same(points.l[end], l);
    }
    problem.l = l;
    problem.dh = dh;
    problem.shape = model::Shape{static_cast<int>(s), C_};
    // Building the parts can take milliseconds (the refined model's curves): ask before
    // that as well, every few runs.
    const auto build = [&] {
      if (unchecked >= kStopBeforeParts) {
        stop.throw_if_requested();
        unchecked = 0;
      }
      return model::LocalizationParts(problem);
    };
    const model::DhParts* parts = nullptr;
    if (run_memory) {
      const double key[] = {s, l, dh};
      const model::LocalizationParts* found = touch_.find(key);
      parts = &(found != nullptr ? *found : touch_.insert(key, build())).dh();
    } else {
      own.emplace(build());
      parts = &own->dh();
    }

    Run* run = nullptr;
    if (cache_single) {
      // A run is known by its (s, l), its first point and its length: a sweep's tiles that
      // cut the law's axes or pbar into parts make runs of several kinds in one (s, l).
      point_key_.assign({s, l, points.pbar[begin]});
      append_material_key(points, begin, &point_key_);
      point_key_.push_back(static_cast<double>(end - begin));
      run = runs_.find(point_key_);
      if (run == nullptr) run = &runs_.insert(point_key_, Run{});
      if (run->ends.size() < end - begin) {
        run->keys.resize((end - begin) * width, std::numeric_limits<double>::quiet_NaN());  // matches no point
        run->ends.resize(end - begin);
      }
    }
    for (std::size_t k = begin; k < end; ++k) {
      if (++unchecked >= kStopEvery) {
        stop.throw_if_requested();
        unchecked = 0;
      }
      if (material == nullptr || !same_material(k, material_k)) {
        material = &material_at(points, k);
        material_k = k;
        problem.loading = material->loading;
      }
      const model::CreepLaw& creep = *material->creep;
      problem.pbar0 = points.pbar[k];
      // The ends: the last run of this (s, l)'s at this position where it had this
      // point's pbar and law, else through single_ (and kept there for the next run).
      model::SingleLevelEnds ends;
      if (run != nullptr) {
        const std::size_t j = k - begin;
        point_key_.assign(1, problem.pbar0);
        append_material_key(points, k, &point_key_);
        double* stored = &run->keys[j * width];
        bool known = true;
        for (std::size_t q = 0; q < width && known; ++q) known = same(point_key_[q], stored[q]);
        if (known) {
          ends = run->ends[j];
        } else {
          ends = ends_at(problem, creep, true);
          std::copy(point_key_.begin(), point_key_.end(), stored);
          run->ends[j] = ends;
        }
      } else {
        ends = ends_at(problem, creep, false);
      }
      // The elastic start at t = 0 has modulus 1/J(0) = 1 E0* for every creep law (the unit
      // of pressure): per (s, l, dh, pbar). Kept for the paper's model, whose start is a
      // Newton solve (3 us), and, where a run has more points than one (a grid's: its laws
      // meet each pbar again), the periodic model's (its small spots' and hand-over's reads
      // cost more than the lookup); the refined model reads its branch, no dearer.
      std::optional<model::ElasticTwoLevel>* elastic = nullptr;
      if (paper || (localization_.periodic && end - begin > 1)) {
        const std::array<double, 4> key{s, l, dh, problem.pbar0};
        elastic = elastic_.find(key);
        if (elastic == nullptr) elastic = &elastic_.put(key, std::nullopt);
      }
      const model::PointSummary summary = model::summarize_point(problem, creep, *parts, ends, elastic);
      sink.take(BatchPoint{k, problem, creep, *parts, summary});
    }
    begin = end;
  }
}

}  // namespace punchsweep::sweep
