#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "model/problem/contact_problem.hpp"
#include "model/laws/creep_law.hpp"
#include "model/laws/creep_laws.hpp"
#include "model/point/point_axes.hpp"
#include "model/point/point_evaluation.hpp"
#include "model/numerics/stop_request.hpp"
#include "model/surface/geometry_parts.hpp"
#include "sweep/value_cache.hpp"

namespace punchsweep::sweep {

/// Points as columns of equal length, one per coordinate of `axes` (model::PointAxes: l,
/// dh, the creep law's parameters, pbar, s, and ramp_time where each point has a ramp of
/// its own), in its order.
struct PointColumns {
  const model::PointAxes* axes;
  std::vector<std::span<const double>> columns;
  std::size_t size() const { return columns.empty() ? 0 : columns.front().size(); }
};

/// One evaluated point, as the batch evaluator hands it on.
struct BatchPoint {
  std::size_t k;                         ///< its position in the columns
  const model::ContactProblem& problem;
  const model::CreepLaw& creep;
  const model::DhParts& parts;           ///< its touchdown, guide or branch (for evaluate_point)
  const model::PointSummary& summary;
};

/// Where the evaluated points go (a tile's arrays, classify's).
class BatchSink {
 public:
  virtual ~BatchSink() = default;
  virtual void take(const BatchPoint& point) = 0;
};

/// The model's summary of many points (model::summarize_point, the same numbers as
/// `punchsweep point`), with every part that depends on fewer coordinates than a point
/// computed once per distinct value of those coordinates: the touchdown and the guide or
/// branch per (s, l, dh), the single-level state per (s, l, X) at the creep-weighted
/// load's ends X(0) and X(inf), the creep law and its loading per value of the law's
/// parameters (and ramp_time), and the paper's elastic start per (s, l, dh, pbar). It
/// serves a sweep's tiles and Python's classify alike, so a model, a creep law or an axis
/// added once works in both. Each part is a pure function of its coordinates, so no value
/// depends on the order of the points, how they are cut into batches, or what the caches
/// hold. The points should come in runs of equal (s, l, dh) (a tile's order, or sorted):
/// a run shares its parts without a lookup. Not thread-safe (one evaluator per rank).
class BatchEvaluator {
 public:
  /// How long the parts are kept. run: for the evaluator's life, bounded (a sweep's tiles
  /// meet the same (s, l, dh) again); call: for one summarize() only, where the caller
  /// sorted its points so that every (s, l, dh) is one run (scattered points would only
  /// fill the caches).
  enum class Memory { run, call };

  /// `loading` is every point's load where the columns have no ramp_time.
  BatchEvaluator(const model::CreepLawSpec& law, double C, model::Localization localization,
                 model::LoadShape loading = {}, Memory memory = Memory::run);

  /// Hands every point of `points` to `sink`, in the columns' order. `stop` is checked
  /// before the first point, then every 64 points and before building a run's parts once
  /// 8 points have passed (model::Stopped).
  /// Throws std::invalid_argument when the columns do not fit the law (axes of another
  /// law, a column missing or extra, unequal lengths).
  void summarize(const PointColumns& points, BatchSink& sink, const model::StopRequest& stop = {});

 private:
  /// A creep law at one value of its parameters, with its load.
  struct Material {
    std::unique_ptr<model::CreepLaw> creep;
    model::LoadShape loading;
  };
  struct Columns;  // the columns by what they set
  const Material& material_at(const Columns& points, std::size_t k);
  model::SingleLevelState single_at(const model::ContactProblem& problem, double X, bool cached);
  model::SingleLevelEnds ends_at(const model::ContactProblem& problem, const model::CreepLaw& creep, bool cached);

  const model::CreepLawSpec& law_;
  double C_;
  model::Localization localization_;
  model::LoadShape loading_;
  Memory memory_;
  ValueCache<model::LocalizationParts> touch_;         ///< (s, l, dh): the geometry's parts
  ValueCache<model::SingleLevelState> single_;         ///< (s, l, X)
  ValueCache<Material> materials_;                     ///< the law's values (and ramp_time), Memory::run
  Material last_;                                      ///< the last one made, Memory::call
  DirectCache<std::optional<model::ElasticTwoLevel>, 4> elastic_;  ///< (s, l, dh, pbar)
  std::vector<double> key_;                            ///< scratch of material_at()
  std::vector<double> point_key_;                      ///< scratch: a point's key in Run::keys
  /// The points of the last run of one (s, l) that began with the same point and had the
  /// same length, in order: their pbar, law values and ramp_time (width 2 + the law's
  /// parameters), and their single-level ends. The next such run (a tile's next dh, the
  /// next tile's) meets the same sequence and reads its ends from here position by
  /// position, in memory order: a lookup per point in single_ cost a sweep 10-15% of its
  /// rate in cache misses.
  struct Run {
    std::vector<double> keys;
    std::vector<model::SingleLevelEnds> ends;
  };
  ValueCache<Run> runs_;  ///< (s, l, the first point's pbar, law values, ramp_time, length)
};

}  // namespace punchsweep::sweep
