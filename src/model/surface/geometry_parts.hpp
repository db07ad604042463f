#pragma once
/// @file
/// A geometry's parts, built once and read at any number of load points (docs/model.md,
/// sections 10 and 17): each level's touchdown load X*, the creep-weighted load at which the
/// level's first cap touches. Read under a material and a load, a level touches at once
/// where X(0+) >= X*, after the delay t* where X(t*) = X*, or never where X(inf) < X*
/// (model::classify): the same reading for every geometry. Two implementations:
/// - LocalizationParts: the paper's two-level square lattice by a localization model (the
///   touchdown of model::touchdown: the periodic model's tables, the paper's, the refined
///   one's), no curve;
/// - CurveParts: any cell's elastic load curve (any number of levels; its areas, loads and
///   sites in contact in time as well).
/// engine::texture_parts chooses between them for a texture.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "model/laws/creep_laws.hpp"
#include "model/load/creep_weighted_load.hpp"
#include "model/point/point_axes.hpp"
#include "model/point/point_evaluation.hpp"
#include "model/problem/contact_problem.hpp"
#include "model/surface/load_curve.hpp"
#include "model/surface/surface_history.hpp"

namespace punchsweep::model {

class GeometryParts {
 public:
  virtual ~GeometryParts() = default;

  /// Each level's touchdown load X*, in E0* (level 0, the tallest: 0; +infinity for a level
  /// that never touches, whatever the load).
  virtual std::span<const double> touchdowns() const = 0;
  /// Whether the parts resolve level `level`'s X* (a curve's: at or above its X_resolved).
  virtual bool resolved(std::size_t level) const = 0;
  /// The cell's load curve where the parts are one; nullptr for a localization's.
  virtual const LoadCurve* curve() const = 0;

  int levels() const { return static_cast<int>(touchdowns().size()); }
  /// Each level's touch under `load`.
  std::vector<LevelTouch> touches(const CreepWeightedLoad& load) const;
  /// Each level's touch at `n` load points: point k takes columns[j][k] for each coordinate
  /// j of `axes` that has a column (nullptr: none, the point keeps its default), the creep
  /// law `spec` at its values and its load. t_star and regime are n x levels(), row-major
  /// (regime as model::Regime's codes). Python's surface_classify reads this.
  void touches_at(const CreepLawSpec& spec, const PointAxes& axes, std::span<const double* const> columns, std::size_t n,
                  double* t_star, std::int8_t* regime) const;
};

/// The largest X(inf) (E0*) of `n` points taken as GeometryParts::touches_at takes them (0
/// for none): how far a curve is read for them.
double largest_final_load(const CreepLawSpec& spec, const PointAxes& axes, std::span<const double* const> columns,
                          std::size_t n);

/// The paper's two-level square lattice (the problem's l, dh, shape) by its localization
/// model: the model's parts of (s, l, dh) (model::dh_parts: the touchdown, and the guide or
/// branch the point's other quantities read), level 1's touchdown theirs. The problem's
/// pressure and load are not read. A sweep's tiles and Python's classify keep these per
/// (s, l, dh) (sweep::BatchEvaluator).
class LocalizationParts final : public GeometryParts {
 public:
  explicit LocalizationParts(const ContactProblem& problem);
  std::span<const double> touchdowns() const override { return touchdowns_; }
  bool resolved(std::size_t) const override { return true; }
  const LoadCurve* curve() const override { return nullptr; }
  /// The model's parts (for model::summarize_point and evaluate_point).
  const DhParts& dh() const { return dh_; }

 private:
  DhParts dh_;
  std::array<double, 2> touchdowns_;
};

/// Any cell by its elastic load curve.
class CurveParts final : public GeometryParts {
 public:
  explicit CurveParts(LoadCurve curve) : curve_(std::move(curve)) {}
  std::span<const double> touchdowns() const override { return curve_.level_touchdown; }
  bool resolved(std::size_t level) const override;
  const LoadCurve* curve() const override { return &curve_; }

 private:
  LoadCurve curve_;
};

}  // namespace punchsweep::model
