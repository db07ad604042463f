#include "model/load/load_history.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Core>

#include "model/numerics/gauss_rules.hpp"
#include "model/laws/relaxation_integral.hpp"

namespace punchsweep::model {
namespace {

/// The terms k >= first of a relaxation series (without E(inf)) as the kernel of a history
/// integral (relaxation_integral_mapped): the terms too slow for the Gauss-Laguerre sum.
class SeriesTail {
 public:
  SeriesTail(const RelaxationSeries& series, std::size_t first, double creep_time_scale)
      : terms_(series.terms), first_(first), creep_time_scale_(creep_time_scale) {}
  double relaxation(double age) const {
    double e = 0.0;
    for (std::size_t k = first_; k < terms_.size(); ++k) e += terms_[k].E * decay(age, k);
    return e;
  }
  double relaxation_rate(double age) const {
    double rate = 0.0;
    for (std::size_t k = first_; k < terms_.size(); ++k) rate -= terms_[k].E / terms_[k].tau * decay(age, k);
    return rate;
  }
  double relaxation_time_scale() const { return terms_[first_].tau; }
  double creep_time_scale() const { return creep_time_scale_; }
  /// As ExponentialSeriesLaw::relaxation_memory.
  double relaxation_memory() const { return kForgetting * terms_.back().tau; }
  bool singular_at_zero() const { return false; }

