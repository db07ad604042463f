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
/// A site joins the sites in contact this far (relative) past its touchdown load: the
/// touchdowns' joining probe, and the states read at loads.
constexpr double kJoined = 1e-9;

/// The last touchdown the limit answered (0 where it answered none): a site it leaves
/// unanswered touches past it, if at all.
double last_answered(const std::vector<SmallSpotTouchdown>& touched) {
  double last = 0.0;
  for (const SmallSpotTouchdown& t : touched) last = std::isfinite(t.X) ? std::max(last, t.X) : last;
  return last;
}

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
    double d = spacing(loaded);
    for (const std::size_t i : loaded) d = std::min(d, distance(i, k));
    return d;
  }
  /// The nearest distance from a site of `loaded` to another or its own image.
  double spacing(const std::vector<std::size_t>& loaded) const {
    double d = std::min(geometry_.Lx, geometry_.Ly);
    for (const std::size_t i : loaded) {
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
  /// The state from `from` where given (a converged state of the first sites of `loaded`, at
  /// a load near X: the sites that joined since start at a thousandth of its largest radius),
  /// or where Newton does not converge from there, from the isolated caps.
  State at(const std::vector<std::size_t>& loaded, double X, const State* from = nullptr) const {
    if (from != nullptr && from->converged && from->a.size() > 0 && from->a.size() <= static_cast<Eigen::Index>(loaded.size())) {
      State warm = solve(loaded, X, from);
      if (warm.converged) return warm;
    }
    return solve(loaded, X, nullptr);
  }
  State solve(const std::vector<std::size_t>& loaded, double X, const State* from) const {
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
    Eigen::VectorXd P0 = Eigen::VectorXd::Zero(N), M0 = Eigen::VectorXd::Zero(N);
    if (from != nullptr) {
      const Eigen::Index n = from->a.size();
      st.a.head(n) = from->a;
      st.a.tail(N - n).setConstant(1e-3 * from->a.maxCoeff());
      P0.head(n) = from->P;
      M0.head(n) = from->M2;
      st.delta = from->delta;
    } else {
      // Start: each cap an isolated punch sunk to one depth delta0 below the tallest tip
      // (Greenwood and Williamson's independent caps), delta0 such that they carry the load; a
      // cap in contact that delta0 does not reach (a lower site just joined) starts at a
      // thousandth of the largest radius. The curvatures, far-field moments and tilts start
      // from those caps' loads.
      const auto isolated_radius = [&](Eigen::Index i, double delta0) {
        const double depth = delta0 - geometry_.sites[site(loaded, i)].drop;
        return depth > 0.0 ? std::pow(depth / K_d_[site(loaded, i)], 1.0 / shape(loaded, i).s) : 0.0;
      };
      const auto isolated_load = [&](double delta0) {
        double sum = 0.0;
        for (Eigen::Index i = 0; i < N; ++i) sum += K_P_[site(loaded, i)] * std::pow(isolated_radius(i, delta0), shape(loaded, i).s + 1.0);
        return sum;
      };
      double least_drop = std::numeric_limits<double>::infinity();
      for (Eigen::Index i = 0; i < N; ++i) least_drop = std::min(least_drop, geometry_.sites[site(loaded, i)].drop);
      double deep = 1.0;
      while (isolated_load(least_drop + deep) < total) deep *= 2.0;
      const double delta0 = bisect_boundary([&](double d) { return isolated_load(least_drop + d) < total; }, 0.0, deep, 1e-15, 200).first + least_drop;
      for (Eigen::Index i = 0; i < N; ++i) {
        st.a(i) = isolated_radius(i, delta0);
        P0(i) = K_P_[site(loaded, i)] * std::pow(st.a(i), shape(loaded, i).s + 1.0);
        M0(i) = m2_[site(loaded, i)] * std::pow(st.a(i), shape(loaded, i).s + 3.0);
      }
      const double widest = st.a.maxCoeff();
      for (Eigen::Index i = 0; i < N; ++i) st.a(i) = std::max(st.a(i), 1e-3 * widest);
    }
    P0 *= total / P0.sum();
    Eigen::VectorXd eps = 0.25 * (L * P0), moment = 0.25 * (L * M0), tilt = tilts(loaded, P0);
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
    int restarts = 0;
    for (int outer = 0; outer < 40; ++outer) {
      // Newton on the radii and delta, the curvatures, far-field moments and tilts held:
      // drop_i - tilt_i + moment_i + F_i(a_i) + sum_j G_ij P_j(a_j) = delta, sum_j P_j(a_j) = total.
      Eigen::VectorXd a = st.a;
      double delta = st.delta;
      bool newton = false, collapsed = false;
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
          r(i) = geometry_.sites[site(loaded, i)].drop - tilt(i) + moment(i) + F(i) + GP(i) - delta;
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
        if (!a.allFinite()) break;
        if (a.minCoeff() < 1e-12 * a.maxCoeff()) {  // a site not in contact at this load (with these fields)
          collapsed = true;
          break;
        }
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
      tilt = tilts(loaded, P);
      if (!newton) {
        // A site just in contact whose spot the held fields close (the start's fields, a
        // little off the state's): again from this state's fields, its radius a thousandth
        // of the largest; twice at most.
        if (!collapsed || ++restarts > 2) break;
        st.a = a.cwiseMax(1e-3 * a.maxCoeff());
        continue;
      }
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
    const double tilt = tilt_of(target.shape, std::hypot(gx, gy));
    if (std::isnan(tilt)) return tilt;
    return st.delta - u + tilt;
  }

 private:
  /// How far a field of this slope lowers the gap of a cap of `shape` at its lowest point,
  /// off the tip where the field tilts, (s - 1) C y^s, y = (slope / (s C))^(1 / (s - 1)) (a
  /// paraboloid's vertex moved by the tilted plane, exactly); NaN for a cone the slope
  /// turns off its tip (slope > C), 0 for a cone within.
  static double tilt_of(const Shape& shape, double slope) {
    if (shape.s == 1) return slope > shape.C ? std::numeric_limits<double>::quiet_NaN() : 0.0;
    const double s = shape.s;
    const double y = std::pow(slope / (s * shape.C), 1.0 / (s - 1.0));
    return (s - 1.0) * shape.C * std::pow(y, s);
  }
  /// Each loaded site's tilt (tilt_of) in the field of the loads P of `loaded` (a scattered
  /// cell's caps lie on slopes of each other's fields; a lattice's by symmetry do not); 0
  /// for a cone.
  Eigen::VectorXd tilts(const std::vector<std::size_t>& loaded, const Eigen::VectorXd& P) const {
    Eigen::VectorXd out = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(loaded.size()));
    for (std::size_t i = 0; i < loaded.size(); ++i) {
      double gx = 0.0, gy = 0.0;
      for (std::size_t j = 0; j < loaded.size(); ++j) {
        gx += P(static_cast<Eigen::Index>(j)) * Gx_(loaded[i], loaded[j]);
        gy += P(static_cast<Eigen::Index>(j)) * Gy_(loaded[i], loaded[j]);
      }
      const double t = tilt_of(geometry_.sites[loaded[i]].shape, std::hypot(gx, gy));
      out(static_cast<Eigen::Index>(i)) = std::isnan(t) ? 0.0 : t;
    }
    return out;
  }
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

/// Whether the limit takes the cell: a level-0 site at drop 0 (the tallest tips; a
/// scattered supercell's other tall caps touch in turn, as lower sites do), at most
/// kSmallSpotMaxSites sites. The tallest sites, or none.
std::vector<std::size_t> tallest_sites(const CellGeometry& geometry) {
  std::vector<std::size_t> tallest;
  if (geometry.sites.empty() || geometry.sites.size() > kSmallSpotMaxSites) return {};
  for (std::size_t k = 0; k < geometry.sites.size(); ++k) {
    if (geometry.sites[k].level == 0 && geometry.sites[k].drop == 0.0) tallest.push_back(k);
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
  if (closing_level_ >= 1) {
    others_ = touchdowns(closing_level_);
    deepest_ = deepest_exposed_drop(geometry_, closing_level_);
  }
}

namespace {

/// small_spot_touchdowns of `geometry` (whose fields `cell` holds: the sites' places and
/// shapes, whatever their drops), its tallest sites `tallest`, the sites of `skipped_level`
/// left out; where `enough` > 0, only until that many sites of `counted_level` (every
/// site's for SmallSpotLimit::kEveryLevel) have touched, and only until past X_stop.
std::vector<SmallSpotTouchdown> touchdowns_of(const CellGeometry& geometry, const SmallSpotCell& cell, const std::vector<std::size_t>& tallest,
                                              int skipped_level, int counted_level = SmallSpotLimit::kEveryLevel, std::size_t enough = 0,
                                              double X_stop = std::numeric_limits<double>::infinity()) {
  std::vector<SmallSpotTouchdown> out(geometry.sites.size());
  std::vector<std::size_t> loaded = tallest;
  for (const std::size_t k : loaded) out[k] = {0.0, 0.0};
  // (The reach's first guess: the tallest caps' isolated spots, the cell shared among them.)
  const double share = geometry.Lx * geometry.Ly / static_cast<double>(tallest.size());
  const Shape& tall = geometry.sites[tallest[0]].shape;
  // The sites touch in turn: each round finds the least load at which an untouched site's
  // gap closes with the sites in contact so far (the root of the largest closure past its
  // drop, one state a trial load for every site), and the sites closed there (within 1e-9
  // of it) join them, as long as the limit holds for every untouched site: past the first
  // load where the spots outgrow one's nearest distance nothing more is answered (a site
  // there might have touched before the next).
  double X_from = 0.0;
  SmallSpotCell::State last;  // the last round's state where its sites joined
  for (;;) {
    std::vector<std::size_t> untouched;
    for (std::size_t k = 0; k < geometry.sites.size(); ++k) {
      if (std::find(loaded.begin(), loaded.end(), k) == loaded.end() && geometry.sites[k].level != skipped_level &&
          geometry.sites[k].drop > 0.0) {
        untouched.push_back(k);
      }
    }
    if (untouched.empty()) break;
    double reach = std::numeric_limits<double>::infinity();
    for (const std::size_t k : untouched) reach = std::min(reach, cell.nearest(loaded, k));
    // One state at load X: its largest spot, and how far the untouched sites' gaps are past
    // closing, the furthest (+infinity where the state is not found or a cone's tip is
    // tilted off).
    // (Each state starts from the round's first, at its floor, which starts from the last
    // round's.)
    struct Probe {
      double spot, excess;
      std::vector<double> excesses;
      SmallSpotCell::State state;
    };
    const SmallSpotCell::State* start = &last;
    const auto probe_at = [&](double X) {
      SmallSpotCell::State st = cell.at(loaded, X, start);
      Probe p{st.a.maxCoeff(), -std::numeric_limits<double>::infinity(), {}, {}};
      for (const std::size_t k : untouched) {
        const double c = cell.closure(loaded, st, k);
        p.excesses.push_back(std::isnan(c) || !st.converged ? std::numeric_limits<double>::infinity() : c - geometry.sites[k].drop);
        p.excess = std::max(p.excess, p.excesses.back());
      }
      p.state = std::move(st);
      return p;
    };
    const auto probe = [&](double log_X) { return probe_at(std::exp(log_X)); };
    const auto within = [&](const Probe& p) { return p.spot <= kSmallSpotMaxRatio * reach; };
    // The limit's reach: the largest load whose spots stay within kSmallSpotMaxRatio of the
    // nearest distance (bisection in log X), from just above the last touchdown (1e-6 of the
    // load past it: the sites that joined there have spots, not points, which the state's
    // solve, holding curvatures and moments while it moves the radii, finds).
    // Its first guess: the tallest caps' spots at twice that size, each isolated, the cell's
    // load shared among them; where the spots there are still within and no site has closed
    // (the load shared with more caps: a scattered cell's), four times the load, and on.
    double hi = std::log(load_coefficient(tall) * std::pow(2.0 * kSmallSpotMaxRatio * reach, tall.s + 1) / share);
    const double floor = X_from > 0.0 ? std::log(X_from) + 1e-6 : hi - 80.0;
    if (!(hi > floor)) hi = floor + std::log(4.0);
    const Probe at_floor = probe(floor);
    if (!within(at_floor) || !(at_floor.excess < 0.0)) break;
    start = &at_floor.state;
    double lo = floor;  // the last load known within, every site still open there
    double open = at_floor.excess;
    Probe at_hi = probe(hi);
    while (within(at_hi) && !(at_hi.excess >= 0.0) && hi < floor + 80.0) {
      lo = hi;
      open = at_hi.excess;
      hi += std::log(4.0);
      at_hi = probe(hi);
    }
    if (!within(at_hi)) {
      // The reach by bisection in log X (to 5e-6 of the range), stopped at the first load
      // within it where a site has closed: the root then lies below it, bracketed (the
      // reach is needed only where none closes before it).
      double in = lo, out = hi;
      bool closed = false;
      for (int i = 0; i < 24 && !closed; ++i) {
        const double mid = 0.5 * (in + out);
        Probe p = probe(mid);
        if (!within(p)) {
          out = mid;
        } else if (p.excess >= 0.0) {
          hi = mid;
          at_hi = std::move(p);
          closed = true;
        } else {
          in = lo = mid;
          open = p.excess;
        }
      }
      if (!closed) {
        hi = in;
        at_hi = probe(hi);
      }
    }
    if (!(at_hi.excess >= 0.0)) break;  // none closes within the reach
    const RootResult root = brent([&](double log_X) { return probe(log_X).excess; }, lo, hi, open, at_hi.excess, 1e-13);
    if (!root.converged) break;
    const double X = std::exp(root.x);
    // (A closure past its drop, found: +infinity is a state not found or a cone tilted off.)
    const Probe joined = probe_at(X * (1.0 + kJoined));
    const auto closed = [&](std::size_t i) { return joined.excesses[i] >= 0.0 && std::isfinite(joined.excesses[i]); };
    bool any = false;
    for (std::size_t i = 0; i < untouched.size(); ++i) {
      if (!closed(i)) continue;
      out[untouched[i]] = {X, joined.spot / cell.nearest(loaded, untouched[i])};
      any = true;
    }
    if (!any) break;
    for (std::size_t i = 0; i < untouched.size(); ++i) {
      if (closed(i)) loaded.push_back(untouched[i]);
    }
    last = joined.state;
    X_from = X;
    if (X_from > X_stop) break;
    if (enough > 0) {
      std::size_t touched = 0;
      for (std::size_t k = 0; k < out.size(); ++k) {
        touched += std::isfinite(out[k].X) && (counted_level == SmallSpotLimit::kEveryLevel || geometry.sites[k].level == counted_level);
      }
      if (touched >= enough) break;
    }
  }
  return out;
}

}  // namespace

std::vector<SmallSpotTouchdown> SmallSpotLimit::touchdowns(int skipped_level) const {
  if (!cell_) return std::vector<SmallSpotTouchdown>(geometry_.sites.size());
  return touchdowns_of(geometry_, *cell_, tallest_, skipped_level);
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
  if (!(drop < deepest_)) return std::nullopt;
  return drop;
}

std::optional<SmallSpotCount> SmallSpotLimit::counting(double X, std::size_t caps, int level) const {
  const int closing = closing_level_;
  if (!cell_ || closing < 1 || !(X > 0.0) || caps < 1) return std::nullopt;
  // The closing level's caps below its tallest (each keeps its offset below it; the deepest
  // drop at which its tips stay on the surface is the constructor's).
  double least_drop = std::numeric_limits<double>::infinity();
  std::size_t number = 0;  // of the caps counted
  for (const Site& site : geometry_.sites) {
    if (site.level == closing) least_drop = std::min(least_drop, site.drop);
    number += level == kEveryLevel || site.level == level ? 1 : 0;
  }
  if (caps > number) return std::nullopt;
  double deepest = deepest_;
  deepest *= 1.0 - 1e-8;
  if (!(deepest > 0.0) || !std::isfinite(deepest)) return std::nullopt;
  // The cell with the level's tallest cap at `drop`, its fields the limit's own (they do not
  // depend on the drops).
  CellGeometry moved = geometry_;
  const SmallSpotCell cell(moved);
  const auto move_to = [&](double drop) {
    for (std::size_t k = 0; k < moved.sites.size(); ++k) {
      if (moved.sites[k].level == closing) moved.sites[k].drop = drop + (geometry_.sites[k].drop - least_drop);
    }
  };
  const auto counted = [&](std::size_t k) { return level == kEveryLevel || moved.sites[k].level == level; };
  const double top = 1e-9 * deepest;  // (at drop 0 a cap of the level would be a tallest tip)
  if (level != kEveryLevel) {
    // One level's caps: the caps-th least of their touchdowns with the level's tallest cap at
    // `drop` (+infinity where the limit does not answer it: it answers the sites in the
    // order they touch, up to its reach), continuous in the drop. f = it less X rises with
    // the drop: the closing level's caps touch the later the deeper it lies, another level's
    // the sooner (its sign then turned). An unanswered touchdown lies where the caps in
    // contact outgrow the limit's reach (deep for the level's own, high for another's): +-10 X
    // stands for it, and the root found must be a touchdown the limit answers at X.
    const auto touch_at = [&](double drop) {
      move_to(drop);
      const std::vector<SmallSpotTouchdown> found = touchdowns_of(moved, cell, tallest_, -1, level, caps);
      std::vector<double> touches;
      for (std::size_t k = 0; k < moved.sites.size(); ++k) {
        if (counted(k) && std::isfinite(found[k].X)) touches.push_back(found[k].X);
      }
      if (touches.size() < caps) return std::numeric_limits<double>::infinity();
      std::nth_element(touches.begin(), touches.begin() + static_cast<std::ptrdiff_t>(caps - 1), touches.end());
      return touches[caps - 1];
    };
    const bool rising = level != closing;
    const auto f = [&](double drop) {
      const double touch = touch_at(drop);
      const double g = std::isfinite(touch) ? touch - X : 10.0 * X;
      return rising ? -g : g;
    };
    const double f_top = f(top), f_deepest = f(deepest);
    if (!(f_top < 0.0) || !(f_deepest > 0.0)) return std::nullopt;  // no crossing: an edge, for the contact solves
    const RootResult root = brent(f, top, deepest, f_top, f_deepest, 1e-10 * deepest);
    if (!root.converged || !(std::abs(touch_at(root.x) - X) <= 1e-6 * X)) return std::nullopt;
    return SmallSpotCount{root.x, true};
  }
  // Every cap: the count touched by X, which need not fall steadily as the level sinks (its
  // caps touch later, the other levels' sooner): by bisection over the drop, as
  // reference::LevelClosure counts, every trial's count kept to say whether it fell
  // steadily. A count the limit leaves incomplete (a site unanswered by X) is at least the
  // caps it answered by then; a trial it does not decide lies deep (the other caps carry the
  // load, their spots past the reach), and the answer stands where the last trial below it
  // was decided.
  struct Count {
    std::size_t n = 0;
    bool complete = true;
  };
  const auto count_at = [&](double drop) {
    move_to(drop);
    const std::vector<SmallSpotTouchdown> found = touchdowns_of(moved, cell, tallest_, -1, kEveryLevel, 0, X);
    const double answered = last_answered(found);
    Count c;
    for (std::size_t k = 0; k < moved.sites.size(); ++k) {
      if (found[k].X <= X) {
        ++c.n;
      } else if (!std::isfinite(found[k].X) && !(answered > X)) {
        c.complete = false;
      }
    }
    return c;
  };
  const auto above = [&](const Count& c) -> std::optional<bool> {  // at least `caps`: the drop lies above the answer
    if (c.n >= caps) return true;
    if (c.complete) return false;
    return std::nullopt;
  };
  std::vector<std::pair<double, Count>> trials;
  const auto trial = [&](double drop) {
    trials.emplace_back(drop, count_at(drop));
    return trials.back().second;
  };
  const Count at_top = trial(top), at_deepest = trial(deepest);
  const std::optional<bool> top_above = above(at_top), deepest_above = above(at_deepest);
  if (!top_above || !*top_above || (deepest_above && *deepest_above)) return std::nullopt;  // no crossing: an edge
  double lo = top, hi = deepest;
  std::optional<bool> hi_above = deepest_above;
  while (hi - lo > 1e-10 * deepest) {
    const double mid = 0.5 * (lo + hi);
    const std::optional<bool> mid_above = above(trial(mid));
    if (mid_above.value_or(false)) {
      lo = mid;
    } else {
      hi = mid;
      hi_above = mid_above;
    }
  }
  if (!hi_above) return std::nullopt;
  // Steady: every decided count no greater than any decided at a shallower trial.
  std::sort(trials.begin(), trials.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  bool steady = true;
  std::size_t least = std::numeric_limits<std::size_t>::max();
  for (const auto& [drop, c] : trials) {
    if (!c.complete) continue;
    if (c.n > least) steady = false;
    least = std::min(least, c.n);
  }
  return SmallSpotCount{lo, steady};
}

std::vector<LoadCurveSample> SmallSpotLimit::samples(const std::vector<double>& loads, const std::vector<SmallSpotTouchdown>& touched) const {
  std::vector<LoadCurveSample> out;
  if (!cell_ || touched.size() != geometry_.sites.size()) return out;
  // The sites below the tallest in the order they touch: the sites in contact at a load are
  // the tallest and a first part of them (each state then starts from the last).
  std::vector<std::size_t> order;
  const double answered = last_answered(touched);
  for (std::size_t k = 0; k < touched.size(); ++k) {
    if (std::find(tallest_.begin(), tallest_.end(), k) == tallest_.end()) order.push_back(k);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return touched[i].X < touched[j].X; });
  const std::size_t L = static_cast<std::size_t>(geometry_.levels());
  SmallSpotCell::State last;
  for (const double X : loads) {
    if (!(X > 0.0)) break;
    // The sites in contact by X (touched before it, by more than kJoined of its load: a site
    // closing at X has no spot yet); one the limit leaves unanswered touches past the last
    // it answered, so only after X where that lies past X.
    std::vector<std::size_t> loaded = tallest_, open;
    for (const std::size_t k : order) (touched[k].X * (1.0 + kJoined) < X ? loaded : open).push_back(k);
    if (std::any_of(open.begin(), open.end(), [&](std::size_t k) { return !std::isfinite(touched[k].X); }) && !(answered > X)) break;
    SmallSpotCell::State st = cell_->at(loaded, X, last.converged && last.a.size() <= static_cast<Eigen::Index>(loaded.size()) ? &last : nullptr);
    if (!st.converged) break;
    double reach = cell_->spacing(loaded);
    for (const std::size_t k : open) reach = std::min(reach, cell_->nearest(loaded, k));
    if (!(st.a.maxCoeff() <= kSmallSpotMaxRatio * reach)) break;
    LoadCurveSample sample;
    sample.X = X;
    sample.level_load.assign(L, 0.0);
    sample.level_area.assign(L, 0.0);
    for (std::size_t i = 0; i < loaded.size(); ++i) {
      const std::size_t level = static_cast<std::size_t>(geometry_.sites[loaded[i]].level);
      const Eigen::Index I = static_cast<Eigen::Index>(i);
      sample.level_load[level] += st.P(I);
      sample.level_area[level] += std::numbers::pi * st.a(I) * st.a(I);
    }
    out.push_back(std::move(sample));
    last = std::move(st);
  }
  return out;
}

std::vector<SmallSpotTouchdown> small_spot_touchdowns(const CellGeometry& geometry) { return SmallSpotLimit(geometry).touchdowns(); }

std::size_t answer_small_spots(LoadCurve& curve, const CellGeometry& geometry, const std::vector<SmallSpotTouchdown>& limit) {
  curve.level_small_spot.assign(static_cast<std::size_t>(curve.levels()), 0);
  curve.site_small_spot.assign(curve.sites(), 0);
  if (geometry.sites.size() != curve.sites() || limit.size() != curve.sites()) return 0;
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
    if (!(limit[k].X > 0.0) || !std::isfinite(limit[k].X) || own == 0.0) continue;  // (the tallest tips: 0)
    if (!std::isfinite(own) && !(stopped && limit[k].X > curve.X_last() && tip_exposed(geometry, surface, k))) continue;
    curve.site_touchdown[k] = limit[k].X;
    curve.site_small_spot[k] = 1;
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

namespace {

/// resolve_small_spots' loads, from the geometry alone (so a curve built to any reach reads
/// the same there): from a decade below the first touchdown past the tallest tips (or below
/// `below` where none is), kSmallSpotSamplesPerDecade a decade on, and at every touchdown
/// (the site joining there still without a spot). The limit holds over a first part of
/// them (a spot reaches kSmallSpotMaxRatio of its distances long before full contact).
std::vector<double> small_spot_loads(const std::vector<SmallSpotTouchdown>& touched, double below) {
  double first = std::numeric_limits<double>::infinity();
  for (const SmallSpotTouchdown& t : touched) {
    if (t.X > 0.0 && t.X < first) first = t.X;
  }
  if (!std::isfinite(first)) first = below;
  const double X_low = 0.1 * first;
  std::vector<double> loads;
  for (int k = 0; k <= 16 * kSmallSpotSamplesPerDecade; ++k) loads.push_back(X_low * std::pow(10.0, static_cast<double>(k) / kSmallSpotSamplesPerDecade));
  for (const SmallSpotTouchdown& t : touched) {
    if (t.X > 0.0 && std::isfinite(t.X)) loads.push_back(t.X);
  }
  std::sort(loads.begin(), loads.end());
  loads.erase(std::unique(loads.begin(), loads.end()), loads.end());
  // (A load of the decades' within kJoined of a touchdown is the touchdown's: the decade that
  // starts at a tenth of the first touchdown meets it again to rounding, and a state there
  // just past it would hold a site without a spot.)
  const auto at_touchdown = [&](double X) {
    return std::any_of(touched.begin(), touched.end(), [&](const SmallSpotTouchdown& t) {
      return t.X > 0.0 && std::isfinite(t.X) && X != t.X && std::abs(X - t.X) <= kJoined * t.X;
    });
  };
  loads.erase(std::remove_if(loads.begin(), loads.end(), at_touchdown), loads.end());
  return loads;
}

}  // namespace

double small_spot_reach(const SmallSpotLimit& limit, const std::vector<SmallSpotTouchdown>& touched, double below) {
  if (!limit.answers() || !(below > 0.0)) return 0.0;
  const std::vector<LoadCurveSample> held = limit.samples(small_spot_loads(touched, below), touched);
  return held.empty() ? 0.0 : held.back().X;
}

bool resolve_small_spots(LoadCurve& curve, const SmallSpotLimit& limit, const std::vector<SmallSpotTouchdown>& touched) {
  if (touched.size() != curve.sites() || curve.samples.empty() || !(curve.X_resolved > curve.X_first())) return false;
  if (!limit.answers()) return false;
  // The limit's loads (its states as far as it holds).
  const std::vector<double> loads = small_spot_loads(touched, curve.X_first());
  std::vector<LoadCurveSample> samples = limit.samples(loads, touched);
  // Only where it holds up to the curve's resolution: the readings below X_resolved are then
  // all the limit's, those past its reach the curve's resolved samples.
  if (samples.empty() || samples.back().X < curve.X_resolved) return false;
  // Refinement, as the curve's own: after a touchdown a new spot's area grows as a power of
  // X - X* that the readings' interpolation does not follow, so an interval whose start lies
  // within twice a touchdown is halved in log X until the readings meet the limit's state at
  // its middle (each level's area to 1e-3 of itself, its load share to 1e-4; no grid's node
  // enters, so every grid reads the same), at most LoadCurveOptions' 10 times.
  const double node_area = 1e-12 * curve.cell_area;  // (rounding's floor)
  for (int pass = 0; pass < 10; ++pass) {
    LoadCurve reading = curve;
    reading.samples = samples;
    reading.pressure_monotone.assign(samples.size() - 1, 1);
    reading.X_full = std::numeric_limits<double>::infinity();
    // (The middles' states in one pass of the limit, each started from the last.)
    std::vector<double> middles;
    for (std::size_t k = 0; k + 1 < samples.size(); ++k) {
      const double a = samples[k].X, b = samples[k + 1].X;
      if (std::any_of(touched.begin(), touched.end(), [&](const SmallSpotTouchdown& t) { return t.X > 0.0 && t.X <= a && a <= 2.0 * t.X; })) {
        middles.push_back(std::sqrt(a * b));
      }
    }
    std::vector<LoadCurveSample> added;
    for (LoadCurveSample& truth : limit.samples(middles, touched)) {
      const CurveState read = reading.at(truth.X);
      bool missed = false;
      for (std::size_t level = 0; level < truth.level_area.size(); ++level) {
        const double area = truth.level_area[level];
        missed = missed || std::abs(read.level_area[level] - area) > 1e-3 * area + node_area ||
                 std::abs(read.level_load[level] - truth.level_load[level]) > 1e-4 * truth.X * curve.cell_area;
      }
      if (missed) added.push_back(std::move(truth));
    }
    if (added.empty()) break;
    samples.insert(samples.end(), std::make_move_iterator(added.begin()), std::make_move_iterator(added.end()));
    std::sort(samples.begin(), samples.end(), [](const LoadCurveSample& x, const LoadCurveSample& y) { return x.X < y.X; });
  }
  // The curve past the limit's reach (its samples beyond the last the limit holds at), the
  // limit's before: where the curve stopped within the reach, the limit's samples go on to
  // the reach (they hold there), as a curve built further reads.
  const double held = samples.back().X;
  const auto kept = std::upper_bound(curve.samples.begin(), curve.samples.end(), held,
                                     [](double x, const LoadCurveSample& s) { return x < s.X; });
  const std::size_t dropped = static_cast<std::size_t>(kept - curve.samples.begin());
  // (The limit's loads grow with X: no node unloads.)
  std::vector<char> monotone(samples.size() - (kept == curve.samples.end() ? 1 : 0), 1);
  if (kept != curve.samples.end()) {
    monotone.insert(monotone.end(), curve.pressure_monotone.begin() + static_cast<std::ptrdiff_t>(dropped), curve.pressure_monotone.end());
  }
  samples.insert(samples.end(), kept, curve.samples.end());
  curve.samples = std::move(samples);
  curve.pressure_monotone = std::move(monotone);
  curve.X_resolved = curve.X_first();
  curve.X_small_spot = held;
  return true;
}

}  // namespace punchsweep::model
