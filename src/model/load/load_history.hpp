#pragma once

#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "model/load/creep_weighted_load.hpp"

namespace punchsweep::model {

/// Numerical choices of the load-history integral (see LoadHistory).
struct HistoryQuadrature {
  /// Gauss nodes per panel, n. The error falls as h^(2n) with the panel width h once the
  /// panels resolve the kernel (as composite Gauss-Legendre; tested for n = 2, 3), and
  /// never slower than the interpolation error h^n.
  int nodes_per_panel = 12;
  /// Panel width h in v = sqrt(t - t0), in units of sqrt(lambda), lambda the law's
  /// creep_time_scale() (T_eps for the standard linear solid).
  double panel_width = 0.5;
};

/// The loads P_i(t) = int_0-^t E(t - tau) dQ_i(tau) (docs/model.md, section 5), written as
///   P_i(t) = E(0) Q_i(t) + int_0^t E'(t - tau) Q_i(tau) dtau,
/// which needs Q and not its derivative (Q jumps at t = 0 and has a root singularity at t*).
///
/// Before t0 (the delayed contact time; 0 if level 2 touches at once) only level 1 carries
/// load and Q1 = l^2 X(tau) = L g(tau), Q2 = 0 exactly (L = pbar0 l^2, X = pbar0 g the
/// creep-weighted load). On [t0, t_end] Q is sampled at
/// Gauss-Legendre nodes of panels uniform in v = sqrt(tau - t0): in v the two-level
/// solution is analytic, although a2 ~ sqrt(tau - t0) after touchdown. The kernel integral
/// then uses the piecewise interpolant (product integration): a 16-point Gauss rule on
/// sub-intervals no longer than 2 relaxation time scales, so the kernel is resolved at no
/// extra solves. A load that rises piecewise linearly (ramp, table) puts kinks into X and
/// so into Q: panels and kernel pieces end at them. Only the error of the interpolant remains; because it interpolates at
/// Gauss nodes it integrates at order 2n in h (see HistoryQuadrature).
///
/// A fast-relaxing material (a relaxation memory shorter than the stretch of time one
/// panel spans at t: the standard linear solid with T above about 16 at t = 5, or any T at
/// late enough t) needs more: P_i is then about E(inf)/E(0) of the two terms above, so
/// their difference would amplify the interpolant's error near t by E(0)/E(inf), and the
/// rounding of tau near a large t by the kernel's rate. There load() uses
///   P_i(t) = E(t) Q_i(t) + int_{t-m}^t (Q_i(tau) - Q_i(t)) E'(t - tau) dtau
/// (by parts; m the relaxation memory, beyond which E' is below 1e-17 of its scale), with Q
/// sampled afresh at n Gauss nodes of the memory window: the integrand vanishes where the
/// kernel is largest, and the window's interpolant is as exact as the window is short.
///
/// A law given as a relaxation series E = E(inf) + sum_k E_k exp(-s/tau_k)
/// (CreepLaw::relaxation_series) is integrated term by term (docs/model.md, section 12.7):
///   P_i(t) = E(inf) Q_i(t) + sum_k E_k D_k(t),   D_k(t) = int_0-^t exp(-(t - tau)/tau_k) dQ_i(tau).
/// A term that relaxes within the smooth stretch of history before t (tau_k at most
/// 1/kLaguerreReach of the time since touchdown or the load's last kink) forgets everything
/// older, and
///   D_k(t) = int_0^inf exp(-x) (q(t) - q(t - tau_k x)) dx
/// is a Gauss-Laguerre sum over the interpolant q: no kernel quadrature, no fresh samples,
/// and the difference of q with itself carries no interpolation error into P. The other
/// terms (the slow ones) are the kernel of the integral above.
class LoadHistory {
 public:
  /// Writes Q1, Q2 at tau (called with increasing tau); returns false if it failed.
  using Sampler = std::function<bool(double tau, double* Q1, double* Q2)>;

  LoadHistory(const CreepWeightedLoad& load, double level1_load, double t0, double t_end,
              const HistoryQuadrature& quadrature, const Sampler& sample);

  /// The work a history over [t0, t_end] would take, before any is done: the Q samples it
  /// takes and the kernel pieces one load() call may sum.
  struct Cost {
    double samples = 0.0;
    double kernel_pieces = 0.0;
  };
  static Cost cost(const CreepWeightedLoad& load, double t0, double t_end, const HistoryQuadrature& quadrature);
  /// The most work evaluate_point() spends on one history; a material whose times span
  /// more decades than that resolves (a wide Prony spectrum over a long time) is flagged
  /// instead (docs/model.md, section 12.7).
  static constexpr double kMaxSamples = 2e6;
  static constexpr double kMaxKernelPieces = 1e5;

  /// False if any sample failed; then load() is meaningless.
  bool ok() const { return ok_; }