 private:
  /// exp(-age/tau_k), left out (0) from kNegligibleDecay on, as ExponentialSeriesLaw does.
  double decay(double age, std::size_t k) const {
    const double x = age / terms_[k].tau;
    return x < kNegligibleDecay ? std::exp(-x) : 0.0;
  }
  const std::vector<RelaxationSeries::Term>& terms_;
  std::size_t first_;
  double creep_time_scale_;
};

/// Appends panel edges after edges.back() up to `end`, each at step(previous edge). No
/// sliver at the end: a last step under half a panel joins the one before.
template <class Step>
void extend_edges(std::vector<double>& edges, double end, Step&& step) {
  while (edges.back() < end) {
    const double v = edges.back();
    double next = step(v);
    if (end - next < 0.5 * (next - v)) next = end;
    edges.push_back(next);
  }
}

}  // namespace

LoadHistory::LoadHistory(const CreepWeightedLoad& load, double level1_load, double t0, double t_end,
                         const HistoryQuadrature& quadrature, const Sampler& sample)
    : load_(load),
      creep_(load.creep()),
      series_(load.creep().relaxation_series()),
      level1_load_(level1_load),
      t0_(t0),
      n_(quadrature.nodes_per_panel) {
  const GaussRule& rule = gauss_legendre(n_);
  nodes_ = rule.nodes;
  bary_.resize(n_);
  for (int j = 0; j < n_; ++j) {
    double w = 1.0;
    for (int k = 0; k < n_; ++k) {
      if (k != j) w /= nodes_[j] - nodes_[k];
    }
    bary_[j] = w;
  }
  const double v_end = std::sqrt(std::max(t_end - t0, 0.0));
  const double width = quadrature.panel_width * std::sqrt(creep_.creep_time_scale());
  kinks_ = load.shape().kinks();
  // Stretches of v between the load's kinks after t0, each cut into equal panels. Once the
  // load has settled (X = X(inf) to rounding), Q is constant: one panel holds the rest.
  std::vector<double> edges{0.0};
  for (const double k : kinks_) {
    if (k > t0 && k < t_end) edges.push_back(std::sqrt(k - t0));
  }
  const double t_settled = load.settled_time();
  const bool settles = t_settled > t0 && t_settled < t_end;
  if (settles) edges.push_back(std::sqrt(t_settled - t0));
  edges.push_back(v_end);
  const double growth = kPanelGrowth * quadrature.panel_width / HistoryQuadrature{}.panel_width;
  for (std::size_t j = 0; j + 1 < edges.size(); ++j) {
    const double length = edges[j + 1] - edges[j];
    Stretch stretch;
    stretch.v_start = edges[j];
    stretch.first_panel = panels_;
    const bool settled = settles && j + 2 == edges.size();
    stretch.panels = settled ? 1 : std::max(1, static_cast<int>(std::ceil(length / width)));
    stretch.width = std::max(length, 1e-300) / stretch.panels;
    // Under a power law J ~ t^n, so Q ~ v^(2n) at v = 0 when the two-level phase starts at
    // t = 0: panels shrink 4-fold towards it (kSingularLevels of them) before the rest.
    const bool singular_start = j == 0 && t0 == 0.0 && creep_.singular_at_zero();
    if (j > 0 && !settled) {
      // After a kink of the load every retardation term starts again: Q is smooth in tau
      // there but varies on the shortest creep time near the kink. The panels are laid out
      // as the first stretch's from touchdown, in u = sqrt(tau - tau_kink) (uniform, or
      // graded past kMaxUniformPanels), and mapped to v = sqrt(v_kink^2 + u^2).
      const double v_kink = edges[j];
      const double u_end = std::sqrt((edges[j + 1] - v_kink) * (edges[j + 1] + v_kink));
      const int uniform = std::max(1, static_cast<int>(std::ceil(u_end / width)));
      const bool graded = uniform > kMaxUniformPanels && growth * u_end > width;
      std::vector<double> u{0.0};
      extend_edges(u, u_end, [&](double at) {
        return graded ? at + std::max(width, growth * at) : at + u_end / uniform;
      });
      stretch.edges.push_back(v_kink);
      for (std::size_t k = 1; k + 1 < u.size(); ++k) stretch.edges.push_back(std::sqrt(v_kink * v_kink + u[k] * u[k]));
      stretch.edges.push_back(edges[j + 1]);
      stretch.panels = static_cast<int>(stretch.edges.size()) - 1;
    } else if (!settled &&
               (singular_start || (stretch.panels > kMaxUniformPanels && growth * edges[j + 1] > width))) {
      // Graded: panels of the uniform width until the growth exceeds it, then growing.
      stretch.edges.push_back(edges[j]);
      if (singular_start) {
        const double first = std::min(width, edges[1]);
        for (int k = kSingularLevels; k >= 0; --k) stretch.edges.push_back(first * std::pow(0.25, k));
      }
      extend_edges(stretch.edges, edges[j + 1], [&](double v) { return v + std::max(width, growth * v); });
      stretch.panels = static_cast<int>(stretch.edges.size()) - 1;
    }
    panels_ += stretch.panels;
    stretches_.push_back(stretch);
  }
  Q1_.resize(static_cast<std::size_t>(panels_) * n_);
  Q2_.resize(Q1_.size());
  for (const Stretch& stretch : stretches_) {
    for (int p = 0; p < stretch.panels && ok_; ++p) {
      for (int j = 0; j < n_ && ok_; ++j) {
        const double v = stretch.edges.empty()
                             ? stretch.v_start + (p + 0.5 * (nodes_[j] + 1.0)) * stretch.width
                             : stretch.panel_start(p) + 0.5 * (nodes_[j] + 1.0) * stretch.panel_width(p);
        const std::size_t i = static_cast<std::size_t>(stretch.first_panel + p) * n_ + j;
        ok_ = sample(t0 + v * v, &Q1_[i], &Q2_[i]);
      }
    }
  }
}

const LoadHistory::Stretch& LoadHistory::stretch_of(int panel) const {
  std::size_t j = stretches_.size() - 1;
  while (j > 0 && panel < stretches_[j].first_panel) --j;
  return stretches_[j];
}

int LoadHistory::panel_at(double v) const {
  std::size_t j = stretches_.size() - 1;
  while (j > 0 && v < stretches_[j].v_start) --j;
  const Stretch& s = stretches_[j];
  if (!s.edges.empty()) {
    const auto above = std::upper_bound(s.edges.begin(), s.edges.end(), v);
    const int relative = static_cast<int>(above - s.edges.begin()) - 1;
    return s.first_panel + std::clamp(relative, 0, s.panels - 1);
  }
  return s.first_panel + std::min(static_cast<int>((v - s.v_start) / s.width), s.panels - 1);
}

double LoadHistory::panel_start(int panel) const {
  const Stretch& s = stretch_of(panel);
  return s.panel_start(panel - s.first_panel);
}

void LoadHistory::interpolate(const Stretch& s, int panel, double v, double* Q1, double* Q2) const {
  const int relative = panel - s.first_panel;
  const double xi = s.edges.empty() ? 2.0 * ((v - s.v_start) / s.width - relative) - 1.0
                                    : 2.0 * (v - s.panel_start(relative)) / s.panel_width(relative) - 1.0;
  const std::size_t base = static_cast<std::size_t>(panel) * n_;
  interpolate_nodes(&Q1_[base], &Q2_[base], xi, Q1, Q2);
}

LoadHistory::Cost LoadHistory::cost(const CreepWeightedLoad& load, double t0, double t_end,
                                    const HistoryQuadrature& quadrature) {
  const CreepLaw& creep = load.creep();
  // Past the settled time one panel holds the rest (the constructor's layout).
  const double v_end = std::sqrt(std::max(std::min(t_end, load.settled_time()) - t0, 0.0));
  const double width = quadrature.panel_width * std::sqrt(creep.creep_time_scale());
  Cost c;
  // Panels: uniform, or graded past kMaxUniformPanels (5 of the uniform width, then a
  // factor 1 + kPanelGrowth each).
  double panels = std::ceil(v_end / width);
  const double growth = kPanelGrowth * quadrature.panel_width / HistoryQuadrature{}.panel_width;
  if (panels > kMaxUniformPanels && growth * v_end > width) {
    panels = std::min(panels, 1.0 / growth + std::log(v_end * growth / width) / std::log1p(growth) + 1.0);
  }
  // Each stretch after a kink is laid out afresh from the kink (at most as many panels as
  // the first), and a settled load adds one.
  const double kinks = static_cast<double>(load.shape().kinks().size());
  c.samples = (panels * (1.0 + kinks) + 1.0) * quadrature.nodes_per_panel;
  // The kernel pieces of the wide form over the memory window, uniform or graded by age as
  // relaxation_integral_mapped cuts them (the narrow form samples Q afresh, a handful).
  const double window = std::min(creep.relaxation_memory(), t_end);
  const double panel_span = (2.0 * v_end + width) * width;
  const double span = kernel_piece_span(creep);
  double pieces = std::ceil(window / span);
  if (pieces > kMaxUniformKernelPieces) {
    pieces = 1.0 / kAgeRatio + std::log(window * kAgeRatio / span) / std::log1p(kAgeRatio) + 1.0;
  }
  // The pieces restart at each panel's edge, so each panel adds about one.
  c.kernel_pieces = creep.relaxation_memory() < panel_span ? 0.0 : pieces + panels;
  return c;
}

void LoadHistory::interpolate_nodes(const double* Q1, const double* Q2, double xi, double* q1, double* q2) const {
  double num1 = 0.0;
  double num2 = 0.0;
  double den = 0.0;
  for (int j = 0; j < n_; ++j) {
    const double d = xi - nodes_[j];
    if (d == 0.0) {
      *q1 = Q1[j];
      *q2 = Q2[j];
      return;
    }
    const double c = bary_[j] / d;
    num1 += c * Q1[j];
    num2 += c * Q2[j];
    den += c;
  }
  *q1 = num1 / den;
  *q2 = num2 / den;
}

Eigen::Vector2d LoadHistory::interpolate_at(double tau) const {
  const double v = std::sqrt(std::max(tau - t0_, 0.0));
  const int panel = panel_at(v);
  Eigen::Vector2d q;
  interpolate(stretch_of(panel), panel, v, &q[0], &q[1]);
  return q;
}

bool LoadHistory::load(double t, double Q1_at_t, double Q2_at_t, double* P1, double* P2,
                       const Sampler& near) const {
  if (!series_) return load_kernel(creep_, creep_, t, Q1_at_t, Q2_at_t, P1, P2, near);
  const std::vector<RelaxationSeries::Term>& terms = series_->terms;
  // The smooth stretch of history before t: since touchdown or the load's last kink.
  double t_smooth = t0_;
  for (const double k : kinks_) {
    if (k > t_smooth && k < t) t_smooth = k;
  }
  std::size_t fast = 0;
  while (fast < terms.size() && kLaguerreReach * terms[fast].tau <= t - t_smooth) ++fast;
  Eigen::Vector2d sum = series_->E_final * Eigen::Vector2d(Q1_at_t, Q2_at_t);
  if (fast > 0) {
    const GaussRule& rule = gauss_laguerre(kLaguerreNodes);
    const Eigen::Vector2d q_t = interpolate_at(t);
    for (std::size_t k = 0; k < fast; ++k) {
      Eigen::Vector2d d = Eigen::Vector2d::Zero();
      for (int i = 0; i < kLaguerreNodes; ++i) {
        d += rule.weights[i] * (q_t - interpolate_at(t - terms[k].tau * rule.nodes[i]));
      }
      sum += terms[k].E * d;
    }
  }
  if (fast < terms.size()) {
    Eigen::Vector2d slow;
    // Over the two-level panels the integrand is the interpolant, a polynomial in v that the
    // Gauss pieces integrate as they resolve the kernel: the creep time scale does not bound them.
    const SeriesTail tail(*series_, fast, creep_.creep_time_scale());
    const SeriesTail tail_on_panels(*series_, fast, std::numeric_limits<double>::infinity());
    if (!load_kernel(tail, tail_on_panels, t, Q1_at_t, Q2_at_t, &slow[0], &slow[1], near)) {
      return false;
    }
    sum += slow;
  }
  *P1 = sum[0];
  *P2 = sum[1];
  return true;
}

template <class Kernel>
bool LoadHistory::load_kernel(const Kernel& creep, const Kernel& on_panels, double t, double Q1_at_t, double Q2_at_t, double* P1, double* P2,
                              const Sampler& near) const {
  const double memory = creep.relaxation_memory();
  const double v_t = std::sqrt(std::max(t - t0_, 0.0));
  // The stretch of time the panel at t spans; a memory shorter than that is a narrow kernel.
  const int panel_t = panel_at(v_t);
  const Stretch& stretch_t = stretch_of(panel_t);
  const double width_at_t = stretch_t.panel_width(panel_t - stretch_t.first_panel);
  const double panel_span = (2.0 * v_t + width_at_t) * width_at_t;
  const double tau_min = std::max(0.0, t - memory);
  if (memory < panel_span) return load_near(creep, on_panels, t, tau_min, v_t, Q1_at_t, Q2_at_t, P1, P2, near);
  const double E0 = creep.relaxation(0.0);
  Eigen::Vector2d sum(E0 * Q1_at_t, E0 * Q2_at_t);

  // Single-level phase [0, t0): Q1 = L g(tau), Q2 = 0, smooth in tau between the kinks.
  for_each_piece(kinks_, tau_min, std::min(t0_, t), [&](double a, double b) {
    sum[0] += level1_load_ * relaxation_integral(
                                 creep, t, a, b, [&](double tau) { return load_.response(tau); }, 0.0);
  });

  // Two-level phase [t0, t], panel by panel in v = sqrt(tau - t0).
  const double v_lo = std::sqrt(std::max(tau_min - t0_, 0.0));
  for (int panel = panel_at(v_lo); panel < panels_; ++panel) {
    const double v_a = std::max(v_lo, panel_start(panel));
    const double v_b = panel + 1 == panels_ ? v_t : std::min(v_t, panel_start(panel + 1));
    if (!(v_b > v_a)) break;
    const Stretch& stretch = stretch_of(panel);  // once a panel, not at every kernel node
    sum += relaxation_integral_sqrt(
        on_panels, t, t0_, v_a, v_b,
        [&](double v) {
          Eigen::Vector2d q;
          interpolate(stretch, panel, v, &q[0], &q[1]);
          return q;
        },
        Eigen::Vector2d::Zero().eval());
  }
  *P1 = sum[0];
  *P2 = sum[1];
  return true;
}

template <class Kernel>
bool LoadHistory::load_near(const Kernel& creep, const Kernel& on_panels, double t, double tau_min, double v_t, double Q1_at_t, double Q2_at_t,
                            double* P1, double* P2, const Sampler& near) const {
  const double E_t = creep.relaxation(t);
  Eigen::Vector2d sum(E_t * Q1_at_t, E_t * Q2_at_t);
  const Eigen::Vector2d at_t(Q1_at_t, Q2_at_t);

  // Single-level part of the window, [tau_min, t0): Q1 = L g(tau), Q2 = 0.
  for_each_piece(kinks_, tau_min, std::min(t0_, t), [&](double a, double b) {
    sum += relaxation_integral(
        creep, t, a, b,
        [&](double tau) { return (Eigen::Vector2d(level1_load_ * load_.response(tau), 0.0) - at_t).eval(); },
        Eigen::Vector2d::Zero().eval());
  });

  // Two-level part, [max(tau_min, t0), t]: Q sampled at the n Gauss nodes of the window in
  // v = sqrt(tau - t0), in which Q is analytic even across touchdown (and between kinks of
  // the load, so the window is cut at them).
  bool ok = true;
  std::vector<double> q1(static_cast<std::size_t>(n_));
  std::vector<double> q2(q1.size());
  for_each_piece(kinks_, std::max(tau_min, t0_), t, [&](double a, double b) {
    const double v_a = std::sqrt(std::max(a - t0_, 0.0));
    const double v_b = a == std::max(tau_min, t0_) && b == t ? v_t : std::sqrt(b - t0_);
    if (!ok || !(v_b > v_a)) return;
    for (int j = 0; j < n_ && ok; ++j) {
      const double v = v_a + 0.5 * (nodes_[static_cast<std::size_t>(j)] + 1.0) * (v_b - v_a);
      ok = near(t0_ + v * v, &q1[static_cast<std::size_t>(j)], &q2[static_cast<std::size_t>(j)]);
    }
    if (!ok) return;
    sum += relaxation_integral_sqrt(
        on_panels, t, t0_, v_a, v_b,
        [&](double v) {
          Eigen::Vector2d q;
          interpolate_nodes(q1.data(), q2.data(), 2.0 * (v - v_a) / (v_b - v_a) - 1.0, &q[0], &q[1]);
          return (q - at_t).eval();
        },
        Eigen::Vector2d::Zero().eval());
  });
  if (!ok) return false;
  *P1 = sum[0];
  *P2 = sum[1];
  return true;
}

}  // namespace punchsweep::model
