#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
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
  // The periodic BEM reference (empty without it), whatever the quantities: -1 and NaN at
  // the points outside its sample. Regime codes as above.
  std::vector<std::int8_t> bem_regime;
  std::vector<double> bem_t_star;         ///< T_eps
  // points * times values each.
  std::vector<double> bem_a1;             ///< R
  std::vector<double> bem_a2;             ///< R
  std::vector<double> bem_P1;             ///< R^2 E0*
  std::vector<double> bem_P2;             ///< R^2 E0*
  std::vector<double> bem_area_fraction;  ///< 1

  /// Sizes every array for `points` points and `times` snapshot times: the series when
  /// `full`, the bem_* arrays (as not computed) when `bem`; the others are left empty.
  void resize(std::size_t points, std::size_t times, bool full, bool bem) {
    regime.assign(points, -1);
    valid.assign(points, -1);
    for (auto* v : {&t_star, &h_0, &h_inf, &a1_inf, &a2_inf, &area_fraction_inf}) v->assign(points, 0.0);
    const std::size_t series = full ? points * times : 0;
    for (auto* v : {&a1, &a2, &P1, &P2, &area_fraction}) v->assign(series, 0.0);
    // Unlike the model's arrays, these are not all overwritten: only sampled points are.
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    bem_regime.assign(bem ? points : 0, -1);
    bem_t_star.assign(bem ? points : 0, kNaN);
    for (auto* v : {&bem_a1, &bem_a2, &bem_P1, &bem_P2, &bem_area_fraction}) v->assign(bem ? points * times : 0, kNaN);
  }
};

}  // namespace punchsweep::io
