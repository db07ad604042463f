#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "io/tile_data.hpp"
#include "model/long_term_guide.hpp"
#include "model/regime.hpp"
#include "reference/reference_point.hpp"
#include "sweep/grid.hpp"
#include "sweep/reference_sample.hpp"
#include "sweep/sweep_config.hpp"

namespace punchsweep::sweep {

/// Evaluates every point of a tile with the model (the same functions as
/// `punchsweep point`). Sub-results that depend on fewer coordinates are computed once:
/// the touchdown and long-term guide per (l, s, dh) and the single-level ends per (l, s, pbar, T) for the whole
/// run of this process, the elastic start per (l, s, dh, pbar) per tile. Each is a pure
/// function of its coordinates, so no value depends on the tiling or the rank count.
///
/// With a BEM reference it also evaluates reference::evaluate_reference_point (as
/// `punchsweep reference` does: grid N, the snapshot times, the default step control and
/// solver) at every point of the tile that is in the reference sample, into the bem_*
/// arrays. That is a pure function of the point too, because the constructor makes FFTW's
/// plans reproducible for the process (use_reproducible_fft_plans).
/// Not thread-safe (one evaluator per rank).
class TileEvaluator {
 public:
  /// Throws std::invalid_argument when the reference sample does not fit the grid.
  TileEvaluator(const Grid& grid, double C, std::vector<double> times, Quantities quantities,
                const ReferenceConfig& reference = {});

  /// Fills `out` (resized here), row-major over the box, time last.
  void evaluate(const TileBox& box, io::TileData* out) const;

  /// The points that get the reference; empty without one.
  const std::optional<ReferenceSample>& reference_sample() const { return sample_; }
  /// The options of every reference point (meaningful with a reference only).
  const reference::ReferenceOptions& reference_options() const { return reference_options_; }

 private:
  /// The reference at the sampled points of `box` into out's bem_* arrays (sized already).
  void evaluate_reference(const TileBox& box, io::TileData* out) const;

  /// The single-level ends of eq 9.5/9.10 at one (l, s, pbar, T).
  struct Ends {
    double h_0 = 0.0;
    double h_inf = 0.0;
    double a1_inf_single = 0.0;
    bool ready = false;
  };
  struct Touch {
    model::Touchdown touchdown;
    std::shared_ptr<const model::LongTermGuide> guide;  ///< built with the touchdown
    bool ready = false;
  };

  Grid grid_;
  double C_;
  std::vector<double> times_;
  Quantities quantities_;
  std::optional<ReferenceSample> sample_;
  reference::ReferenceOptions reference_options_;
  bool cache_ = false;                 ///< the run-wide caches fit (else: per tile)
  mutable std::vector<Ends> ends_;     ///< by global (l, s, T, pbar)
  mutable std::vector<Touch> touch_;   ///< by global (l, s, dh)
};

}  // namespace punchsweep::sweep
