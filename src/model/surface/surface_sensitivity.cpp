#include "model/surface/surface_sensitivity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "model/load/creep_weighted_load.hpp"
#include "model/point/parameters.hpp"
#include "model/surface/surface_history.hpp"

namespace punchsweep::model {

namespace {

/// Which input a parameter is: -1 the pressure, j >= 0 the law's j-th; -2 neither.
int input_index(const SurfaceLoad& load, const Parameter* parameter) {
  if (parameter == find_parameter(kPressure)) return -1;
  for (std::size_t j = 0; j < load.law->parameters.size(); ++j) {
    if (&load.law->parameters[j] == parameter || load.law->parameters[j].name == parameter->name) return static_cast<int>(j);
  }
  return -2;
}

/// The load with input `index` set to x (NaN-free: a value out of range gives nullopt).
bool with_input(SurfaceLoad& load, int index, double x) {
  const Parameter& p = index < 0 ? *find_parameter(kPressure) : load.law->parameters[static_cast<std::size_t>(index)];
  if (!p.admits(x)) return false;
  (index < 0 ? load.pbar0 : load.law_values[static_cast<std::size_t>(index)]) = x;
  return true;
}

Regime level_regime(const LoadCurve& curve, int level, const SurfaceLoad& load, double* t_star) {
  const std::unique_ptr<CreepLaw> creep = make_creep_law(*load.law, load.law_values);
  const CreepWeightedLoad X(*creep, load.pbar0, load.shape);
  const LevelTouch touch = level_touches(curve, X)[static_cast<std::size_t>(level)];
  *t_star = touch.t_star;
  return touch.regime;
}

}  // namespace

double level_t_star(const LoadCurve& curve, int level, const SurfaceLoad& load) {
  double t = 0.0;
  level_regime(curve, level, load, &t);
  return t;
}

std::vector<TStarDerivative> level_t_star_derivatives(const LoadCurve& curve, int level, const SurfaceLoad& load,
                                                      double t_star) {
  std::vector<const Parameter*> inputs{find_parameter(kPressure)};
  for (const Parameter& p : load.law->parameters) inputs.push_back(&p);
  std::vector<TStarDerivative> out;
  for (const Parameter* p : inputs) {
    const int index = input_index(load, p);
    const double x = index < 0 ? load.pbar0 : load.law_values[static_cast<std::size_t>(index)];
    const bool temperature = p->name == "temperature";
    out.push_back(t_star_derivative(*p, x, t_star, temperature, [&](double value) {
      SurfaceLoad moved = load;
      if (!with_input(moved, index, value)) return std::numeric_limits<double>::quiet_NaN();
      return level_t_star(curve, level, moved);
    }));
  }
  return out;
}

namespace {

/// Calls corner(load) for the load at each corner of `tolerances` (std::invalid_argument
/// naming a tolerance on another input than the load's, or one a corner takes out of range).
template <class Corner>
void for_each_corner(const SurfaceLoad& load, std::span<const Tolerance> tolerances, Corner&& corner) {
  if (tolerances.size() > kMaxTolerances) throw std::invalid_argument("at most 6 tolerances");
  std::vector<int> index;
  for (const Tolerance& t : tolerances) {
    index.push_back(input_index(load, t.parameter));
    if (index.back() == -2) {
      throw std::invalid_argument(std::string(t.parameter->name) +
                                  ": a tolerance on the texture's geometry needs a load curve per corner; surface takes "
                                  "tolerances on the pressure and the creep law's parameters");
    }
  }
  const std::size_t corners = std::size_t{1} << tolerances.size();
  for (std::size_t c = 0; c < corners; ++c) {
    SurfaceLoad moved = load;
    for (std::size_t k = 0; k < tolerances.size(); ++k) {
      const double base = index[k] < 0 ? load.pbar0 : load.law_values[static_cast<std::size_t>(index[k])];
      const double x = (c >> k) & 1 ? base + tolerances[k].plus : base - tolerances[k].minus;
      if (!with_input(moved, index[k], x)) {
        throw std::invalid_argument(std::string(tolerances[k].parameter->name) + " = " + std::to_string(x) +
                                    " at a corner of the tolerances is outside its range: " +
                                    std::string(tolerances[k].parameter->range));
      }
    }
    const std::unique_ptr<CreepLaw> creep = make_creep_law(*moved.law, moved.law_values);
    corner(CreepWeightedLoad(*creep, moved.pbar0, moved.shape));
  }
}

}  // namespace

std::vector<TStarRange> level_t_star_ranges(const LoadCurve& curve, const SurfaceLoad& load,
                                            std::span<const Tolerance> tolerances) {
  std::vector<TStarRange> ranges(static_cast<std::size_t>(curve.levels()));
  // Every level's touch at each corner from one creep law and one reading of the curve.
  for_each_corner(load, tolerances, [&](const CreepWeightedLoad& X) {
    const std::vector<LevelTouch> touches = level_touches(curve, X);
    for (std::size_t level = 0; level < ranges.size(); ++level) ranges[level].take(touches[level].t_star, touches[level].regime);
  });
  return ranges;
}

double largest_final_load(const SurfaceLoad& load, std::span<const Tolerance> tolerances) {
  const std::unique_ptr<CreepLaw> creep = make_creep_law(*load.law, load.law_values);
  double X = CreepWeightedLoad(*creep, load.pbar0, load.shape).final();
  if (!tolerances.empty()) for_each_corner(load, tolerances, [&](const CreepWeightedLoad& corner) { X = std::max(X, corner.final()); });
  return X;
}

}  // namespace punchsweep::model
