#include "fit/prony_fit.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "fit/nnls.hpp"
#include "model/numerics/number_text.hpp"

namespace punchsweep::fit {

double PronyTerms::storage(double omega) const {
  double s = E_inf;
  for (std::size_t i = 0; i < E.size(); ++i) {
    const double wt = omega * tau[i];
    s += E[i] * wt * wt / (1.0 + wt * wt);
  }
  return s;
}

double PronyTerms::loss(double omega) const {
  double s = 0.0;
  for (std::size_t i = 0; i < E.size(); ++i) {
    const double wt = omega * tau[i];
    s += E[i] * wt / (1.0 + wt * wt);
  }
  return s;
}

double PronyTerms::relaxation(double t) const {
  double s = E_inf;
  for (std::size_t i = 0; i < E.size(); ++i) s += E[i] * std::exp(-t / tau[i]);
  return s;
}

namespace {

enum class Quantity { storage, loss, relaxation };

/// One reading: what it measures, where, its value, and the square root of its weight (the
/// factor on its residual).
struct Reading {
  Quantity what;
  double x;
  double value;
  double root_weight = 1.0;
};

/// The least-squares problem over given relaxation times: rows are the readings' relative
/// residuals (model / value - 1), then the smoothing penalty's; columns E_inf and the E_i,
/// in units of `scale` (the median reading) so the matrix is of order one.
class Problem {
 public:
  Problem(std::vector<Reading> readings, double smoothing) : readings_(std::move(readings)), smoothing_(smoothing) {
    std::vector<double> v;
    for (const Reading& r : readings_) v.push_back(r.value);
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    scale_ = v[v.size() / 2];
  }

  std::size_t size() const { return readings_.size(); }
  const std::vector<Reading>& readings() const { return readings_; }

  /// Weights (E_inf, E_i in Pa) >= 0 at times `tau`, and the residual vector.
  struct Solution {
    Eigen::VectorXd weights;
    Eigen::VectorXd residual;
    double rss = 0.0;  ///< over the readings only
  };
  Solution solve(const std::vector<double>& tau) const {
    const auto m = static_cast<Eigen::Index>(tau.size());
    const auto n = static_cast<Eigen::Index>(readings_.size());
    const Eigen::Index penalties = smoothing_ > 0.0 && m >= 3 ? m - 2 : 0;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n + penalties, m + 1);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(n + penalties);
    for (Eigen::Index r = 0; r < n; ++r) {
      const Reading& d = readings_[static_cast<std::size_t>(r)];
      const double w = scale_ / d.value * d.root_weight;
      A(r, 0) = d.what == Quantity::loss ? 0.0 : w;
      for (Eigen::Index i = 0; i < m; ++i) {
        const double t = tau[static_cast<std::size_t>(i)];
        const double wt = d.x * t;
        A(r, i + 1) = w * (d.what == Quantity::storage ? wt * wt / (1.0 + wt * wt)
                           : d.what == Quantity::loss  ? wt / (1.0 + wt * wt)
                                                       : std::exp(-d.x / t));
      }
      b(r) = d.root_weight;
    }
    const double s = std::sqrt(smoothing_);
    for (Eigen::Index k = 0; k < penalties; ++k) {
      A(n + k, k + 1) = s;
      A(n + k, k + 2) = -2.0 * s;
      A(n + k, k + 3) = s;
    }
    // Unconstrained first (the usual case once the times are set); NNLS where a weight
    // would be negative.
    Eigen::VectorXd x = A.colPivHouseholderQr().solve(b);
    if ((x.array() < 0.0).any()) x = nnls(A, b);
    Solution sol;
    sol.residual = A * x - b;
    sol.rss = sol.residual.head(n).squaredNorm();
    sol.weights = x * scale_;
    return sol;
  }

