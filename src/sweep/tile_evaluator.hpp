#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "map/grid.hpp"
#include "map/quantities.hpp"
#include "model/point/point_axes.hpp"
#include "model/point/sensitivity.hpp"
#include "map/tile_data.hpp"
#include "model/laws/creep_laws.hpp"
#include "model/paper/long_term_guide.hpp"
#include "model/contact/regime.hpp"
#include "model/numerics/stop_request.hpp"
#include "reference/reference_point.hpp"
#include "sweep/batch_evaluator.hpp"
#include "sweep/reference_sample.hpp"
#include "sweep/sweep_config.hpp"

namespace punchsweep::sweep {

/// Evaluates every point of a tile with the model (the same functions as
/// `punchsweep point`). The grid's axes are a point's coordinates by name
/// (model::PointAxes): l, dh, the creep law's own (for the standard linear solid T), pbar,
/// s, and ramp_time when the load is a ramp. The points go through the
/// BatchEvaluator (as Python's classify does), which keeps the parts that depend on fewer
/// coordinates for the whole run of this process; each is a pure function of its
/// coordinates, so no value depends on the tiling or the rank count. What a point stores is
/// read off its result through map::kQuantities.
///
/// With a BEM reference it also evaluates reference::evaluate_reference_point (as
/// `punchsweep reference` does: grid N, the snapshot times, the default step control and
/// solver) at every point of the tile that is in the reference sample, into the bem_*
/// arrays. The sample is all points, K at random, or picked from the model's own answers
/// (reference.sample = invalid or boundary: chosen_by_model, a model-only pass over the grid
/// in the constructor, the same on every rank). That is a pure function of the point too, because the constructor makes FFTW's
/// plans reproducible for the process (use_reproducible_fft_plans).
/// Not thread-safe (one evaluator per rank).
class TileEvaluator {
 public:
  /// Throws std::invalid_argument when the grid's axes are not model::PointAxes of `law`
  /// or the reference sample does not fit the grid.
  /// `loading` is the load's shape where the grid has no ramp_time axis (a step by default);
  /// `localization` the model's (the paper's by default).
  /// `tolerance` (a map's output.tolerance) adds, at every point, t* at the ends of the box
  /// about it and the regimes there (model::t_star_range, as `punchsweep point --tolerance`).
  TileEvaluator(const map::Grid& grid, const model::CreepLawSpec& law, double C, std::vector<double> times,
                map::Quantities quantities, const ReferenceConfig& reference = {},
                model::LoadShape loading = {}, model::Localization localization = {},
                std::vector<model::StatedTolerance> tolerance = {});

  /// Whether evaluate() also runs the BEM reference (when this evaluator has one).
  enum class Reference { evaluated, skipped };

  /// Fills `out` (resized here), row-major over the box, time last. With
  /// Reference::skipped only the model's quantities are filled (no bem_* arrays): what a
  /// calibration or a disk estimate of the model alone needs, from the same evaluator.
  /// `stop` is checked between the box's (l, s, dh) curves and between (and inside) its
  /// BEM points: once requested, the tile is given up by throwing model::Stopped.
  void evaluate(const map::TileBox& box, map::TileData* out, Reference reference = Reference::evaluated,
                const model::StopRequest& stop = {}) const;

  /// The points that get the reference; empty without one.
  const std::optional<ReferenceSample>& reference_sample() const { return sample_; }
  /// The options of every reference point (meaningful with a reference only).
  const reference::ReferenceOptions& reference_options() const { return reference_options_; }

 private:
  /// The grid points (flat, increasing) the model picks for the reference: those it flags
  /// invalid, or those whose regime differs from a neighbour's one step along an axis.
  std::vector<std::uint64_t> chosen_by_model(ReferenceConfig::SampleRule rule) const;
  /// The reference at the sampled points of `box` into out's bem_* arrays (sized already).
  void evaluate_reference(const map::TileBox& box, map::TileData* out, const model::StopRequest& stop) const;
  /// The contact problem and the creep law's parameter values at grid position `at`.
  model::PointValues point_at(const map::Index& at) const;

  map::Grid grid_;
  const model::CreepLawSpec& law_;
  double C_;
  std::vector<double> times_;
  map::Quantities quantities_;
  /// The point's coordinates (the law's; ramp_time where the grid has it), each coordinate's
  /// axis in the grid, and the coordinates in the order a batch's runs nest.
  model::PointAxes axes_;
  std::vector<std::size_t> grid_axis_;
  std::vector<std::size_t> nesting_;
  model::LoadShape loading_;               ///< without a ramp_time axis
  model::Localization localization_;
  std::optional<ReferenceSample> sample_;
  reference::ReferenceOptions reference_options_;
  /// The box of tolerances, each on the law's own parameter object where it is the law's
  /// (model::t_star_range finds a parameter by identity).
  std::vector<model::StatedTolerance> tolerance_;
  /// The model's points, with the parts they share kept for the run.
  mutable BatchEvaluator batch_;
  mutable std::vector<double> columns_;     ///< a box's points as columns (scratch)
  mutable std::vector<std::size_t> index_;  ///< their positions in the tile (scratch)
};

}  // namespace punchsweep::sweep
