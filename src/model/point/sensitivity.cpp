#include "model/point/sensitivity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/laws/material.hpp"
#include "model/numerics/number_text.hpp"
#include "model/localization/localization_model.hpp"
#include "model/contact/regime.hpp"

namespace punchsweep::model {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// A point with its real-valued parameters addressable by index: the problem's (l, dh,
/// pbar, C), then the law's real-valued ones.
struct Point {
  ContactProblem problem;
  const CreepLawSpec* law;
  std::vector<double> law_values;
  std::vector<const Parameter*> parameters;

  Point(const ContactProblem& p, const CreepLawSpec& l, std::span<const double> values)
      : problem(p), law(&l), law_values(values.begin(), values.end()) {
    for (const std::string_view name : {kPitch, kHeightDifference, kPressure, kShapeConstant}) {
      parameters.push_back(problem_parameter(name));
    }
    for (const Parameter& q : law->parameters) {
      if (!q.integer) parameters.push_back(&q);
    }
  }
  double* field(std::size_t k) {
    if (double* f = problem_field(problem, parameters[k]->name)) return f;
    for (std::size_t i = 0; i < law->parameters.size(); ++i) {
      if (&law->parameters[i] == parameters[k]) return &law_values[i];
    }
    return nullptr;
  }
  /// t* with parameter k at x (NaN where x is out of its range).
  double t_star_at(std::size_t k, double x) {
    if (!parameters[k]->admits(x)) return kNaN;
    double* f = field(k);
    const double keep = *f;
    *f = x;
    double t = kNaN;
    try {
      if (problem_error(problem).empty()) t = t_star_of(problem, *law, law_values);
    } catch (const std::invalid_argument&) {  // a law value its builder refuses (a shift's range)
    }
    *f = keep;
    return t;
  }
};

bool delayed(double t) { return std::isfinite(t) && t > 0.0; }

}  // namespace

double t_star_of(const ContactProblem& problem, const CreepLawSpec& law, std::span<const double> law_values) {
  const std::unique_ptr<CreepLaw> creep = make_creep_law(law, law_values);
  return classify(problem, *creep).t_star;
}

TStarDerivative t_star_derivative(const Parameter& parameter, double x, double t_star, bool temperature,
                                  const std::function<double(double)>& t_at) {
  TStarDerivative d{&parameter, x, kNaN, kNaN};
  const double h = kRelativeStep * (temperature ? std::max(std::abs(x), 1.0) : std::abs(x));
  if (!delayed(t_star) || !(h > 0.0)) return d;
  const double up = t_at(x + h), down = t_at(x - h), up2 = t_at(x + h / 2), down2 = t_at(x - h / 2);
  if (!(delayed(up) && delayed(down) && delayed(up2) && delayed(down2))) return d;
  const double coarse = (up - down) / (2 * h), fine = (up2 - down2) / h;
  // The two agree to kAgreement, or both are 0 to t*'s own precision.
  if (std::abs(coarse - fine) <= kAgreement * std::abs(fine) || std::abs(coarse - fine) * h <= 1e-12 * t_star) {
    d.derivative = (4 * fine - coarse) / 3;  // Richardson: the h^2 term of the central difference cancels
    if (!temperature) d.elasticity = d.derivative * x / t_star;
  }
  return d;
}

TStarDerivative t_star_derivative(const ContactProblem& problem, const CreepLaw& creep, std::string_view name,
                                  double t_star) {
  ContactProblem p = problem;
  double* field = problem_field(p, name);
  const Parameter& parameter = *problem_parameter(name);
  const double x = *field;
  return t_star_derivative(parameter, x, t_star, false, [&](double v) {
    if (!parameter.admits(v)) return kNaN;
    *field = v;
    const double t = problem_error(p).empty() ? classify(p, creep).t_star : kNaN;
    *field = x;
    return t;
  });
}

std::vector<TStarDerivative> t_star_derivatives(const ContactProblem& problem, const CreepLawSpec& law,
                                                std::span<const double> law_values, double t_star) {
  Point point(problem, law, law_values);
  // Along the problem's own parameters the law stays as it is: built once here, not at
  // every step (a Prony law's interconversion finds its roots on each build).
  const std::unique_ptr<CreepLaw> creep = make_creep_law(law, law_values);
  std::vector<TStarDerivative> out;
  for (std::size_t k = 0; k < point.parameters.size(); ++k) {
    const Parameter& p = *point.parameters[k];
    if (problem_field(point.problem, p.name) != nullptr) {
      out.push_back(t_star_derivative(problem, *creep, p.name, t_star));
      continue;
    }
    const bool temperature = p.name == temperature_parameter().name;
    out.push_back(t_star_derivative(p, *point.field(k), t_star, temperature,
                                    [&](double v) { return point.t_star_at(k, v); }));
  }
  return out;
}

