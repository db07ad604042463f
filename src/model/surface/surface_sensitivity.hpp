#pragma once
/// @file
/// How each level's t* of a texture moves with the load's inputs (docs/model.md, section
/// 17): the pressure and the creep law's parameters (T, a material's temperature), read off
/// the same load curve, by the point's rule (model/point/sensitivity.hpp: central
/// differences at two steps, Richardson, checked); and the range of each level's t* over a
/// box of tolerances on them. The geometry's own inputs (dh, pitch) would need a curve per
/// step and corner: not here.

#include <span>
#include <vector>

#include "model/laws/creep_laws.hpp"
#include "model/point/sensitivity.hpp"
#include "model/problem/load_shape.hpp"
#include "model/surface/load_curve.hpp"

namespace punchsweep::model {

/// The load's inputs at one point: the pressure, the law and its values, the load's shape.
struct SurfaceLoad {
  double pbar0 = 0.0;
  const CreepLawSpec* law = nullptr;
  std::vector<double> law_values;  ///< in law->parameters order
  LoadShape shape{};
};

/// t* of `level` under `load`, read off `curve` (0 immediate, +infinity never).
double level_t_star(const LoadCurve& curve, int level, const SurfaceLoad& load);

/// d t*/dx of `level` along pbar and each real-valued parameter of the law (in that order),
/// at a point whose t* is `t_star`: NaN where the level is not delayed there.
std::vector<TStarDerivative> level_t_star_derivatives(const LoadCurve& curve, int level, const SurfaceLoad& load,
                                                      double t_star);

/// Each level's least and greatest t* over the corners of `tolerances` (each on pbar or one
/// of the law's parameters; std::invalid_argument naming one on another parameter, or one
/// that takes its parameter out of range), with the corners' regimes counted: one entry
/// per level, every corner's creep law made and the curve read once for all levels.
std::vector<TStarRange> level_t_star_ranges(const LoadCurve& curve, const SurfaceLoad& load,
                                            std::span<const Tolerance> tolerances);

/// The largest X(inf) (E0*) of `load` and of every corner of `tolerances` (as
/// level_t_star_ranges takes them, and refuses them): as far as a curve is read for them.
double largest_final_load(const SurfaceLoad& load, std::span<const Tolerance> tolerances);

}  // namespace punchsweep::model
