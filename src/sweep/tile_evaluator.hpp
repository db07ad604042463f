#pragma once

#include <vector>

#include "io/tile_data.hpp"
#include "sweep/grid.hpp"
#include "sweep/sweep_config.hpp"

namespace punchsweep::sweep {

/// Evaluates every point of a tile with the model (the same functions as
/// `punchsweep point`). Sub-results that depend on fewer coordinates (touchdown per dh,
/// single-level ends per (pbar, T), elastic start per (dh, pbar)) are computed once per
/// tile; each is a pure function of its coordinates, so no value depends on the tiling.
class TileEvaluator {
 public:
  TileEvaluator(const Grid& grid, double C, std::vector<double> times, Quantities quantities);

  /// Fills `out` (resized here), row-major over the box, time last.
  void evaluate(const TileBox& box, io::TileData* out) const;

 private:
  Grid grid_;
  double C_;
  std::vector<double> times_;
  Quantities quantities_;
};

}  // namespace punchsweep::sweep