  /// P_i(t) for t in [t0, t_end], given the exact Q_i(t) at that time. `near` samples Q in
  /// the memory window before t when the kernel is narrower than a panel (called with tau
  /// in [t - memory, t), in increasing order); returns false if a sample failed.
  bool load(double t, double Q1_at_t, double Q2_at_t, double* P1, double* P2, const Sampler& near) const;

  /// Number of Q samples taken (the solves the history cost).
  int samples() const { return static_cast<int>(Q1_.size()); }

  /// A series term is summed by Gauss-Laguerre once the smooth history before t is at least
  /// kLaguerreReach of its tau_k: the integrand's branch point (touchdown, where Q2 ~
  /// sqrt(tau - t0), or a kink of the load) lies beyond x = kLaguerreReach, where the
  /// kLaguerreNodes-point rule's error, about (2 n)! / kLaguerreReach^(2 n) = 2.5e-16 of Q,
  /// is at rounding; its nodes reach x = 29.9, inside the stretch.
  static constexpr double kLaguerreReach = 50.0;
  static constexpr int kLaguerreNodes = 10;

 private:
  /// A stretch of v between kinks of the load, cut into `panels` panels of equal width.
  struct Stretch {
    double v_start = 0.0;
    double width = 0.0;  ///< of each panel (uniform stretches)
    int first_panel = 0;
    int panels = 0;
    /// Graded stretches: the panels' edges (panels + 1 of them); empty when uniform.
    std::vector<double> edges;
    double panel_start(int relative) const {
      return edges.empty() ? v_start + relative * width : edges[static_cast<std::size_t>(relative)];
    }
    double panel_width(int relative) const {
      return edges.empty() ? width
                           : edges[static_cast<std::size_t>(relative) + 1] - edges[static_cast<std::size_t>(relative)];
    }
  };
  /// The most uniform panels a stretch takes; beyond, they grow geometrically in v
  /// (kPanelGrowth), as a spectrum of retardation times over many decades needs.
  static constexpr int kMaxUniformPanels = 64;
  /// A graded panel at v spans max(width, kPanelGrowth v width / width0) in v, width0 the
  /// default panel width (HistoryQuadrature{}.panel_width sqrt(creep time)): at the default
  /// a factor 1.69 in time a panel, and finer in proportion to a finer width, so that the
  /// width still controls the error everywhere. (Against histories of growth 0.05 and 16
  /// nodes, the loads P_i of the four shipped materials agree to 6e-15 E0* R^2 at 0.3, as
  /// at 0.2 (1.5e-14); at 0.4 the 24-term epoxy's are 4e-13 off.)
  static constexpr double kPanelGrowth = 0.3;
  /// The stretch panel `panel` lies in.
  const Stretch& stretch_of(int panel) const;
  /// The panel that holds v (the last one for v beyond the end).
  int panel_at(double v) const;
  double panel_start(int panel) const;
  /// Interpolated Q at v on panel `panel` of stretch `s` (stretch_of(panel)).
  void interpolate(const Stretch& s, int panel, double v, double* Q1, double* Q2) const;
  /// Barycentric interpolation at xi in [-1, 1] of samples at the reference nodes.
  void interpolate_nodes(const double* Q1, const double* Q2, double xi, double* q1, double* q2) const;
  /// The interpolant at time tau in [t0, t_end].
  Eigen::Vector2d interpolate_at(double tau) const;
  /// load() with the relaxation kernel `kernel` (the law, or the slow terms of its series),
  /// and `on_panels`, the same kernel for the two-level panels.
  template <class Kernel>
  bool load_kernel(const Kernel& kernel, const Kernel& on_panels, double t, double Q1_at_t, double Q2_at_t, double* P1, double* P2,
                   const Sampler& near) const;
  /// The narrow-kernel form of load_kernel() (see the class comment) over [tau_min, t], with
  /// v_t = sqrt(t - t0); false if `near` failed.
  template <class Kernel>
  bool load_near(const Kernel& kernel, const Kernel& on_panels, double t, double tau_min, double v_t, double Q1_at_t, double Q2_at_t,
                 double* P1, double* P2, const Sampler& near) const;

  CreepWeightedLoad load_;
  const CreepLaw& creep_;  ///< load_'s material: its relaxation function is the kernel
  std::optional<RelaxationSeries> series_;  ///< the law's relaxation series, if term by term
  double level1_load_;
  double t0_;
  std::vector<Stretch> stretches_;  ///< one unless the load has kinks after t0
  std::vector<double> kinks_;       ///< kinks of the load's shape (LoadShape::kinks)
  int panels_ = 0;
  int n_ = 0;
  bool ok_ = true;
  std::vector<double> nodes_;       ///< reference nodes on [-1, 1]
  std::vector<double> bary_;        ///< barycentric weights of the nodes
  std::vector<double> Q1_, Q2_;     ///< samples, panel-major
};

}  // namespace punchsweep::model