 private:
  std::vector<Reading> readings_;
  double smoothing_;
  double scale_ = 1.0;
};

PronyTerms terms_of(const std::vector<double>& tau, const Eigen::VectorXd& weights) {
  PronyTerms t;
  t.E_inf = weights(0);
  for (std::size_t i = 0; i < tau.size(); ++i) {
    const double e = weights(static_cast<Eigen::Index>(i) + 1);
    if (e > 0.0) {
      t.E.push_back(e);
      t.tau.push_back(tau[i]);
    }
  }
  return t;
}

double bic(double rss, std::size_t n, std::size_t terms) {
  const double nn = static_cast<double>(n);
  return nn * std::log(std::max(rss, 1e-300) / nn) + static_cast<double>(2 * terms + 1) * std::log(nn);
}

/// Levenberg-Marquardt over log10 tau with a forward-difference Jacobian, the weights
/// re-solved at every evaluation (variable projection).
std::vector<double> refine_times(const Problem& problem, std::vector<double> tau) {
  const auto p = static_cast<Eigen::Index>(tau.size());
  Eigen::VectorXd theta(p);
  for (Eigen::Index i = 0; i < p; ++i) theta(i) = std::log10(tau[static_cast<std::size_t>(i)]);
  const auto times = [](const Eigen::VectorXd& th) {
    std::vector<double> t;
    for (Eigen::Index i = 0; i < th.size(); ++i) t.push_back(std::pow(10.0, th(i)));
    return t;
  };
  Eigen::VectorXd r = problem.solve(times(theta)).residual;
  double cost = r.squaredNorm();
  double mu = 1e-3;
  constexpr double kStep = 1e-6;  // decades
  for (int iteration = 0; iteration < 60; ++iteration) {
    Eigen::MatrixXd J(r.size(), p);
    for (Eigen::Index i = 0; i < p; ++i) {
      Eigen::VectorXd th = theta;
      th(i) += kStep;
      J.col(i) = (problem.solve(times(th)).residual - r) / kStep;
    }
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    bool improved = false;
    for (int tries = 0; tries < 12 && !improved; ++tries) {
      Eigen::MatrixXd M = JtJ;
      M.diagonal() += mu * JtJ.diagonal().cwiseMax(1e-12);
      const Eigen::VectorXd step = -M.ldlt().solve(g);
      const Eigen::VectorXd trial = theta + step.cwiseMax(-1.0).cwiseMin(1.0);
      const Eigen::VectorXd rt = problem.solve(times(trial)).residual;
      const double ct = rt.squaredNorm();
      if (std::isfinite(ct) && ct < cost) {
        const double gain = (cost - ct) / cost;
        theta = trial;
        r = rt;
        cost = ct;
        mu = std::max(mu / 3.0, 1e-9);
        improved = true;
        if (gain < 1e-10) return times(theta);
      } else {
        mu *= 4.0;
      }
    }
    if (!improved) break;
  }
  return times(theta);
}

PronyFit fit(std::vector<Reading> readings, double lo, double hi, const PronyOptions& options, bool frequency) {
  if (readings.size() < 4) {
    throw std::invalid_argument("too few readings to fit a Prony series (" + std::to_string(readings.size()) +
                                "; 4 or more)");
  }
  for (const Reading& r : readings) {
    if (!(std::isfinite(r.x) && r.x > 0.0 && std::isfinite(r.value) && r.value > 0.0)) {
      throw std::invalid_argument("a reading is not finite and > 0 (abscissa " + model::number_text(r.x, 6) +
                                  ", modulus " + model::number_text(r.value, 6) + " Pa)");
    }
  }
  if (!(hi > lo)) throw std::invalid_argument("the readings span no range of " + std::string(frequency ? "frequency" : "time"));
  const Problem problem(std::move(readings), options.smoothing);
  PronyFit out;
  out.residuals = static_cast<int>(problem.size());
  std::vector<double> best_tau;
  double best_bic = std::numeric_limits<double>::infinity();
  const double decades = std::log10(hi / lo);
  for (const double density : options.per_decade) {
    const int m = std::max(1, static_cast<int>(std::ceil(decades * density))) + 1;
    std::vector<double> tau;
    for (int i = 0; i < m; ++i) tau.push_back(lo * std::pow(10.0, decades * i / (m - 1)));
    const Problem::Solution s = problem.solve(tau);
    const PronyTerms t = terms_of(tau, s.weights);
    PronyCandidate c{density, m, static_cast<int>(t.E.size()), s.rss, bic(s.rss, problem.size(), t.E.size())};
    out.candidates.push_back(c);
    if (c.bic < best_bic) {
      best_bic = c.bic;
      best_tau = t.tau;
      out.chosen = out.candidates.size() - 1;
    }
  }
  std::vector<double> tau = best_tau;
  // Times the refinement drives within 1% of each other are one term (two there are a
  // degenerate pair whose weights trade off, a valley along which the refinement crawls
  // and stops where rounding leaves it): merged, and the times refined again without the
  // pair, until no two meet.
  const auto merge = [](std::vector<double>& t) {
    std::sort(t.begin(), t.end());
    const std::size_t before = t.size();
    t.erase(std::unique(t.begin(), t.end(), [](double a, double b) { return b - a <= 0.01 * b; }), t.end());
    return t.size() < before;
  };
  for (int round = 0; round < 8; ++round) {
    if (!(options.refine && !tau.empty() && problem.size() > tau.size() + 1)) break;
    tau = refine_times(problem, tau);
    if (!merge(tau)) break;
  }
  merge(tau);
  const Problem::Solution s = problem.solve(tau);
  out.terms = terms_of(tau, s.weights);
  out.rss = s.rss;
  out.bic = bic(s.rss, problem.size(), out.terms.E.size());
  // RMS relative errors per quantity.
  double s1 = 0.0, s2 = 0.0;
  int n1 = 0, n2 = 0;
  for (const Reading& r : problem.readings()) {
    const double model = r.what == Quantity::storage ? out.terms.storage(r.x)
                         : r.what == Quantity::loss  ? out.terms.loss(r.x)
                                                     : out.terms.relaxation(r.x);
    const double e = model / r.value - 1.0;
    if (r.what == Quantity::loss) {
      s2 += e * e;
      ++n2;
    } else {
      s1 += e * e;
      ++n1;
    }
  }
  out.rms_first = n1 ? std::sqrt(s1 / n1) : 0.0;
  out.rms_second = n2 ? std::sqrt(s2 / n2) : 0.0;
  return out;
}

void check_sizes(std::size_t a, std::size_t b, const char* what) {
  if (a != b) throw std::invalid_argument(std::string("the readings' ") + what + " differ in length");
}

/// The square roots of `weights` (each 1 where empty), checked: as many as the readings,
/// each finite and > 0.
std::vector<double> root_weights(std::span<const double> weights, std::size_t n) {
  if (weights.empty()) return std::vector<double>(n, 1.0);
  check_sizes(n, weights.size(), "abscissae and weights");
  std::vector<double> roots;
  for (const double w : weights) {
    if (!(std::isfinite(w) && w > 0.0)) throw std::invalid_argument("a reading's weight is not finite and > 0");
    roots.push_back(std::sqrt(w));
  }
  return roots;
}

}  // namespace

