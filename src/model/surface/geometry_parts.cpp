#include "model/surface/geometry_parts.hpp"

#include <algorithm>
#include <memory>

namespace punchsweep::model {

std::vector<LevelTouch> GeometryParts::touches(const CreepWeightedLoad& load) const {
  return level_touches(touchdowns(), [this](std::size_t level) { return resolved(level); }, load);
}

namespace {

/// Calls at(k, load) for each of `n` points: point k takes columns[j][k] for each coordinate j
/// of `axes` that has a column, the creep law `spec` at its values and its load.
template <class At>
void for_each_point(const CreepLawSpec& spec, const PointAxes& axes, std::span<const double* const> columns, std::size_t n,
                    At&& at) {
  PointValues point;
  point.law.resize(axes.law().size());
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t j = 0; j < axes.size(); ++j) {
      if (columns[j] != nullptr) set_coordinate(axes[j], columns[j][k], &point);
    }
    const std::unique_ptr<CreepLaw> creep = make_creep_law(spec, point.law);
    at(k, CreepWeightedLoad(*creep, point.problem.pbar0, point.problem.loading));
  }
}

}  // namespace

void GeometryParts::touches_at(const CreepLawSpec& spec, const PointAxes& axes, std::span<const double* const> columns,
                               std::size_t n, double* t_star, std::int8_t* regime) const {
  const std::size_t L = static_cast<std::size_t>(levels());
  for_each_point(spec, axes, columns, n, [&](std::size_t k, const CreepWeightedLoad& load) {
    const std::vector<LevelTouch> level = touches(load);
    for (std::size_t q = 0; q < L; ++q) {
      t_star[k * L + q] = level[q].t_star;
      regime[k * L + q] = static_cast<std::int8_t>(level[q].regime);
    }
  });
}

double largest_final_load(const CreepLawSpec& spec, const PointAxes& axes, std::span<const double* const> columns,
                          std::size_t n) {
  double X = 0.0;
  for_each_point(spec, axes, columns, n, [&](std::size_t, const CreepWeightedLoad& load) { X = std::max(X, load.final()); });
  return X;
}

LocalizationParts::LocalizationParts(const ContactProblem& problem)
    : dh_(dh_parts(problem)), touchdowns_{0.0, dh_.touchdown.X_star} {}

bool CurveParts::resolved(std::size_t level) const { return touchdown_resolved(curve_, level); }

}  // namespace punchsweep::model
