#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace punchsweep::io {

/// Results of one tile, each array row-major over the tile box (l, dh, T, pbar, s) and,
/// for the time series, (l, dh, T, pbar, s, time). Codes: regime 0 immediate, 1 delayed,
/// 2 never, -1 not computed; valid 0 valid, 1 same_level_overlap, 2 cross_level_overlap,
/// 3 no_solution, -1 not computed. Floats: NaN where not defined (t_star for never).
struct TileData {
  std::vector<std::int8_t> regime;
  std::vector<std::int8_t> valid;
  std::vector<double> t_star;             ///< T_eps
  std::vector<double> h_0;                ///< R
  std::vector<double> h_inf;              ///< R
  std::vector<double> a1_inf;             ///< R
  std::vector<double> a2_inf;             ///< R
  std::vector<double> area_fraction_inf;  ///< 1
  // --quantities full only (empty otherwise): points * times values each.
  std::vector<double> a1;                 ///< R
  std::vector<double> a2;                 ///< R
  std::vector<double> P1;                 ///< R^2 E0*
  std::vector<double> P2;                 ///< R^2 E0*
  std::vector<double> area_fraction;      ///< 1

  /// Sizes every array for `points` points (and `times` snapshot times when full).
  void resize(std::size_t points, std::size_t times, bool full) {
    regime.assign(points, -1);
    valid.assign(points, -1);
    for (auto* v : {&t_star, &h_0, &h_inf, &a1_inf, &a2_inf, &area_fraction_inf}) v->assign(points, 0.0);
    const std::size_t series = full ? points * times : 0;
    for (auto* v : {&a1, &a2, &P1, &P2, &area_fraction}) v->assign(series, 0.0);
  }
};

}  // namespace punchsweep::io
