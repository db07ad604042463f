#include "model/shells/shell_sums.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>
#include <random>
#include <tuple>
#include <utility>

#include "model/numerics/chebyshev.hpp"

namespace punchsweep::model {
namespace {

constexpr double kPi = std::numbers::pi;
/// The nearest other-level punch, at l/sqrt(2): spots of radii x and y touch at x + y = this.
constexpr double kCrossReach = 1.0 / std::numbers::sqrt2;
/// Shells nearer than this (in l) are tabulated piecewise; beyond it x + y <= 1 is at most
/// a third of the distance and the sums are smooth (one piece).
constexpr double kNearDistance = 3.0;
/// The tables' range: the family's states keep their spots apart by Localization::kMergeMargin,
/// same-level radii x <= kSameEdge and x + y <= kCrossEdge; t = x / (kCrossEdge - y) in [0, 1].
constexpr double kRadiusReach = 0.5;
constexpr double kSameEdge = 0.5 * Localization::kMergeMargin;
constexpr double kCrossEdge = Localization::kMergeMargin * kCrossReach;
/// How far past their edges the tables are read (extrapolated): a Newton solve's difference
/// steps from a state at the margin. The sums are analytic well beyond (the spots touch a
/// further 1 - kMergeMargin away).
constexpr double kEdgeSlack = 1e-3;
/// Interpolation nodes: per patch along the piecewise variable, along y (in kIntervals
/// equal intervals of [0, kRadiusReach]), and of the far shells' smooth piece.
constexpr int kPatchNodes = 16;
constexpr int kCrossNodes = 16;
constexpr int kIntervals = 4;
constexpr double kIntervalWidth = kRadiusReach / kIntervals;
constexpr int kFarNodes = 16;
/// The first patches halve toward the touching edge this many times.
constexpr int kGradedPatches = 6;
/// Narrower patches are accepted as they are (the functions are continuous at the edge).
constexpr double kMinPatch = 1e-4;

bool within(const ShellSums::Sums& table, const ShellSums::Sums& exact, double scale) {
  return std::abs(table.carried - exact.carried) <= scale * ShellSums::kTableTolerance &&
         std::abs(table.depth - exact.depth) <= scale * ShellSums::kTableTolerance * (1.0 + std::abs(exact.depth));
}

/// Values (carried, depth) on a tensor grid, [j_t][interval][j_u][value] -> coefficients
/// [k_t][interval][k_u][value], both directions transformed.
std::vector<double> tensor_coefficients(const std::vector<double>& values, int nt, int intervals, int nu) {
  const int columns = intervals * nu * 2;
  std::vector<double> along_t(values.size());
  for (int col = 0; col < columns; ++col) {
    const std::vector<double> c = chebyshev::coefficients(values.data() + col, nt, columns);
    for (int k = 0; k < nt; ++k) along_t[k * columns + col] = c[k];
  }
  if (nu == 1) return along_t;
  std::vector<double> out(values.size());
  for (int k = 0; k < nt; ++k) {
    for (int iv = 0; iv < intervals; ++iv) {
      for (int v = 0; v < 2; ++v) {
        const int base = (k * intervals + iv) * nu * 2 + v;
        const std::vector<double> c = chebyshev::coefficients(along_t.data() + base, nu, 2);
        for (int m = 0; m < nu; ++m) out[base + m * 2] = c[m];
      }
    }
  }
  return out;
}

/// The tensor interpolant at (unit t, interval, unit u): sum_k T_k(t) sum_m T_m(u) c[k][m],
/// summed over k first for every (m, value) at once (independent lanes that vectorize,
/// where nested Clenshaw recurrences wait on each other).
ShellSums::Sums tensor_value(const std::vector<double>& c, int nt, int intervals, int nu, double t, int interval,
                             double u) {
  constexpr int kMax = 64;
  double Tt[kMax];
  double Tu[kMax];
  chebyshev::polynomials(t, nt, Tt);
  chebyshev::polynomials(u, nu, Tu);
  double along_u[2 * kMax] = {};  // [m][value]
  for (int k = 0; k < nt; ++k) {
    const double* row = c.data() + (k * intervals + interval) * nu * 2;
    const double w = Tt[k];
    for (int j = 0; j < 2 * nu; ++j) along_u[j] += w * row[j];
  }
  ShellSums::Sums out;
  for (int m = 0; m < nu; ++m) {
    out.carried += Tu[m] * along_u[2 * m];
    out.depth += Tu[m] * along_u[2 * m + 1];
  }
  return out;
}

}  // namespace

ShellSums::ShellSums(int s, Localization localization) : ShellSums(s, localization, true) {}

ShellSums::ShellSums(int s, Localization localization, bool build) : localization_(localization), s_(s), spot_(s) {
  for (const DistanceShell& shell : kept_neighbours(1, localization.shells)) {
    const bool near = shell.distance < kNearDistance;
    if (shell.level == 1) {
      (near ? same_near_ : same_far_).push_back(shell);
      same_count_ += shell.count;
    } else {
      (near ? cross_near_ : cross_far_).push_back(shell);
      cross_count_ += shell.count;
    }
  }
  if (localization.distributed && build) build_tables();
}

void ShellSums::build_tables() {
  // The far shells: one smooth piece in x (same) and in (x, y) (cross).
  const std::vector<double> xf = chebyshev::nodes(kFarNodes, 0.0, kRadiusReach);
  {
    std::vector<double> values;
    for (const double x : xf) {
      const Sums v = direct(same_far_, x, x);
      values.insert(values.end(), {v.carried, v.depth});
    }
    same_far_table_ = tensor_coefficients(values, kFarNodes, 1, 1);
  }
  {
    std::vector<double> values;
    for (const double x : xf) {
      for (const double y : xf) {
        const Sums v = direct(cross_far_, x, y);
        values.insert(values.end(), {v.carried, v.depth});
      }
    }
    cross_far_table_ = tensor_coefficients(values, kFarNodes, 1, kFarNodes);
  }

  // The near shells: patches along the variable in which the nearest spots touch, split
  // until the interpolant meets the direct sums at points between its nodes.
  std::vector<double> u_nodes;
  for (int iv = 0; iv < kIntervals; ++iv) {
    for (const double y : chebyshev::nodes(kCrossNodes, iv * kIntervalWidth, (iv + 1) * kIntervalWidth)) {
      u_nodes.push_back(y);
    }
  }
  const auto build = [&](double lo, double hi, bool cross, std::vector<Patch>* patches) {
    const int nu = cross ? kCrossNodes : 1;
    // Values at one t over all y nodes (cross) or at x = t (same).
    const auto column = [&](double t, std::vector<double>* values) {
      if (!cross) {
        const Sums v = direct(same_near_, t, t);
        values->insert(values->end(), {v.carried, v.depth});
        return;
      }
      for (const double y : u_nodes) {
        const Sums v = direct(cross_near_, t * (kCrossEdge - y), y);
        values->insert(values->end(), {v.carried, v.depth});
      }
    };
    std::function<void(double, double)> refine = [&](double a, double b) {
      std::vector<double> values;
      for (const double t : chebyshev::nodes(kPatchNodes, a, b)) column(t, &values);
      Patch patch{a, b, tensor_coefficients(values, kPatchNodes, cross ? kIntervals : 1, nu)};
      bool good = true;
      for (const double share : {0.25, 0.5, 0.75}) {
        const double t = a + share * (b - a);
        std::vector<double> exact;
        column(t, &exact);
        for (int col = 0; good && col < static_cast<int>(exact.size()) / 2; ++col) {
          const int iv = col / nu;
          const double u = cross ? chebyshev::unit(u_nodes[col], iv * kIntervalWidth, (iv + 1) * kIntervalWidth) : 0.0;
          const Sums table =
              tensor_value(patch.coefficients, kPatchNodes, cross ? kIntervals : 1, nu, chebyshev::unit(t, a, b), iv, u);
          good = within(table, Sums{exact[2 * col], exact[2 * col + 1]}, 0.1);
        }
      }
      if (good || b - a < kMinPatch) {
        patches->push_back(std::move(patch));
        return;
      }
      refine(a, 0.5 * (a + b));
      refine(0.5 * (a + b), b);
    };
    // Start from patches halving toward the edge, where the nearest spots would touch (the
    // refinement would split there anyway).
    double a = lo;
    for (int k = 1; k <= kGradedPatches; ++k) {
      const double b = k == kGradedPatches ? hi : lo + (hi - lo) * (1.0 - std::ldexp(1.0, -k));
      refine(a, b);
      a = b;
    }
  };
  build(0.0, kSameEdge, false, &same_patches_);
  build(0.0, 1.0, true, &cross_patches_);
  tabulated_ = true;
}

std::vector<double> ShellSums::header() const {
  // Format 1. Whatever the construction depends on besides the code: a change of any of
  // these makes saved tables stale (and from_tables checks the direct sums as well).
  return {1.0,
          static_cast<double>(s_),
          static_cast<double>(localization_.shells),
          localization_.distributed ? 1.0 : 0.0,
          kPatchNodes,
          kCrossNodes,
          kIntervals,
          kFarNodes,
          kGradedPatches,
          kMinPatch,
          kNearDistance,
          kEdgeSlack,
          kTableTolerance,
          Localization::kMergeMargin,
          SpotAverage::kRadialNodes,
          SpotAverage::kMaxAngles};
}

std::vector<double> ShellSums::tables() const {
  if (!tabulated_) return {};
  std::vector<double> out = header();
  for (const std::vector<Patch>* patches : {&same_patches_, &cross_patches_}) {
    out.push_back(static_cast<double>(patches->size()));
    for (const Patch& p : *patches) {
      out.insert(out.end(), {p.lo, p.hi, static_cast<double>(p.coefficients.size())});
      out.insert(out.end(), p.coefficients.begin(), p.coefficients.end());
    }
  }
  for (const std::vector<double>* table : {&same_far_table_, &cross_far_table_}) {
    out.push_back(static_cast<double>(table->size()));
    out.insert(out.end(), table->begin(), table->end());
  }
  return out;
}

std::optional<ShellSums> ShellSums::from_tables(int s, Localization localization, const std::vector<double>& tables) {
  if (!localization.distributed) return std::nullopt;
  ShellSums out(s, localization, false);
  const std::vector<double> header = out.header();
  if (tables.size() < header.size() || !std::equal(header.begin(), header.end(), tables.begin())) return std::nullopt;
  std::size_t at = header.size();
  // A count at `at`, no larger than what is left and than `most`.
  const auto count = [&](std::size_t most) -> std::optional<std::size_t> {
    if (at >= tables.size()) return std::nullopt;
    const double n = tables[at++];
    if (!(n >= 0.0 && n <= static_cast<double>(std::min(most, tables.size() - at)) && n == std::floor(n))) {
      return std::nullopt;
    }
    return static_cast<std::size_t>(n);
  };
  const auto take = [&](std::size_t n, std::vector<double>* into) {
    into->assign(tables.begin() + static_cast<std::ptrdiff_t>(at), tables.begin() + static_cast<std::ptrdiff_t>(at + n));
    at += n;
  };
  const std::size_t patch_sizes[2] = {2 * kPatchNodes, 2 * kPatchNodes * kIntervals * kCrossNodes};
  std::vector<Patch>* patches[2] = {&out.same_patches_, &out.cross_patches_};
  for (int k = 0; k < 2; ++k) {
    const std::optional<std::size_t> n = count(tables.size());
    if (!n || *n == 0) return std::nullopt;
    for (std::size_t i = 0; i < *n; ++i) {
      if (at + 3 > tables.size()) return std::nullopt;
      Patch p{tables[at], tables[at + 1], {}};
      at += 2;
      const std::optional<std::size_t> size = count(patch_sizes[k]);
      if (!size || *size != patch_sizes[k]) return std::nullopt;
      take(*size, &p.coefficients);
      patches[k]->push_back(std::move(p));
    }
  }
  const std::size_t far_sizes[2] = {2 * kFarNodes, 2 * kFarNodes * kFarNodes};
  std::vector<double>* far[2] = {&out.same_far_table_, &out.cross_far_table_};
  for (int k = 0; k < 2; ++k) {
    const std::optional<std::size_t> size = count(far_sizes[k]);
    if (!size || *size != far_sizes[k]) return std::nullopt;
    take(*size, far[k]);
  }
  if (at != tables.size()) return std::nullopt;
  out.tabulated_ = true;
  // The tables must still be the sums this build computes: three fixed radii, and points
  // drawn at random in this process, which no one who edits a file can know in advance.
  if (!within(out.same(0.2), out.same_direct(0.2), 1.0) || !within(out.cross(0.2, 0.15), out.cross_direct(0.2, 0.15), 1.0) ||
      !within(out.cross(0.3, 0.3), out.cross_direct(0.3, 0.3), 1.0) || !out.spot_check(std::random_device{}())) {
    return std::nullopt;
  }
  return out;
}

bool ShellSums::spot_check(std::uint64_t seed) const {
  if (!tabulated_) return true;
  std::mt19937_64 rng(seed);
  const auto in = [&rng](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  // The tables meet the direct sums to kTableTolerance; a check allows ten times that, so
  // an honest table never fails one, while an edit that moves a value by more does.
  constexpr double kCheckScale = 10.0;
  for (const Patch& p : same_patches_) {
    const double x = in(p.lo, p.hi);
    if (!within(same(x), same_direct(x), kCheckScale)) return false;
  }
  for (const Patch& p : cross_patches_) {
    for (int iv = 0; iv < kIntervals; ++iv) {
      const double y = in(iv * kIntervalWidth, (iv + 1) * kIntervalWidth);
      const double x = in(p.lo, p.hi) * (kCrossEdge - y);
      if (!within(cross(x, y), cross_direct(x, y), kCheckScale)) return false;
    }
  }
  return true;
}

std::string ShellSums::table_name(int s, Localization localization) {
  std::string name = "shell_sums-s" + std::to_string(s) + "-" + localization.spelling();
  std::replace(name.begin(), name.end(), ':', '_');
  return name;
}

ShellSums::Sums ShellSums::direct(const std::vector<DistanceShell>& shells, double x, double y) const {
  // The two kernels at distance r share sqrt(r^2 - x^2).
  const auto kernels = [x](double r) {
    const double root = std::sqrt(r * r - x * x);
    return std::array<double, 2>{2.0 / kPi * (x / root - std::asin(x / r)), 1.0 / (kPi * root)};
  };
  const bool spread = localization_.distributed && y > 0.0;
  Sums out;
  for (const DistanceShell& shell : shells) {
    const std::array<double, 2> k = spread ? spot_.both(kernels, shell.distance, y, x) : kernels(shell.distance);
    out.carried += shell.count * k[0];
    out.depth += shell.count * k[1];
  }
  return out;
}

ShellSums::Sums ShellSums::same_direct(double x) const {
  return direct(same_near_, x, x) + direct(same_far_, x, x);
}

ShellSums::Sums ShellSums::cross_direct(double x, double y) const {
  return direct(cross_near_, x, y) + direct(cross_far_, x, y);
}

ShellSums::Sums ShellSums::same(double x) const {
  if (!tabulated_ || !(x >= 0.0 && x <= kSameEdge * (1.0 + kEdgeSlack))) return same_direct(x);
  const auto patch = std::upper_bound(same_patches_.begin(), same_patches_.end(), x,
                                      [](double v, const Patch& p) { return v < p.hi; });
  const Patch& p = patch == same_patches_.end() ? same_patches_.back() : *patch;
  return tensor_value(p.coefficients, kPatchNodes, 1, 1, chebyshev::unit(x, p.lo, p.hi), 0, 0.0) +
         tensor_value(same_far_table_, kFarNodes, 1, 1, chebyshev::unit(x, 0.0, kRadiusReach), 0, 0.0);
}

ShellSums::Sums ShellSums::cross(double x, double y) const {
  const double t = x / (kCrossEdge - y);
  if (!tabulated_ || !(x >= 0.0 && x <= kRadiusReach && y >= 0.0 && y <= kRadiusReach && t <= 1.0 + kEdgeSlack)) {
    return cross_direct(x, y);
  }
  const auto patch = std::upper_bound(cross_patches_.begin(), cross_patches_.end(), t,
                                      [](double v, const Patch& p) { return v < p.hi; });
  const Patch& p = patch == cross_patches_.end() ? cross_patches_.back() : *patch;
  const int iv = std::min(static_cast<int>(y / kIntervalWidth), kIntervals - 1);
  return tensor_value(p.coefficients, kPatchNodes, kIntervals, kCrossNodes, chebyshev::unit(t, p.lo, p.hi), iv,
                      chebyshev::unit(y, iv * kIntervalWidth, (iv + 1) * kIntervalWidth)) +
         tensor_value(cross_far_table_, kFarNodes, 1, kFarNodes, chebyshev::unit(x, 0.0, kRadiusReach), 0,
                      chebyshev::unit(y, 0.0, kRadiusReach));
}

namespace {

std::mutex& registry_mutex() {
  static std::mutex mutex;
  return mutex;
}

ShellSumsStore& store() {
  static ShellSumsStore store;
  return store;
}

}  // namespace

void set_shell_sums_store(ShellSumsStore s) {
  const std::lock_guard<std::mutex> lock(registry_mutex());
  store() = std::move(s);
}

const ShellSums& shell_sums(int s, Localization localization) {
  static std::map<std::tuple<int, int, bool>, std::unique_ptr<const ShellSums>> built;
  const std::lock_guard<std::mutex> lock(registry_mutex());
  auto& entry = built[{s, localization.shells, localization.distributed}];
  if (entry) return *entry;
  const std::string name = ShellSums::table_name(s, localization);
  const bool stored = localization.distributed && store().load && store().save;
  if (stored) {
    if (std::optional<ShellSums> saved = ShellSums::from_tables(s, localization, store().load(name))) {
      entry = std::make_unique<const ShellSums>(std::move(*saved));
      return *entry;
    }
  }
  entry = std::make_unique<const ShellSums>(s, localization);
  if (stored) store().save(name, entry->tables());
  return *entry;
}

}  // namespace punchsweep::model
