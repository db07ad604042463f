#pragma once
/// @file
/// A sample's mean, spread and band: what an ensemble of drawn textures (one per seed) says
/// of a quantity. Percentiles as numpy's default (linear between the order statistics:
/// position (n - 1) p); +infinity (a level that never touches) is a value like any other,
/// larger than every finite one: a mean or a percentile that reaches one is +infinity, the
/// spread of a sample holding one is undefined (NaN).

#include <cstddef>
#include <vector>

namespace punchsweep::model {

struct SampleStatistics {
  std::size_t n = 0;
  double mean = 0.0;
  double sd = 0.0;      ///< the sample standard deviation (n - 1 in the denominator; NaN for n < 2)
  double se = 0.0;      ///< the mean's standard error, sd / sqrt(n)
  double p5 = 0.0;      ///< the 5% percentile
  double median = 0.0;
  double p95 = 0.0;     ///< the 95% percentile
  std::size_t infinite = 0;  ///< how many values are +infinity
};

/// The `p` percentile (0 <= p <= 1) of `sorted` (ascending, not empty).
double percentile(const std::vector<double>& sorted, double p);

/// The statistics of `values` (not empty; no NaN). Throws std::invalid_argument otherwise.
SampleStatistics sample_statistics(std::vector<double> values);

}  // namespace punchsweep::model
