#include "model/surface/small_spot_touchdown.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "model/numerics/root_finding.hpp"
#include "model/problem/shape.hpp"

namespace punchsweep::model {

namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

template <class Term>
void PeriodicPointLoads::add_images(double& sum, double x, double y, bool regular, const Term& term) const {
  for (int i = -images_x_; i <= images_x_; ++i) {
    for (int j = -images_y_; j <= images_y_; ++j) {
      if (regular && i == 0 && j == 0) continue;
      sum += term(std::hypot(x - i * Lx_, y - j * Ly_));
    }
  }
}

template <class Term>
void PeriodicPointLoads::add_waves(double& sum, double x, double y, const Term& term) const {
  for (int i = -waves_x_; i <= waves_x_; ++i) {
    for (int j = -waves_y_; j <= waves_y_; ++j) {
      if (i == 0 && j == 0) continue;
      const double kx = 2.0 * kPi * i / Lx_, ky = 2.0 * kPi * j / Ly_;
      sum += term(std::hypot(kx, ky)) * std::cos(kx * x + ky * y);
    }
  }
}

PeriodicPointLoads::PeriodicPointLoads(double Lx, double Ly) : Lx_(Lx), Ly_(Ly), area_(Lx * Ly), alpha_(2.0 / std::sqrt(Lx * Ly)) {
  // erfc(6) = 2e-17: the real sum to 6 / alpha, the Fourier sum to k = 12 alpha.
  const double side = std::sqrt(area_);
  images_x_ = static_cast<int>(std::ceil(3.0 * side / Lx_)) + 1;
  images_y_ = static_cast<int>(std::ceil(3.0 * side / Ly_)) + 1;
  waves_x_ = static_cast<int>(std::ceil(24.0 * Lx_ / (2.0 * kPi * side))) + 1;
  waves_y_ = static_cast<int>(std::ceil(24.0 * Ly_ / (2.0 * kPi * side))) + 1;
  regular_displacement_ = sum_real(0.0, 0.0, true) - 2.0 * alpha_ / (kPi * std::sqrt(kPi));
  double fourier = 0.0;
  add_waves(fourier, 0.0, 0.0, [&](double k) { return 2.0 / (k * area_) * std::erfc(k / (2.0 * alpha_)); });
  regular_displacement_ += fourier - 2.0 / (std::sqrt(kPi) * alpha_ * area_);
  regular_laplacian_ = sum_laplacian(0.0, 0.0, true);
}

double PeriodicPointLoads::sum_real(double x, double y, bool regular) const {
  double sum = 0.0;
  add_images(sum, x, y, regular, [&](double r) { return std::erfc(alpha_ * r) / (kPi * r); });
  return sum;
}

double PeriodicPointLoads::displacement(double x, double y) const {
  double fourier = 0.0;
  add_waves(fourier, x, y, [&](double k) { return 2.0 / (k * area_) * std::erfc(k / (2.0 * alpha_)); });
  return sum_real(x, y, false) - 2.0 / (std::sqrt(kPi) * alpha_ * area_) + fourier;
}

std::array<double, 2> PeriodicPointLoads::gradient(double x, double y) const {
  const double step = 1e-5 * std::sqrt(area_);
  return {(displacement(x + step, y) - displacement(x - step, y)) / (2.0 * step),
          (displacement(x, y + step) - displacement(x, y - step)) / (2.0 * step)};
}

double PeriodicPointLoads::sum_laplacian(double x, double y, bool regular) const {
  // Ewald's split of G, differentiated: the screened part's Laplacian
  // e''/(pi r) - e'/(pi r^2) + e/(pi r^3) with e = erfc(alpha r), and -k^2 times each wave.
  const double a = alpha_, root_pi = std::sqrt(kPi);
  double sum = 0.0;
  add_images(sum, x, y, regular, [&](double r) {
    const double gauss = std::exp(-a * a * r * r);
    const double e = std::erfc(a * r), e1 = -2.0 * a / root_pi * gauss, e2 = 4.0 * a * a * a * r / root_pi * gauss;
    return (e2 / r - e1 / (r * r) + e / (r * r * r)) / kPi;
  });
  // At a node, the limit of the screened part's Laplacian less 1/(pi r^3): 8 alpha^3 / (3 pi^1.5).
  if (regular) sum += 8.0 * a * a * a / (3.0 * kPi * root_pi);
  add_waves(sum, x, y, [&](double k) { return -(2.0 * k / area_ * std::erfc(k / (2.0 * a))); });
  return sum;
}

double PeriodicPointLoads::laplacian(double x, double y) const { return sum_laplacian(x, y, false); }

namespace {

/// The second moment of an isolated punch's pressure, M2 = int p r^2 dA = m2 a^(s+3)
/// (Betti's theorem against the Hertz state of the same radius: M2 = 2 a^(s+3) [K_P - 4/3 K_d
/// + 2 C B(s/2 + 1, 3/2)]; Hertz: 2/5 a^2 P, a flat punch's limit 2/3 a^2 P).
double second_moment_coefficient(const Shape& shape) {
  const double s = shape.s;
  const double beta = std::exp(std::lgamma(0.5 * s + 1.0) + std::lgamma(1.5) - std::lgamma(0.5 * s + 2.5));
  return 2.0 * (load_coefficient(shape) - 4.0 / 3.0 * depth_coefficient(shape) + 2.0 * shape.C * beta);
}

/// The cell's sites as punches of small spots: the fields between every pair, the state of
/// the sites in contact at a load, and an untouched site's closure.
class SmallSpotCell {
 public:
  explicit SmallSpotCell(const CellGeometry& geometry) : geometry_(geometry), field_(geometry.Lx, geometry.Ly) {
    const std::size_t n = geometry.sites.size();
    G_ = Eigen::MatrixXd(n, n);
    L_ = Eigen::MatrixXd(n, n);
    Gx_ = Eigen::MatrixXd::Zero(n, n);  // (the images' field is even about a site: no slope there)
    Gy_ = Eigen::MatrixXd::Zero(n, n);
    for (std::size_t i = 0; i < n; ++i) {
      const Shape& shape = geometry.sites[i].shape;
      K_P_.push_back(load_coefficient(shape));
      K_d_.push_back(depth_coefficient(shape));
      m2_.push_back(second_moment_coefficient(shape));
      G_(i, i) = field_.regular_displacement();
      L_(i, i) = field_.regular_laplacian();
      // G and L are even, their gradient odd: each pair once.
      for (std::size_t j = i + 1; j < n; ++j) {
        const auto [dx, dy] = offset(i, j);
        G_(i, j) = G_(j, i) = field_.displacement(dx, dy);
        L_(i, j) = L_(j, i) = field_.laplacian(dx, dy);
        const std::array<double, 2> g = field_.gradient(dx, dy);
        Gx_(i, j) = g[0];
        Gy_(i, j) = g[1];
        Gx_(j, i) = -g[0];
        Gy_(j, i) = -g[1];
      }
    }
  }

