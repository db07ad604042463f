#include "model/problem/parameter.hpp"

#include <array>
#include <cmath>
#include <sstream>

#include "model/problem/shape.hpp"

namespace punchsweep::model {
namespace {

constexpr std::array<Parameter, 5> kProblemParameters{{
    {kPitch, "R", "lattice pitch", "lattice pitch l, in R", "l > 0 (in R)", [](double v) { return v > 0.0; },
     false, {}, "linspace(0.5, 1.25, 7)"},
    {kHeightDifference, "R", "height difference of the punch levels",
     "height difference dh of the two punch levels, in R", "dh >= 0 (in R)", [](double v) { return v >= 0.0; },
     false, {}, "linspace(0.01, 0.12, 23)"},
    {kPressure, "E0/(1-nu^2)", "nominal pressure", "constant nominal pressure pbar0, in E0* = E0/(1-nu^2)",
     "pbar > 0 (in E0* = E0/(1-nu^2))", [](double v) { return v > 0.0; }, false, {}, "logspace(0.005, 0.08, 24)"},
    {kExponent, "1", "shape exponent", "shape exponent s of f(r) = C r^s / R^(s-1) (1 cone, 2 paraboloid)",
     "an integer in [1, 32]",
     [](double v) { return v >= Shape::kMinExponent && v <= Shape::kMaxExponent; }, true, {}, "1, 2, 3"},
    {kShapeConstant, "1", "shape constant", "shape constant C of f(r) (dimensionless; sphere: s = 2, C = 0.5)",
     "C > 0", [](double v) { return v > 0.0; }, false, "0.5", {}},
}};

/// A texture's lengths beyond the two-level problem's (`surface`, `surface-map`).
constexpr std::array<Parameter, 3> kTextureParameters{{
    {kThirdLevelDrop, "R", "drop of the third level", "how far level 2 lies below the tallest tips, in R",
     "dh2 >= 0 (in R)", [](double v) { return v >= 0.0; }},
    {kScatterWidth, "R", "width of the caps' height scatter",
     "the standard deviation (normal) or half-width (uniform) of the caps' height changes, in R",
     "a width >= 0 (in R)", [](double v) { return v >= 0.0; }},
    // As a map's axis its values are doubles: whole numbers up to 2^53 (--seed alone takes
    // any 64-bit seed).
    {kScatterSeed, "1", "seed of the scatter's draws", "the seed of --scatter's draws (std::mt19937_64)",
     "an integer in [0, 2^53]", [](double v) { return v >= 0.0 && v <= 9007199254740992.0; }, true},
}};

}  // namespace

bool Parameter::admits(double value) const {
  return std::isfinite(value) && (!integer || value == std::floor(value)) && in_range(value);
}

std::string Parameter::error(double value) const {
  if (admits(value)) return {};
  std::ostringstream out;
  out.precision(17);
  out << long_name << ' ' << name << " = " << value << " is outside its range: " << range;
  return out.str();
}

std::span<const Parameter> problem_parameters() { return kProblemParameters; }

const Parameter* problem_parameter(std::string_view name) {
  for (const Parameter& p : kProblemParameters) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

const Parameter* texture_parameter(std::string_view name) {
  for (const Parameter& p : kTextureParameters) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

std::string shape_error(const Shape& shape) {
  if (std::string e = problem_parameter(kExponent)->error(shape.s); !e.empty()) return e;
  return problem_parameter(kShapeConstant)->error(shape.C);
}

}  // namespace punchsweep::model