Tolerance StatedTolerance::at(double value, bool* clipped) const {
  const double w = relative ? std::abs(value) * width : width;
  Tolerance t{parameter, w, w};
  const bool clip = value - w < 0.0 && parameter->admits(0.0) &&
                    !parameter->admits(-std::numeric_limits<double>::denorm_min());
  if (clip) t.minus = value;
  if (clipped) *clipped = clip;
  return t;
}

namespace {

// The position of `parameter` among the point's real-valued parameters.
std::size_t position(const Point& point, const Parameter* parameter) {
  const auto k = std::find(point.parameters.begin(), point.parameters.end(), parameter);
  if (k == point.parameters.end()) {
    throw std::invalid_argument("a tolerance on " + std::string(parameter ? parameter->name : "?") +
                                ", which is no real-valued parameter of this point");
  }
  return static_cast<std::size_t>(k - point.parameters.begin());
}

// t_star_range of `point` (its creep law `law` at `law_values`).
TStarRange range_over(Point& point, const CreepLawSpec& law, std::span<const double> law_values,
                      std::span<const Tolerance> tolerances) {
  std::vector<std::size_t> index;
  for (const Tolerance& tol : tolerances) {
    const std::size_t k = position(point, tol.parameter);
    const double x = *point.field(k);
    for (const double v : {x - tol.minus, x + tol.plus}) {
      if (!tol.parameter->admits(v)) {
        throw std::invalid_argument("the tolerance on " + std::string(tol.parameter->name) + " reaches " +
                                    number_text(v, 10) + ", outside its range: " + std::string(tol.parameter->range));
      }
    }
    index.push_back(k);
  }
  if (index.size() > kMaxTolerances) {
    throw std::invalid_argument("at most " + std::to_string(kMaxTolerances) + " tolerances (" +
                                std::to_string(1u << kMaxTolerances) + " corners)");
  }
  // The creep law is made once where no tolerance is on one of its parameters (making one,
  // a Prony series' interconversion, costs several classifications).
  const bool law_varies = std::any_of(index.begin(), index.end(), [&](std::size_t k) {
    return problem_field(point.problem, point.parameters[k]->name) == nullptr;
  });
  const std::unique_ptr<CreepLaw> fixed_law = law_varies ? nullptr : make_creep_law(law, law_values);
  TStarRange r;
  for (unsigned corner = 0; corner < (1u << index.size()); ++corner) {
    Point p = point;
    for (std::size_t j = 0; j < index.size(); ++j) {
      const double x = *point.field(index[j]);
      *p.field(index[j]) = (corner >> j) & 1u ? x + tolerances[j].plus : x - tolerances[j].minus;
    }
    const Classification c =
        classify(p.problem, fixed_law ? *fixed_law : *make_creep_law(*p.law, p.law_values));
    r.take(c.t_star, c.regime);
  }
  if (r.not_computed > 0) r.low = r.high = std::numeric_limits<double>::quiet_NaN();
  return r;
}

}  // namespace

void TStarRange::take(double t_star, Regime regime) {
  if (std::isnan(t_star)) {
    ++not_computed;
    return;
  }
  ++(regime == Regime::immediate ? immediate : regime == Regime::never ? never : delayed);
  // (Under a ramp an immediate touch has t* > 0: the regimes order as their t* do.)
  const bool first = immediate + delayed + never == 1;
  if (first || t_star < low || (t_star == low && regime < regime_low)) {
    low = t_star;
    regime_low = regime;
  }
  if (first || t_star > high || (t_star == high && regime > regime_high)) {
    high = t_star;
    regime_high = regime;
  }
}

TStarRange t_star_range(const ContactProblem& problem, const CreepLawSpec& law, std::span<const double> law_values,
                        std::span<const Tolerance> tolerances) {
  Point point(problem, law, law_values);
  return range_over(point, law, law_values, tolerances);
}

TStarRange t_star_range(const ContactProblem& problem, const CreepLawSpec& law, std::span<const double> law_values,
                        std::span<const StatedTolerance> stated) {
  Point point(problem, law, law_values);
  std::vector<Tolerance> box;
  for (const StatedTolerance& t : stated) box.push_back(t.at(*point.field(position(point, t.parameter))));
  return range_over(point, law, law_values, box);
}

std::string knife_edge_note(const std::vector<TStarDerivative>& derivatives) {
  const TStarDerivative* steepest = nullptr;
  for (const TStarDerivative& d : derivatives) {
    if (std::isfinite(d.elasticity) && (!steepest || std::abs(d.elasticity) > std::abs(steepest->elasticity))) steepest = &d;
  }
  if (!steepest || !(std::abs(steepest->elasticity) > kKnifeEdgeElasticity)) return {};
  char elasticity_text[64];  // three significant digits
  std::snprintf(elasticity_text, sizeof elasticity_text, "%.3g", steepest->elasticity);
  return "t* is on a knife edge: x/t* d t*/dx = " + std::string(elasticity_text) + " for " +
         std::string(steepest->parameter->name) + " (a 1% change moves t* by far more than 1%); --tolerance gives its range";
}

}  // namespace punchsweep::model