  /// The distance between the tips of sites a and b (to the nearest periodic image).
  double distance(std::size_t a, std::size_t b) const {
    const auto [dx, dy] = offset(a, b);
    return std::hypot(dx, dy);
  }

  /// The nearest distance from a site of `loaded` to another (or its own image) or to site k.
  double nearest(const std::vector<std::size_t>& loaded, std::size_t k) const {
    double d = std::min(geometry_.Lx, geometry_.Ly);
    for (const std::size_t i : loaded) {
      d = std::min(d, distance(i, k));
      for (const std::size_t j : loaded) {
        if (j != i) d = std::min(d, distance(i, j));
      }
    }
    return d;
  }

  /// The sites in contact at mean load X: each one's load P, radius a and second moment M2
  /// (in the order of `loaded`), and the tallest tip's sinking delta.
  struct State {
    Eigen::VectorXd P, a, M2;
    double delta = 0.0;
    bool converged = false;
  };
  State at(const std::vector<std::size_t>& loaded, double X) const {
    const Eigen::Index N = static_cast<Eigen::Index>(loaded.size());
    const double total = X * geometry_.Lx * geometry_.Ly;
    Eigen::MatrixXd G(N, N), L(N, N);
    for (Eigen::Index i = 0; i < N; ++i) {
      for (Eigen::Index j = 0; j < N; ++j) {
        G(i, j) = G_(loaded[static_cast<std::size_t>(i)], loaded[static_cast<std::size_t>(j)]);
        L(i, j) = L_(loaded[static_cast<std::size_t>(i)], loaded[static_cast<std::size_t>(j)]);
      }
    }
    State st;
    st.P = Eigen::VectorXd::Zero(N);
    st.M2 = Eigen::VectorXd::Zero(N);
    st.a = Eigen::VectorXd(N);
    // Start: the load shared evenly, each radius its isolated punch's (a tenth of it for a
    // lower site, which joined at a spot of zero).
    for (Eigen::Index i = 0; i < N; ++i) {
      st.a(i) = std::pow(total / static_cast<double>(N) / K_P_[site(loaded, i)], 1.0 / (shape(loaded, i).s + 1.0));
      if (geometry_.sites[site(loaded, i)].drop > 0.0) st.a(i) *= 0.1;
    }
    // The curvatures and far-field moments start from the tallest caps' isolated share
    // (the lower sites, just in contact, carry little).
    Eigen::VectorXd P0 = Eigen::VectorXd::Zero(N), M0 = Eigen::VectorXd::Zero(N);
    for (Eigen::Index i = 0; i < N; ++i) {
      if (geometry_.sites[site(loaded, i)].drop > 0.0) continue;
      P0(i) = K_P_[site(loaded, i)] * std::pow(st.a(i), shape(loaded, i).s + 1.0);
      M0(i) = m2_[site(loaded, i)] * std::pow(st.a(i), shape(loaded, i).s + 3.0);
    }
    P0 *= total / P0.sum();
    Eigen::VectorXd eps = 0.25 * (L * P0), moment = 0.25 * (L * M0);
    // Sneddon's relations for site i's profile C r^s + eps r^2 at radius a: its load P and
    // sinking F, and their slopes in a.
    struct Cap {
      double P, dP, F, dF;
    };
    const auto cap = [&](Eigen::Index i, double a, double curvature) {
      const std::size_t k = site(loaded, i);
      const double s = shape(loaded, i).s;
      return Cap{K_P_[k] * std::pow(a, s + 1.0) + 8.0 / 3.0 * curvature * std::pow(a, 3),
                 (s + 1.0) * K_P_[k] * std::pow(a, s) + 8.0 * curvature * a * a,
                 K_d_[k] * std::pow(a, s) + 2.0 * curvature * a * a, s * K_d_[k] * std::pow(a, s - 1.0) + 4.0 * curvature * a};
    };
    for (int outer = 0; outer < 40; ++outer) {
      // Newton on the radii and delta, the curvatures and far-field moments held:
      // drop_i + moment_i + F_i(a_i) + sum_j G_ij P_j(a_j) = delta, sum_j P_j(a_j) = total.
      Eigen::VectorXd a = st.a;
      double delta = st.delta;
      bool newton = false;
      for (int it = 0; it < 100 && !newton; ++it) {
        Eigen::VectorXd P(N), dP(N), F(N), dF(N);
        for (Eigen::Index i = 0; i < N; ++i) {
          const Cap c = cap(i, a(i), eps(i));
          P(i) = c.P;
          dP(i) = c.dP;
          F(i) = c.F;
          dF(i) = c.dF;
        }
        Eigen::MatrixXd J = Eigen::MatrixXd::Zero(N + 1, N + 1);
        Eigen::VectorXd r(N + 1);
        const Eigen::VectorXd GP = G * P;
        for (Eigen::Index i = 0; i < N; ++i) {
          r(i) = geometry_.sites[site(loaded, i)].drop + moment(i) + F(i) + GP(i) - delta;
          J.row(i).head(N) = G.row(i).cwiseProduct(dP.transpose());
          J(i, i) += dF(i);
          J(i, N) = -1.0;
        }
        r(N) = P.sum() - total;
        J.row(N).head(N) = dP.transpose();
        const Eigen::VectorXd step = J.partialPivLu().solve(r);
        // A radius may not go below a tenth of itself in one step (a site just in contact
        // starts from a small spot).
        double damp = 1.0;
        for (Eigen::Index i = 0; i < N; ++i) {
          if (step(i) > 0.9 * a(i)) damp = std::min(damp, 0.9 * a(i) / step(i));
        }
        a -= damp * step.head(N);
        delta -= damp * step(N);
        if (!a.allFinite() || a.minCoeff() < 1e-12 * a.maxCoeff()) break;  // a site not in contact at this load
        // Converged where the step or the residual is at rounding (a just-joined site's small
        // radius moves by 1e-13 of the largest for a residual of 1e-17).
        newton = damp == 1.0 && (step.head(N).cwiseAbs().maxCoeff() <= 1e-12 * a.maxCoeff() ||
                                 r.cwiseAbs().maxCoeff() <= 1e-14 * std::abs(delta));
      }
      Eigen::VectorXd P(N), M2(N);
      for (Eigen::Index i = 0; i < N; ++i) {
        P(i) = cap(i, a(i), eps(i)).P;
        M2(i) = m2_[site(loaded, i)] * std::pow(a(i), shape(loaded, i).s + 3.0);
      }
      const double moved = (a - st.a).cwiseAbs().maxCoeff();
      st.a = a;
      st.P = P;
      st.M2 = M2;
      st.delta = delta;
      eps = 0.25 * (L * P);
      moment = 0.25 * (L * M2);
      if (!newton) break;
      if (outer > 0 && moved <= 1e-12 * a.maxCoeff()) {
        st.converged = true;
        break;
      }
    }
    return st;
  }

