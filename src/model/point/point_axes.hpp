#pragma once
/// @file
/// A point's coordinates, declared once: for a creep law (and a load that rises over a
/// ramp_time of each point's own, or not) the parameters that fix one point of the model,
/// in a map's axis order, each with the part of the point it sets. A sweep's grid, its tile
/// evaluator, the batch evaluator, Python's classify and the point commands iterate this list
/// instead of naming l, dh, pbar and s by position; a new axis is a Coordinate here, its
/// Parameter and the line of set_coordinate() that puts it into the point (and, where a
/// batch shares work across points, what that work depends on: Coordinate's order).

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "model/problem/contact_problem.hpp"
#include "model/problem/parameter.hpp"

namespace punchsweep::model {

/// What a coordinate sets, in the order a batch's runs nest (outermost first): the points
/// of one (l, s, dh) share their touchdown and branch, those of one (l, s) their
/// single-level states, those of one material its creep law; the pressure varies fastest.
enum class Coordinate : unsigned char {
  pitch,              ///< l, ContactProblem::l
  exponent,           ///< s, ContactProblem::shape.s
  height_difference,  ///< dh, ContactProblem::dh
  law,                ///< one of the creep law's parameters (law_index says which)
  ramp_time,          ///< the load's rise time: ContactProblem::loading = LoadShape::ramp(value)
  pressure,           ///< pbar, ContactProblem::pbar0
};

/// How many coordinates a batch's runs are made of: those up to height_difference (l, s, dh).
inline constexpr std::size_t kRunCoordinates = static_cast<std::size_t>(Coordinate::height_difference) + 1;

/// One coordinate of a point.
struct PointAxis {
  const Parameter* parameter;
  Coordinate coordinate;
  std::size_t law_index = 0;  ///< Coordinate::law: the parameter's position in the law's
};

/// One point's values, as the point's model takes them: the problem and the law's values.
struct PointValues {
  ContactProblem problem;
  std::vector<double> law;
};

/// The coordinates of a point under a creep law with parameters `law`, in a map's axis
/// order: l, dh, the law's parameters, pbar, s, then ramp_time where `ramp` (for the
/// standard linear solid: l, dh, T, pbar, s).
class PointAxes {
 public:
  PointAxes(std::span<const Parameter> law, bool ramp);

  std::size_t size() const { return axes_.size(); }
  const PointAxis& operator[](std::size_t j) const { return axes_[j]; }
  auto begin() const { return axes_.begin(); }
  auto end() const { return axes_.end(); }
  /// The position of the (first) axis that sets `coordinate`; size() where none does.
  std::size_t find(Coordinate coordinate) const;
  /// The position of the axis called `name`; size() where none is.
  std::size_t find(std::string_view name) const;
  /// The positions of the law's parameters, in the law's order.
  const std::vector<std::size_t>& law() const { return law_; }
  /// Every position, in the order a batch's runs nest (by Coordinate, then axis order):
  /// l, s, dh, the law's parameters, ramp_time, pbar.
  std::vector<std::size_t> nesting() const;
  /// The point at `values` (one per axis, in order) into `point`: the fields the axes set,
  /// the rest left as they are (C, the localization, a step's loading where no ramp_time).
  void set(std::span<const double> values, PointValues* point) const;

 private:
  std::vector<PointAxis> axes_;
  std::vector<std::size_t> law_;
};

/// Sets what `axis` sets in `point` to `value`.
void set_coordinate(const PointAxis& axis, double value, PointValues* point);

}  // namespace punchsweep::model
