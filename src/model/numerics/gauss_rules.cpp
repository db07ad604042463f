#include "model/numerics/gauss_rules.hpp"

#include <gsl/gsl_integration.h>

#include <array>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

namespace punchsweep::model {
namespace {

constexpr int kMaxLegendreNodes = 128;
constexpr int kMaxLaguerreNodes = 32;

GaussRule make_legendre(int n) {
  gsl_integration_glfixed_table* table = gsl_integration_glfixed_table_alloc(n);
  GaussRule rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  for (int i = 0; i < n; ++i) {
    gsl_integration_glfixed_point(-1.0, 1.0, i, &rule.nodes[i], &rule.weights[i], table);
  }
  gsl_integration_glfixed_table_free(table);
  return rule;
}

GaussRule make_laguerre(int n) {
  // Weight (x - a)^alpha exp(-b (x - a)) on (a, inf) with a = 0, b = 1, alpha = 0.
  gsl_integration_fixed_workspace* w =
      gsl_integration_fixed_alloc(gsl_integration_fixed_laguerre, static_cast<std::size_t>(n), 0.0, 1.0, 0.0, 0.0);
  if (w == nullptr) throw std::runtime_error("GSL could not make the Gauss-Laguerre rule");
  GaussRule rule;
  const double* x = gsl_integration_fixed_nodes(w);
  const double* c = gsl_integration_fixed_weights(w);
  rule.nodes.assign(x, x + n);
  rule.weights.assign(c, c + n);
  gsl_integration_fixed_free(w);
  return rule;
}

template <int kMax>
const GaussRule& cached(int n, GaussRule (*make)(int), const char* name) {
  if (n < 1 || n > kMax) throw std::invalid_argument(std::string(name) + " order out of range");
  static std::array<std::once_flag, kMax + 1> once;
  static std::array<std::unique_ptr<GaussRule>, kMax + 1> rules;
  std::call_once(once[n], [n, make] { rules[n] = std::make_unique<GaussRule>(make(n)); });
  return *rules[n];
}

}  // namespace

const GaussRule& gauss_legendre(int n) { return cached<kMaxLegendreNodes>(n, make_legendre, "Gauss-Legendre"); }

const GaussRule& gauss_laguerre(int n) { return cached<kMaxLaguerreNodes>(n, make_laguerre, "Gauss-Laguerre"); }

}  // namespace punchsweep::model