  /// How far site k's gap has closed in state st of `loaded` (its drop when it touches), with
  /// its tip's field u, and the lowest gap's shift where the field tilts; NaN for a cone the
  /// tilt turns off its tip.
  double closure(const std::vector<std::size_t>& loaded, const State& st, std::size_t k) const {
    const Site& target = geometry_.sites[k];
    double u = 0.0, gx = 0.0, gy = 0.0;
    for (std::size_t j = 0; j < loaded.size(); ++j) {
      const Eigen::Index J = static_cast<Eigen::Index>(j);
      u += st.P(J) * G_(k, loaded[j]) + 0.25 * st.M2(J) * L_(k, loaded[j]);
      gx += st.P(J) * Gx_(k, loaded[j]);
      gy += st.P(J) * Gy_(k, loaded[j]);
    }
    const double slope = std::hypot(gx, gy);
    double tilt = 0.0;
    if (target.shape.s == 1) {
      if (slope > target.shape.C) return std::numeric_limits<double>::quiet_NaN();
    } else {
      const double s = target.shape.s;
      const double y = std::pow(slope / (s * target.shape.C), 1.0 / (s - 1.0));
      tilt = (s - 1.0) * target.shape.C * std::pow(y, s);
    }
    return st.delta - u + tilt;
  }

