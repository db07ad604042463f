#include "model/problem/cell_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "model/numerics/integer_power.hpp"

namespace punchsweep::model {

int CellGeometry::levels() const {
  int top = -1;
  for (const Site& site : sites) top = std::max(top, site.level);
  return top + 1;
}

std::string geometry_error(const CellGeometry& g) {
  std::ostringstream out;
  out.precision(17);
  if (!(std::isfinite(g.Lx) && g.Lx > 0.0 && std::isfinite(g.Ly) && g.Ly > 0.0)) {
    out << "cell " << g.Lx << " x " << g.Ly << " R is outside its range: Lx, Ly finite and > 0";
    return out.str();
  }
  if (g.sites.empty()) return "the cell has no site: it needs at least one punch";
  std::vector<bool> seen(g.sites.size(), false);
  for (std::size_t k = 0; k < g.sites.size(); ++k) {
    const Site& site = g.sites[k];
    out << "site " << k << ": ";
    if (!(site.x >= 0.0 && site.x < g.Lx && site.y >= 0.0 && site.y < g.Ly)) {
      out << "(" << site.x << ", " << site.y << ") R is outside the cell: 0 <= x < " << g.Lx << ", 0 <= y < " << g.Ly;
      return out.str();
    }
    if (site.shape.s < Shape::kMinExponent || site.shape.s > Shape::kMaxExponent) {
      out << "s = " << site.shape.s << " is outside its range: an integer in [" << Shape::kMinExponent << ", "
          << Shape::kMaxExponent << "]";
      return out.str();
    }
    if (!(std::isfinite(site.shape.C) && site.shape.C > 0.0)) {
      out << "C = " << site.shape.C << " is outside its range: C > 0";
      return out.str();
    }
    if (!(std::isfinite(site.drop) && site.drop >= 0.0)) {
      out << "drop = " << site.drop << " R is outside its range: finite and >= 0";
      return out.str();
    }
    // (Numbered without gaps, the levels are fewer than the sites: a larger number is
    // refused before it sizes anything.)
    if (site.level < 0 || static_cast<std::size_t>(site.level) >= g.sites.size()) {
      out << "level = " << site.level << " is outside its range: an integer in [0, " << g.sites.size() - 1
          << "], the levels numbered 0, 1, ... without gaps";
      return out.str();
    }
    seen[static_cast<std::size_t>(site.level)] = true;
    out.str("");
  }
  const std::size_t levels = static_cast<std::size_t>(g.levels());
  for (std::size_t level = 0; level < levels; ++level) {
    if (!seen[level]) {
      out << "level " << level << " has no site: the levels are numbered 0 .. " << levels - 1 << " without gaps";
      return out.str();
    }
  }
  return {};
}

namespace {
/// d wrapped into [-L/2, L/2]: the offset to the nearest periodic image.
double wrapped(double d, double L) { return d - L * std::nearbyint(d / L); }
}  // namespace

SurfaceLocator::SurfaceLocator(const CellGeometry& geometry) : geometry_(geometry) {
  const std::vector<Site>& sites = geometry.sites;
  const double n = static_cast<double>(std::max<std::size_t>(sites.size(), 1));
  // Buckets of about the mean spacing (at most 2048 each way).
  const double spacing = std::sqrt(geometry.Lx * geometry.Ly / n);
  const auto count = [&](double L) { return static_cast<int>(std::clamp(std::floor(L / spacing), 1.0, 2048.0)); };
  bx_ = count(geometry.Lx);
  by_ = count(geometry.Ly);
  wx_ = geometry.Lx / bx_;
  wy_ = geometry.Ly / by_;
  buckets_.resize(static_cast<std::size_t>(bx_) * static_cast<std::size_t>(by_));
  for (std::size_t k = 0; k < sites.size(); ++k) buckets_[bucket_of(sites[k].x, sites[k].y)].push_back(k);
  // The bound of the surface: each point x lies within `half` (a coarse cell's half
  // diagonal) of a coarse point p, and z(x) <= f_k(d(p, k) + half) + drop_k for any site k
  // (f grows with r); the least of these over the sites about p, the greatest over p.
  reach_.assign(sites.size(), std::numeric_limits<double>::infinity());
  span_x_ = span_y_ = 2;
  const int cx = 2 * bx_, cy = 2 * by_;
  const double half = 0.5 * std::hypot(geometry.Lx / cx, geometry.Ly / cy);
  top_ = -std::numeric_limits<double>::infinity();
  for (int a = 0; a < cx; ++a) {
    for (int b = 0; b < cy; ++b) {
      const double px = (a + 0.5) * geometry.Lx / cx, py = (b + 0.5) * geometry.Ly / cy;
      double bound = std::numeric_limits<double>::infinity();
      for (int span = 2; !std::isfinite(bound); span *= 2) {
        span_x_ = span_y_ = span;
        visit(px, py, [&](std::size_t k, double r) { bound = std::min(bound, surface(k, r + half)); });
        if (span > 2 * std::max(bx_, by_)) break;  // every bucket read
      }
      top_ = std::max(top_, bound);
    }
  }
  double longest = 0.0;
  for (std::size_t k = 0; k < sites.size(); ++k) {
    const Site& site = sites[k];
    reach_[k] = top_ >= site.drop ? std::pow((top_ - site.drop) / site.shape.C, 1.0 / site.shape.s) : -1.0;
    longest = std::max(longest, reach_[k]);
  }
  const auto span = [](double reach, double width, int buckets) {
    return static_cast<int>(std::min(std::ceil(reach / width), static_cast<double>(buckets)));
  };
  span_x_ = span(longest, wx_, bx_);
  span_y_ = span(longest, wy_, by_);
}

double SurfaceLocator::surface(std::size_t k, double r) const {
  const Site& site = geometry_.sites[k];
  return site.shape.C * ipow(r, site.shape.s) + site.drop;
}

double SurfaceLocator::distance(double x, double y, std::size_t k) const {
  const Site& site = geometry_.sites[k];
  return std::hypot(wrapped(x - site.x, geometry_.Lx), wrapped(y - site.y, geometry_.Ly));
}

std::size_t SurfaceLocator::bucket_of(double x, double y) const {
  const auto index = [](double c, double L, double w, int n) {
    const double inside = c - L * std::floor(c / L);
    return static_cast<std::size_t>(std::clamp(static_cast<int>(std::floor(inside / w)), 0, n - 1));
  };
  return index(x, geometry_.Lx, wx_, bx_) * static_cast<std::size_t>(by_) + index(y, geometry_.Ly, wy_, by_);
}

bool tip_exposed(const CellGeometry& geometry, const SurfaceLocator& surface, std::size_t k, std::size_t* by) {
  const Site& site = geometry.sites[k];
  const double same = 1e-12 * std::max(geometry.Lx, geometry.Ly);
  // An earlier site at the same tip (a duplicate) covers it.
  std::size_t cover =
      surface.lowest(site.x, site.y, [&](std::size_t q) { return q < k && surface.distance(site.x, site.y, q) <= same; }).second;
  if (cover == geometry.sites.size()) {
    const auto [low, q] = surface.lowest(site.x, site.y, [k](std::size_t other) { return other != k; });
    // (A tie counts as covered, as the periodic tables count dh at the tall caps' surface
    // hidden: the tip then never stands out of the taller cap.)
    if (q < geometry.sites.size() && low - site.drop <= 1e-12 * std::max(std::abs(site.drop), std::abs(low))) cover = q;
  }
  if (by != nullptr) *by = cover;
  return cover == geometry.sites.size();
}

std::size_t covered_site(const CellGeometry& geometry, const SurfaceLocator& surface, std::size_t* by) {
  for (std::size_t k = 0; k < geometry.sites.size(); ++k) {
    if (!tip_exposed(geometry, surface, k, by)) return k;
  }
  if (by != nullptr) *by = geometry.sites.size();
  return geometry.sites.size();
}

double deepest_exposed_drop(const CellGeometry& geometry, int level) {
  double least = std::numeric_limits<double>::infinity();
  for (const Site& site : geometry.sites) {
    if (site.level == level) least = std::min(least, site.drop);
  }
  const SurfaceLocator surface(geometry);
  double deepest = std::numeric_limits<double>::infinity();
  for (const Site& tip : geometry.sites) {
    if (tip.level != level) continue;
    for (std::size_t j = 0; j < geometry.sites.size(); ++j) {
      if (geometry.sites[j].level == level) continue;
      deepest = std::min(deepest, surface.surface(j, surface.distance(tip.x, tip.y, j)) - (tip.drop - least));
    }
  }
  return deepest;
}

namespace {

/// Whether each site's image (x, y) -> image(x, y) is a site of the same shape, drop and
/// level, positions within 1e-12 of the cell, modulo it.
template <class Image>
bool sites_even(const CellGeometry& g, const Image& image) {
  const auto same = [](double a, double b, double L) {
    const double d = std::fmod(std::abs(a - b), L);
    return std::min(d, L - d) <= 1e-12 * L;
  };
  const auto has = [&](double x, double y, const Site& like) {
    return std::any_of(g.sites.begin(), g.sites.end(), [&](const Site& o) {
      return same(o.x, x, g.Lx) && same(o.y, y, g.Ly) && o.shape.s == like.shape.s && o.shape.C == like.shape.C &&
             o.drop == like.drop && o.level == like.level;
    });
  };
  return std::all_of(g.sites.begin(), g.sites.end(), [&](const Site& s) {
    const auto [x, y] = image(s);
    return has(x, y, s);
  });
}

}  // namespace

bool mirror_symmetric_x(const CellGeometry& g) {
  return sites_even(g, [&](const Site& s) { return std::pair{g.Lx - s.x, s.y}; });
}

bool mirror_symmetric(const CellGeometry& g) {
  return mirror_symmetric_x(g) && sites_even(g, [&](const Site& s) { return std::pair{s.x, g.Ly - s.y}; });
}

std::string lattice_name(LatticeKind lattice) { return lattice == LatticeKind::square ? "square" : "hexagonal"; }

CellGeometry lattice_cell(LatticeKind lattice, double l, const Shape& shape, const std::vector<double>& drops) {
  if (drops.size() > 2) throw std::invalid_argument("lattice_cell: at most two levels below the tallest");
  CellGeometry g;
  const auto add = [&](double x, double y, std::size_t level) {
    g.sites.push_back(Site{x, y, shape, level == 0 ? 0.0 : drops[level - 1], static_cast<int>(level)});
  };
  const std::size_t last = std::min<std::size_t>(drops.size(), 2);  // the highest level placed
  if (lattice == LatticeKind::square) {
    g.Lx = g.Ly = l;
    add(0.0, 0.0, 0);
    if (last >= 1) add(0.5 * l, 0.5 * l, 1);
    if (last >= 2) {
      add(0.5 * l, 0.0, 2);
      add(0.0, 0.5 * l, 2);
    }
  } else {
    const double height = l * std::sqrt(3.0);
    g.Lx = l;
    g.Ly = height;
    add(0.0, 0.0, 0);
    add(0.5 * l, 0.5 * height, 0);
    if (last >= 1) {
      const std::size_t down = last >= 2 ? 2 : 1;
      add(0.5 * l, height / 6.0, 1);        // upward triangles' centres
      add(0.0, 4.0 * height / 6.0, 1);
      add(0.0, 2.0 * height / 6.0, down);   // downward triangles' centres
      add(0.5 * l, 5.0 * height / 6.0, down);
    }
  }
  return g;
}

namespace {

/// `scatter`'s draws for `count` sites from `engine` (list: its values).
std::vector<double> draws_from(const HeightScatter& scatter, std::size_t count, std::mt19937_64& engine) {
  using Kind = HeightScatter::Kind;
  if (scatter.kind == Kind::list) {
    if (scatter.values.size() != count) {
      throw std::invalid_argument("scatter list: " + std::to_string(scatter.values.size()) + " values for " +
                                  std::to_string(count) + " sites");
    }
    return scatter.values;
  }
  std::vector<double> out(count, 0.0);
  if (scatter.kind == Kind::none) return out;
  // A double in (0, 1) from the engine's top 53 bits (never 0: Box-Muller takes its log).
  const auto unit = [&engine]() { return (static_cast<double>(engine() >> 11) + 0.5) * 0x1.0p-53; };
  for (std::size_t k = 0; k < count; ++k) {
    if (scatter.kind == Kind::uniform) {
      out[k] = scatter.width * (2.0 * unit() - 1.0);
    } else {
      const double u1 = unit(), u2 = unit();
      out[k] = scatter.width * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
    }
  }
  return out;
}

}  // namespace

bool drawn_at_random(const HeightScatter& scatter) {
  return scatter.kind == HeightScatter::Kind::normal || scatter.kind == HeightScatter::Kind::uniform;
}

std::vector<double> scatter_draws(const HeightScatter& scatter, std::size_t count) {
  std::mt19937_64 engine(scatter.seed);
  return draws_from(scatter, count, engine);
}

double tallest_rise_quantile(const HeightScatter& scatter, const std::vector<double>& drops, const std::vector<double>& counts,
                             double q) {
  const bool normal = scatter.kind == HeightScatter::Kind::normal;
  if (!drawn_at_random(scatter) || !(scatter.width > 0.0) || !(q > 0.0 && q < 1.0) ||
      drops.size() != counts.size() || drops.empty()) {
    throw std::invalid_argument("tallest_rise_quantile: a normal or uniform scatter of width > 0, 0 < q < 1, a count per drop");
  }
  const double w = scatter.width;
  // log F(x) of one draw: the normal's through its upper tail where that is small (log1p
  // keeps the digits that 1 - tail would lose).
  const auto log_cdf = [&](double x) {
    if (normal) {
      const double z = x / w;
      return z > 0.0 ? std::log1p(-0.5 * std::erfc(z / std::numbers::sqrt2)) : std::log(0.5 * std::erfc(-z / std::numbers::sqrt2));
    }
    const double F = std::clamp((x + w) / (2.0 * w), 0.0, 1.0);
    return std::log(F);
  };
  const auto log_probability = [&](double x) {  // log P(the tallest tip lies at most x above)
    double sum = 0.0;
    for (std::size_t L = 0; L < drops.size(); ++L) {
      if (counts[L] > 0.0) sum += counts[L] * log_cdf(x + drops[L]);
    }
    return sum;
  };
  const double target = std::log(q);
  double lo = -40.0 * w, hi = 40.0 * w;  // (a normal draw past 40 SD: probability below 1e-300)
  while (hi - lo > 1e-12 * w) {
    const double mid = 0.5 * (lo + hi);
    (log_probability(mid) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

CellGeometry supercell(const CellGeometry& cell, int K, const HeightScatter& scatter, const HeightScatter& curvature,
                       double* rise) {
  if (K < 1) throw std::invalid_argument("supercell: K >= 1");
  CellGeometry out;
  out.Lx = K * cell.Lx;
  out.Ly = K * cell.Ly;
  const std::size_t count = static_cast<std::size_t>(K) * K * cell.sites.size();
  std::mt19937_64 engine(drawn_at_random(scatter) ? scatter.seed : curvature.seed);
  const std::vector<double> draws = draws_from(scatter, count, engine);
  const std::vector<double> changes = draws_from(curvature, count, engine);
  std::size_t next = 0;
  for (const Site& site : cell.sites) {
    for (int i = 0; i < K; ++i) {
      for (int j = 0; j < K; ++j) {
        Site copy = site;
        copy.x += i * cell.Lx;
        copy.y += j * cell.Ly;
        copy.drop += draws[next];
        copy.shape.C *= 1.0 + changes[next];
        if (!(copy.shape.C > 0.0) || !std::isfinite(copy.shape.C)) {
          throw std::invalid_argument("supercell: cap " + std::to_string(next) + "'s curvature change " +
                                      std::to_string(changes[next]) + " leaves its C at " + std::to_string(copy.shape.C) +
                                      ": every change must be > -1");
        }
        ++next;
        out.sites.push_back(copy);
      }
    }
  }
  double least = std::numeric_limits<double>::infinity(), design = std::numeric_limits<double>::infinity();
  for (const Site& site : out.sites) least = std::min(least, site.drop);
  for (const Site& site : cell.sites) design = std::min(design, site.drop);
  for (Site& site : out.sites) site.drop -= least;
  if (rise != nullptr) *rise = design - least;
  return out;
}

CellGeometry two_level_square(const ContactProblem& problem) {
  const double half = 0.5 * problem.l;
  return {problem.l, problem.l, {Site{0.0, 0.0, problem.shape, 0.0, 0}, Site{half, half, problem.shape, problem.dh, 1}}};
}

}  // namespace punchsweep::model
