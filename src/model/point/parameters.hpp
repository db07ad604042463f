#pragma once
/// @file
/// Every parameter a point or a sweep may be given, found by name: the contact problem's
/// (problem/parameter.hpp, where Parameter is declared), every creep law's, a material's
/// temperature and the load's ramp_time; and a sweep's axes in their order.

#include <span>
#include <string_view>
#include <vector>

#include "model/problem/parameter.hpp"

namespace punchsweep::model {

/// The parameter called `name` among the problem's, every creep law's, a material's
/// (temperature) and the load's (ramp_time); nullptr if none.
const Parameter* find_parameter(std::string_view name);

/// A sweep's axes for a creep law with parameters `law`: the parameters of
/// PointAxes(law, false) (point_axes.hpp), l, dh, the law's parameters, pbar, s (for the
/// standard linear solid: l, dh, T, pbar, s).
std::vector<const Parameter*> sweep_axes(std::span<const Parameter> law);

}  // namespace punchsweep::model