 private:
  static std::size_t site(const std::vector<std::size_t>& loaded, Eigen::Index i) { return loaded[static_cast<std::size_t>(i)]; }
  const Shape& shape(const std::vector<std::size_t>& loaded, Eigen::Index i) const { return geometry_.sites[site(loaded, i)].shape; }
  /// Site a's tip less site b's, to the nearest periodic image.
  std::array<double, 2> offset(std::size_t a, std::size_t b) const {
    double dx = geometry_.sites[a].x - geometry_.sites[b].x, dy = geometry_.sites[a].y - geometry_.sites[b].y;
    dx -= geometry_.Lx * std::round(dx / geometry_.Lx);
    dy -= geometry_.Ly * std::round(dy / geometry_.Ly);
    return {dx, dy};
  }

  const CellGeometry& geometry_;
  PeriodicPointLoads field_;
  std::vector<double> K_P_, K_d_, m2_;
  Eigen::MatrixXd G_, L_, Gx_, Gy_;  ///< between every pair of sites: G, its Laplacian and gradient
};

/// Whether the limit takes the cell: every level-0 site at drop 0 (a scattered supercell's
/// nearly tallest caps touch at loads of their own, which are the curve's), at most
/// kSmallSpotMaxSites sites. The tallest sites, or none.
std::vector<std::size_t> tallest_sites(const CellGeometry& geometry) {
  std::vector<std::size_t> tallest;
  if (geometry.sites.empty() || geometry.sites.size() > kSmallSpotMaxSites) return {};
  for (std::size_t k = 0; k < geometry.sites.size(); ++k) {
    if (geometry.sites[k].level != 0) continue;
    if (geometry.sites[k].drop != 0.0) return {};
    tallest.push_back(k);
  }
  return tallest;
}

}  // namespace

struct SmallSpotLimit::Cell : SmallSpotCell {
  using SmallSpotCell::SmallSpotCell;
};

SmallSpotLimit::SmallSpotLimit(const CellGeometry& geometry, int closing_level)
    : geometry_(geometry), tallest_(tallest_sites(geometry)), closing_level_(closing_level) {
  if (tallest_.empty()) return;
  cell_ = std::make_shared<const Cell>(geometry_);
  // The other levels touch as they do whatever the closing level's drop: found once.
  if (closing_level_ >= 1) others_ = touchdowns(closing_level_);
}

std::vector<SmallSpotTouchdown> SmallSpotLimit::touchdowns(int skipped_level) const {
  std::vector<SmallSpotTouchdown> out(geometry_.sites.size());
  if (!cell_) return out;
  std::vector<std::size_t> loaded = tallest_;
  for (const std::size_t k : loaded) out[k] = {0.0, 0.0};
  // (The reach's first guess: the tallest caps' isolated spots, the cell shared among them.)
  const double share = geometry_.Lx * geometry_.Ly / static_cast<double>(tallest_.size());
  const Shape& tall = geometry_.sites[tallest_[0]].shape;
  // The sites touch in turn: each round finds every untouched site's touchdown with the
  // sites in contact so far, and the first (with those within 1e-9 of it) join them, where
  // the limit still holds for every other site there.
  double X_from = 0.0;
  for (;;) {
    std::vector<std::pair<double, std::size_t>> found;
    double held_to = std::numeric_limits<double>::infinity();  // the least load where a site's reach ends unanswered
    for (std::size_t k = 0; k < geometry_.sites.size(); ++k) {
      if (std::find(loaded.begin(), loaded.end(), k) != loaded.end() || geometry_.sites[k].level == skipped_level ||
          !(geometry_.sites[k].drop > 0.0)) {
        continue;
      }
      const double reach = cell_->nearest(loaded, k);
      const Site& site = geometry_.sites[k];
      // One state at load X: its largest spot, and how far site k's gap is past closing
      // (+infinity where the state is not found or a cone's tip is tilted off).
      struct Probe {
        double spot, excess;
      };
      const auto probe_at = [&](double X) {
        const SmallSpotCell::State st = cell_->at(loaded, X);
        const double c = cell_->closure(loaded, st, k);
        return Probe{st.a.maxCoeff(), std::isnan(c) || !st.converged ? std::numeric_limits<double>::infinity() : c - site.drop};
      };
      const auto probe = [&](double log_X) { return probe_at(std::exp(log_X)); };
      // A site like one found this round (a supercell's copies, a lattice's images) closes at
      // its load: one state there says so (its gap closed to rounding, its spots within reach).
      const auto alike = std::find_if(found.begin(), found.end(), [&](const auto& f) {
        const Site& other = geometry_.sites[f.second];
        return other.level == site.level && other.drop == site.drop && other.shape.s == site.shape.s && other.shape.C == site.shape.C;
      });
      if (alike != found.end()) {
        const double X = alike->first;  // (a copy: found grows below)
        const Probe there = probe_at(X);
        if (std::abs(there.excess) <= 1e-12 * site.drop && there.spot <= kSmallSpotMaxRatio * reach) {
          found.emplace_back(X, k);
          out[k] = {X, there.spot / reach};
          continue;
        }
      }
      // The limit's reach: the largest load whose spots stay within kSmallSpotMaxRatio of
      // the nearest distance (bisection in log X), from just above the last touchdown (1e-6
      // of the load past it: the sites that joined there have spots, not points, which the
      // state's solve, holding curvatures and moments while it moves the radii, finds).
      double hi = std::log(load_coefficient(tall) * std::pow(2.0 * kSmallSpotMaxRatio * reach, tall.s + 1) / share);
      const double floor = X_from > 0.0 ? std::log(X_from) + 1e-6 : hi - 80.0;
      const auto within = [&](const Probe& p) { return p.spot <= kSmallSpotMaxRatio * reach; };
      const Probe at_floor = hi > floor ? probe(floor) : Probe{};
      if (!(hi > floor) || !within(at_floor)) {
        held_to = std::min(held_to, X_from);
        continue;
      }
      Probe at_hi = probe(hi);
      if (!within(at_hi)) {
        hi = bisect_boundary([&](double log_X) { return within(probe(log_X)); }, floor, hi, 0.0, 24).first;  // (to 5e-6 of the range in log X)
        at_hi = probe(hi);
      }
      const double f_hi = at_hi.excess, f_lo = at_floor.excess;
      if (!(f_hi >= 0.0) || !(f_lo < 0.0)) {  // not closed within the reach (or closed before)
        held_to = std::min(held_to, std::exp(hi));
        continue;
      }
      const RootResult root = brent([&](double log_X) { return probe(log_X).excess; }, floor, hi, f_lo, f_hi, 1e-13);
      if (!root.converged) {
        held_to = std::min(held_to, std::exp(floor));
        continue;
      }
      found.emplace_back(std::exp(root.x), k);
      out[k] = {std::exp(root.x), probe(root.x).spot / reach};
    }
    std::sort(found.begin(), found.end());
    // The first to touch keep their answers where no site left unanswered might have
    // touched before them; the later ones are found again with them.
    const double first = found.empty() ? std::numeric_limits<double>::infinity() : found.front().first;
    for (const auto& [X, k] : found) {
      if (X <= first * (1.0 + 1e-9) && first <= held_to) {
        loaded.push_back(k);
      } else {
        out[k] = {};
      }
    }
    if (found.empty() || !(first <= held_to)) break;
    X_from = first;
  }
  return out;
}

std::optional<double> SmallSpotLimit::level_closure(double X) const {
  const int level = closing_level_;
  if (!cell_ || level < 1) return std::nullopt;
  if (!(X > 0.0)) return 0.0;
  // The other levels' sites in contact by X, in the limit (each must be answered there).
  const std::vector<SmallSpotTouchdown>& others = others_;
  std::vector<std::size_t> loaded, mine;
  double least_drop = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < geometry_.sites.size(); ++k) {
    if (geometry_.sites[k].level == level) {
      mine.push_back(k);
      least_drop = std::min(least_drop, geometry_.sites[k].drop);
    } else if (others[k].X <= X) {
      loaded.push_back(k);
    }
  }
  if (mine.empty()) return std::nullopt;
  const SmallSpotCell::State st = cell_->at(loaded, X);
  if (!st.converged) return std::nullopt;
  double drop = -std::numeric_limits<double>::infinity();
  for (const std::size_t k : mine) {
    // Held where every spot in contact stays within the ratio of the nearest distance, and
    // where each other site unanswered by X would not have touched (its reach goes past X).
    if (st.a.maxCoeff() > kSmallSpotMaxRatio * cell_->nearest(loaded, k)) return std::nullopt;
    const double c = cell_->closure(loaded, st, k);
    if (std::isnan(c)) return std::nullopt;
    drop = std::max(drop, c - (geometry_.sites[k].drop - least_drop));
  }
  // Every other site either in contact by X or shown not to be: its gap still open at X.
  for (std::size_t k = 0; k < geometry_.sites.size(); ++k) {
    if (geometry_.sites[k].level == level || others[k].X <= X) continue;
    const double c = cell_->closure(loaded, st, k);
    if (std::isnan(c) || c >= geometry_.sites[k].drop) return std::nullopt;
  }
  // Past the depth where a taller cap's surface covers one of the level's tips, the tip is
  // no punch of its own: the boundary elements answer there.
  for (const std::size_t k : mine) {
    const double offset = geometry_.sites[k].drop - least_drop;
    for (std::size_t j = 0; j < geometry_.sites.size(); ++j) {
      if (geometry_.sites[j].level == level) continue;
      const double r = cell_->distance(j, k);
      const Shape& shape = geometry_.sites[j].shape;
      if (drop + offset >= shape.C * std::pow(r, shape.s) + geometry_.sites[j].drop) return std::nullopt;
    }
  }
  return drop;
}