PronyFit fit_prony_frequency(std::span<const double> omega, std::span<const double> storage,
                             std::span<const double> loss, const PronyOptions& options,
                             std::span<const double> weights) {
  check_sizes(omega.size(), storage.size(), "frequencies and storage moduli");
  check_sizes(omega.size(), loss.size(), "frequencies and loss moduli");
  const std::vector<double> roots = root_weights(weights, omega.size());
  std::vector<Reading> readings;
  for (std::size_t i = 0; i < omega.size(); ++i) {
    readings.push_back({Quantity::storage, omega[i], storage[i], roots[i]});
    readings.push_back({Quantity::loss, omega[i], loss[i], roots[i]});
  }
  const auto [lo, hi] = std::minmax_element(omega.begin(), omega.end());
  return fit(std::move(readings), omega.empty() ? 1.0 : 1.0 / *hi, omega.empty() ? 0.0 : 1.0 / *lo, options, true);
}

PronyFit fit_prony_relaxation(std::span<const double> t, std::span<const double> modulus, const PronyOptions& options,
                              std::span<const double> weights) {
  check_sizes(t.size(), modulus.size(), "times and moduli");
  const std::vector<double> roots = root_weights(weights, t.size());
  std::vector<Reading> readings;
  for (std::size_t i = 0; i < t.size(); ++i) readings.push_back({Quantity::relaxation, t[i], modulus[i], roots[i]});
  const auto [lo, hi] = std::minmax_element(t.begin(), t.end());
  return fit(std::move(readings), t.empty() ? 1.0 : *lo, t.empty() ? 0.0 : *hi, options, false);
}

}  // namespace punchsweep::fit
