#include "sweep/batch_evaluator.hpp"

#include <bit>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

#include "model/creep_weighted_load.hpp"
#include "model/load_shape.hpp"

namespace punchsweep::sweep {
namespace {

// Bounds on the caches (entries). A run's parts for the paper's model hold a long-term
// guide each (a few kB); the others are small.
constexpr std::size_t kMaxParts = std::size_t{1} << 16;
constexpr std::size_t kMaxStates = std::size_t{1} << 18;
constexpr std::size_t kMaxMaterials = std::size_t{1} << 12;

bool same(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

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
      elastic_(1, kMaxStates) {}

const BatchEvaluator::Material& BatchEvaluator::material_at(const PointColumns& points, std::size_t k) {
  key_.clear();
  for (const std::span<const double> column : points.law) key_.push_back(column[k]);
  const bool ramp = !points.ramp_time.empty();
  key_.push_back(ramp ? points.ramp_time[k] : 0.0);
  if (Material* found = materials_.find(key_)) return *found;
  Material made{model::make_creep_law(law_, std::span<const double>(key_).first(points.law.size())),
                ramp ? model::LoadShape::ramp(key_.back()) : loading_};
  return materials_.insert(key_, std::move(made));
}

model::SingleLevelState BatchEvaluator::single_at(const model::ContactProblem& problem, double X, bool cached) {
  if (!cached) return model::single_level_at(problem, X);
  const double key[] = {static_cast<double>(problem.shape.s), problem.l, X};
  if (const model::SingleLevelState* found = single_.find(key)) return *found;
  return single_.insert(key, model::single_level_at(problem, X));
}

void BatchEvaluator::summarize(const PointColumns& points, BatchSink& sink, const model::StopRequest& stop) {
  const std::size_t n = points.size();
  if (points.law.size() != law_.parameters.size()) {
    throw std::invalid_argument("batch: the creep law " + std::string(law_.name) + " has " +
                                std::to_string(law_.parameters.size()) + " parameters, the points " +
                                std::to_string(points.law.size()));
  }
  bool equal = points.dh.size() == n && points.pbar.size() == n && points.s.size() == n &&
               (points.ramp_time.empty() || points.ramp_time.size() == n);
  for (const std::span<const double> column : points.law) equal = equal && column.size() == n;
  if (!equal) throw std::invalid_argument("batch: the point columns differ in length");

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
  model::DhParts own;
  for (std::size_t begin = 0; begin < n;) {
    stop.throw_if_requested();
    const double s = points.s[begin], l = points.l[begin], dh = points.dh[begin];
    std::size_t end = begin + 1;
    while (end < n && same(points.s[end], s) && same(points.l[end], l) && same(points.dh[end], dh)) ++end;
    if (!run_memory && (begin == 0 || !same(points.s[begin - 1], s) || !same(points.l[begin - 1], l))) {
      // A new (s, l): its single-level states are met again only if another dh follows.
      single_.clear();
      cache_single = end < n && same(points.s[end], s) && same(points.l[end], l);
    }
    problem.l = l;
    problem.dh = dh;
    problem.shape = model::Shape{static_cast<int>(s), C_};
    const model::DhParts* parts = &own;
    if (run_memory) {
      const double key[] = {s, l, dh};
      parts = touch_.find(key);
      if (parts == nullptr) parts = &touch_.insert(key, model::dh_parts(problem));
    } else {
      own = model::dh_parts(problem);
    }
    if (paper) elastic_.clear();

    for (std::size_t k = begin; k < end; ++k) {
      if (((k - begin) & 63) == 63) stop.throw_if_requested();
      if (material == nullptr || !same_material(k, material_k)) {
        material = &material_at(points, k);
        material_k = k;
        problem.loading = material->loading;
      }
      const model::CreepLaw& creep = *material->creep;
      problem.pbar0 = points.pbar[k];
      const model::CreepWeightedLoad load(creep, problem.pbar0, problem.loading);
      const model::SingleLevelState final_state = single_at(problem, load.final(), cache_single);
      const model::SingleLevelEnds ends{single_at(problem, load.initial(), cache_single).h, final_state.h,
                                        final_state.a1};
      // The elastic start at t = 0 has modulus 1/J(0) = 1 E0* for every creep law (the unit
      // of pressure): per pbar within the run. Kept for the paper's model, whose start is a
      // Newton solve (3 us); the others read their branch, no dearer than the lookup.
      std::optional<model::ElasticTwoLevel>* elastic = nullptr;
      if (paper) {
        const double key[] = {problem.pbar0};
        elastic = elastic_.find(key);
        if (elastic == nullptr) elastic = &elastic_.insert(key, std::nullopt);
      }
      const model::PointSummary summary = model::summarize_point(problem, creep, *parts, ends, elastic);
      sink.take(BatchPoint{k, problem, creep, *parts, summary});
    }
    begin = end;
  }
}

}  // namespace punchsweep::sweep
