#include "model/gauss_legendre.hpp"

#include <gsl/gsl_integration.h>

#include <array>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace punchsweep::model {
namespace {

constexpr int kMaxNodes = 128;

GaussLegendreRule make_rule(int n) {
  gsl_integration_glfixed_table* table = gsl_integration_glfixed_table_alloc(n);
  GaussLegendreRule rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  for (int i = 0; i < n; ++i) {
    gsl_integration_glfixed_point(-1.0, 1.0, i, &rule.nodes[i], &rule.weights[i], table);
  }
  gsl_integration_glfixed_table_free(table);
  return rule;
}

}  // namespace

const GaussLegendreRule& gauss_legendre(int n) {
  if (n < 1 || n > kMaxNodes) throw std::invalid_argument("Gauss-Legendre order out of range");
  static std::array<std::once_flag, kMaxNodes + 1> once;
  static std::array<std::unique_ptr<GaussLegendreRule>, kMaxNodes + 1> rules;
  std::call_once(once[n], [n] { rules[n] = std::make_unique<GaussLegendreRule>(make_rule(n)); });
  return *rules[n];
}

}  // namespace punchsweep::model
