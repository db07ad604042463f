#include "model/point/parameters.hpp"

#include "model/laws/creep_laws.hpp"
#include "model/laws/material.hpp"
#include "model/point/point_axes.hpp"
#include "model/problem/load_shape.hpp"

namespace punchsweep::model {

const Parameter* find_parameter(std::string_view name) {
  if (const Parameter* p = problem_parameter(name)) return p;
  for (const CreepLawSpec& law : creep_laws()) {
    for (const Parameter& p : law.parameters) {
      if (p.name == name) return &p;
    }
  }
  for (const Parameter* p : {&material_parameter(), &temperature_parameter(), &ramp_time_parameter()}) {
    if (p->name == name) return p;
  }
  return nullptr;
}

std::vector<const Parameter*> sweep_axes(std::span<const Parameter> law) {
  std::vector<const Parameter*> axes;
  for (const PointAxis& axis : PointAxes(law, false)) axes.push_back(axis.parameter);
  return axes;
}

}  // namespace punchsweep::model
