#include "model/point/point_axes.hpp"

#include <algorithm>

#include "model/problem/load_shape.hpp"

namespace punchsweep::model {

PointAxes::PointAxes(std::span<const Parameter> law, bool ramp) {
  const auto problem = [&](std::string_view name, Coordinate coordinate) {
    axes_.push_back({problem_parameter(name), coordinate});
  };
  problem(kPitch, Coordinate::pitch);
  problem(kHeightDifference, Coordinate::height_difference);
  for (std::size_t j = 0; j < law.size(); ++j) {
    law_.push_back(axes_.size());
    axes_.push_back({&law[j], Coordinate::law, j});
  }
  problem(kPressure, Coordinate::pressure);
  problem(kExponent, Coordinate::exponent);
  if (ramp) axes_.push_back({&ramp_time_parameter(), Coordinate::ramp_time});
}

std::size_t PointAxes::find(Coordinate coordinate) const {
  std::size_t j = 0;
  while (j < axes_.size() && axes_[j].coordinate != coordinate) ++j;
  return j;
}

std::size_t PointAxes::find(std::string_view name) const {
  std::size_t j = 0;
  while (j < axes_.size() && axes_[j].parameter->name != name) ++j;
  return j;
}

std::vector<std::size_t> PointAxes::nesting() const {
  std::vector<std::size_t> order(axes_.size());
  for (std::size_t j = 0; j < order.size(); ++j) order[j] = j;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return axes_[a].coordinate < axes_[b].coordinate; });
  return order;
}

void PointAxes::set(std::span<const double> values, PointValues* point) const {
  point->law.resize(law_.size());
  for (std::size_t j = 0; j < axes_.size(); ++j) set_coordinate(axes_[j], values[j], point);
}

void set_coordinate(const PointAxis& axis, double value, PointValues* point) {
  ContactProblem& problem = point->problem;
  switch (axis.coordinate) {
    case Coordinate::pitch: problem.l = value; return;
    case Coordinate::exponent: problem.shape.s = static_cast<int>(value); return;
    case Coordinate::height_difference: problem.dh = value; return;
    case Coordinate::law: point->law.at(axis.law_index) = value; return;
    case Coordinate::ramp_time: problem.loading = LoadShape::ramp(value); return;
    case Coordinate::pressure: problem.pbar0 = value; return;
  }
}

}  // namespace punchsweep::model
