#pragma once
/// @file
/// A Prony series E(t) = E_inf + sum_i E_i exp(-t / tau_i) fitted to a master curve:
/// relaxation times on a logarithmic grid over the data's span, weights by non-negative
/// least squares on relative errors, the grid's density chosen by the Bayesian information
/// criterion, then the surviving times refined with the weights re-solved at every step
/// (variable projection: Golub and Pereyra, SIAM J. Numer. Anal. 10:413, 1973). In the
/// frequency domain (Tschoegl, The Phenomenological Theory of Linear Viscoelastic
/// Behavior, 1989, section 4.6):
///   E'(w)  = E_inf + sum_i E_i w^2 tau_i^2 / (1 + w^2 tau_i^2),
///   E''(w) =         sum_i E_i w tau_i     / (1 + w^2 tau_i^2).

#include <span>
#include <vector>

namespace punchsweep::fit {

/// A Prony series in SI: moduli in Pa, times in s, tau increasing.
struct PronyTerms {
  double E_inf = 0.0;
  std::vector<double> E;
  std::vector<double> tau;
  double storage(double omega) const;
  double loss(double omega) const;
  double relaxation(double t) const;
};

struct PronyOptions {
  /// Relaxation-time densities tried, in terms per decade; the one with the smallest BIC
  /// is kept.
  std::vector<double> per_decade{0.5, 1.0, 1.5, 2.0, 3.0};
  /// Weight of a penalty on the second differences of neighbouring E_i (relative to the
  /// data's median modulus), for noisy data; 0: none.
  double smoothing = 0.0;
  /// Refine the times after the grid (variable projection).
  bool refine = true;
};

/// One density tried: its grid, the terms that stayed > 0, the residual and the criterion.
struct PronyCandidate {
  double per_decade = 0.0;
  int grid_terms = 0;
  int terms = 0;
  double rss = 0.0;  ///< sum of squared relative residuals
  double bic = 0.0;  ///< n ln(rss / n) + k ln n, k = 2 terms + 1 (each E_i and tau_i, and E_inf)
};

struct PronyFit {
  PronyTerms terms;
  std::vector<PronyCandidate> candidates;
  std::size_t chosen = 0;     ///< index into candidates
  double rss = 0.0;           ///< after refinement
  double bic = 0.0;           ///< after refinement
  /// RMS relative error of each fitted quantity: E' and E'' (frequency data), or E(t) in
  /// `first` (relaxation data; `second` 0), over the readings fitted (unweighted).
  double rms_first = 0.0, rms_second = 0.0;
  int residuals = 0;
};

/// Fits E' and E'' at reduced angular frequencies omega (rad/s; Pa). `weights` (empty: each
/// 1) weigh each reading's squared residuals: a reading that stands for several (a bin of a
/// long export, fit::fit_material) counts as many times. Throws std::invalid_argument when
/// the data are too few (fewer than 4 readings) or not positive. E_inf may come out 0 where
/// the data do not reach a rubbery plateau.
PronyFit fit_prony_frequency(std::span<const double> omega, std::span<const double> storage,
                             std::span<const double> loss, const PronyOptions& options,
                             std::span<const double> weights = {});

/// Fits E(t) at reduced times t (s; Pa), as fit_prony_frequency.
PronyFit fit_prony_relaxation(std::span<const double> t, std::span<const double> modulus, const PronyOptions& options,
                              std::span<const double> weights = {});

}  // namespace punchsweep::fit
