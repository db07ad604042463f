#include "model/numerics/sample_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace punchsweep::model {

double percentile(const std::vector<double>& sorted, double p) {
  const double h = static_cast<double>(sorted.size() - 1) * p;
  const std::size_t lo = static_cast<std::size_t>(std::floor(h));
  const double frac = h - static_cast<double>(lo);
  if (frac == 0.0 || lo + 1 >= sorted.size()) return sorted[lo];
  const double a = sorted[lo], b = sorted[lo + 1];
  if (!std::isfinite(b)) return std::numeric_limits<double>::infinity();
  return a + frac * (b - a);
}

SampleStatistics sample_statistics(std::vector<double> values) {
  if (values.empty()) throw std::invalid_argument("sample_statistics: no values");
  for (const double v : values) {
    if (std::isnan(v) || v == -std::numeric_limits<double>::infinity()) {
      throw std::invalid_argument("sample_statistics: a value that is NaN or -infinity");
    }
  }
  std::sort(values.begin(), values.end());
  SampleStatistics s;
  s.n = values.size();
  s.infinite = static_cast<std::size_t>(std::count_if(values.begin(), values.end(), [](double v) { return std::isinf(v); }));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (s.infinite > 0) {
    s.mean = std::numeric_limits<double>::infinity();
    s.sd = s.se = nan;
  } else {
    double sum = 0.0;
    for (const double v : values) sum += v;
    s.mean = sum / static_cast<double>(s.n);
    double squares = 0.0;
    for (const double v : values) squares += (v - s.mean) * (v - s.mean);
    s.sd = s.n > 1 ? std::sqrt(squares / static_cast<double>(s.n - 1)) : nan;
    s.se = s.sd / std::sqrt(static_cast<double>(s.n));
  }
  s.p5 = percentile(values, 0.05);
  s.median = percentile(values, 0.5);
  s.p95 = percentile(values, 0.95);
  return s;
}

}  // namespace punchsweep::model
