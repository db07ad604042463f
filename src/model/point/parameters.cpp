#include "model/point/parameters.hpp"

#include "model/laws/creep_laws.hpp"
#include "model/laws/material.hpp"
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
  const auto problem = [](std::string_view name) { return find_parameter(name); };
  std::vector<const Parameter*> axes{problem(kPitch), problem(kHeightDifference)};
  for (const Parameter& p : law) axes.push_back(&p);
  axes.push_back(problem(kPressure));
  axes.push_back(problem(kExponent));
  return axes;
}

}  // namespace punchsweep::model