std::vector<SmallSpotTouchdown> small_spot_touchdowns(const CellGeometry& geometry) { return SmallSpotLimit(geometry).touchdowns(); }

std::size_t answer_small_spots(LoadCurve& curve, const CellGeometry& geometry) {
  curve.level_small_spot.assign(static_cast<std::size_t>(curve.levels()), 0);
  if (geometry.sites.size() != curve.sites()) return 0;
  const std::vector<SmallSpotTouchdown> limit = SmallSpotLimit(geometry).touchdowns();
  const bool stopped = !std::isfinite(curve.X_full);  // at its top, short of full contact
  const SurfaceLocator surface(geometry);
  std::size_t answered = 0;
  for (std::size_t k = 0; k < limit.size(); ++k) {
    // A site the curve finds hidden or untouched up to full contact is its alone to say; one
    // untouched by a curve that stopped short (at the question's reach) takes the limit's
    // load past the curve's end where its tip is on the surface, as the whole curve's would.
    // Elsewhere the limit stands where it holds, resolved or not by the grid: at spot ratio
    // 0.1 it is within 1e-6 of X*, where 16 node spacings a spot radius leave the curve 6e-5
    // off (the study's hexagonal level 1), and one answer on every grid keeps --grid auto's
    // comparison its own.
    const double own = curve.site_touchdown[k];
    if (geometry.sites[k].level == 0 || !std::isfinite(limit[k].X) || own == 0.0) continue;
    if (!std::isfinite(own) && !(stopped && limit[k].X > curve.X_last() && tip_exposed(geometry, surface, k))) continue;
    curve.site_touchdown[k] = limit[k].X;
    ++answered;
  }
  if (answered == 0) return 0;
  curve.level_touchdown = curve.least_site_touchdowns(curve.levels());
  for (std::size_t k = 0; k < curve.sites(); ++k) {
    const std::size_t level = static_cast<std::size_t>(curve.site_level[k]);
    if (level > 0 && limit[k].X == curve.site_touchdown[k] && curve.level_touchdown[level] == curve.site_touchdown[k]) curve.level_small_spot[level] = 1;
  }
  return answered;
}

}  // namespace punchsweep::model
