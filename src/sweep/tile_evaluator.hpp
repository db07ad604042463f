#pragma once

#include <vector>

#include <memory>

#include "io/tile_data.hpp"
#include "model/long_term_guide.hpp"
#include "sweep/grid.hpp"
#include "sweep/sweep_config.hpp"

namespace punchsweep::sweep {

/// Evaluates every point of a tile with the model (the same functions as
/// `punchsweep point`). Sub-results that depend on fewer coordinates are computed once:
/// the touchdown and long-term guide per (l, s, dh) and the single-level ends per (l, s, pbar, T) for the whole
/// run of this process, the elastic start per (l, s, dh, pbar) per tile. Each is a pure
/// function of its coordinates, so no value depends on the tiling or the rank count.
/// Not thread-safe (one evaluator per rank).
class TileEvaluator {
 public:
  TileEvaluator(const Grid& grid, double C, std::vector<double> times, Quantities quantities);

  /// Fills `out` (resized here), row-major over the box, time last.
  void evaluate(const TileBox& box, io::TileData* out) const;

 private:
  /// The single-level ends of eq 9.5/9.10 at one (l, s, pbar, T).
  struct Ends {
    double h_0 = 0.0;
    double h_inf = 0.0;
    double a1_inf_single = 0.0;
    bool ready = false;
  };
  struct Touch {
    double a1_star = 0.0;
    double X_star = 0.0;
    std::shared_ptr<const model::LongTermGuide> guide;  ///< built with the touchdown
    bool ready = false;
  };

  Grid grid_;
  double C_;
  std::vector<double> times_;
  Quantities quantities_;
  bool cache_ = false;                 ///< the run-wide caches fit (else: per tile)
  mutable std::vector<Ends> ends_;     ///< by global (l, s, T, pbar)
  mutable std::vector<Touch> touch_;   ///< by global (l, s, dh)
};

}  // namespace punchsweep::sweep
