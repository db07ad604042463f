#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "model/numerics/lattice.hpp"
#include "model/problem/localization.hpp"
#include "model/shells/spot_average.hpp"

namespace punchsweep::model {

/// The kept neighbourhood's sums of a localization of the family (docs/model.md, section 11),
/// per unit load of one neighbour, in units of the pitch l: with every length scaled by l
/// they depend on the scaled radii alone, so one instance serves every l.
///
/// About a punch of scaled radius x, each kept neighbour at scaled distance rho (n of them),
/// as a point load or spread over its own spot (scaled radius y, SpotAverage), adds
///   carried:  n <w(x, .)>,             w(x, r) = (2/pi) (x / sqrt(r^2 - x^2) - arcsin(x / r))
///   depth:    n <1/(pi sqrt(.^2 - x^2))>  (times l: the depth kernel is in 1/length)
/// of its load: the share of it the punch's own spot carries, and the depth it adds there.
/// The neighbourhood is kept_neighbours(level, D); about a punch of either level it is the
/// same set of distances, with the levels swapped, so two sums serve both levels:
///   same(x):     the punch's own level, all of scaled radius x;
///   cross(x, y): the other level, of scaled radius y. About a bare site (x = 0) its depth
///                is the centre displacement kernel <1/(pi .)> of the single-level phase.
///
/// For distributed neighbours the sums are tabulated at construction (Chebyshev interpolants:
/// the near shells piecewise toward the radii at which the nearest spots would touch, the far
/// ones in one smooth piece), because a sum over D = 200 distances costs a million kernel
/// evaluations; the tables agree with the direct sums to kTableTolerance (tested). They
/// reach as far as the family's states do (spots apart by Localization::kMergeMargin); a
/// radius beyond is summed directly. Point loads are summed directly.
class ShellSums {
 public:
  struct Sums {
    double carried = 0.0;  ///< dimensionless
    double depth = 0.0;    ///< in 1/l
    Sums operator+(const Sums& other) const { return {carried + other.carried, depth + other.depth}; }
  };

  /// Agreement of the tables with the direct sums: carried to this, depth to this times
  /// (1 + |depth|).
  static constexpr double kTableTolerance = 1e-10;

  ShellSums(int s, Localization localization);

  /// The tables as numbers, for a cache on disk (the layers above own files): a header that
  /// names the table's construction (format, s, D, spread, node counts, tolerances, the
  /// spot rule), then every patch and piece. Empty for point loads (nothing tabulated).
  std::vector<double> tables() const;
  /// Tables from tables() of an earlier process, if their header matches this build's
  /// construction of (s, localization) and they meet the direct sums at three radii; else
  /// empty (the caller builds them). Bit for bit the tables that were saved.
  static std::optional<ShellSums> from_tables(int s, Localization localization, const std::vector<double>& tables);

  /// Whether the tables meet the direct sums (to 10 kTableTolerance) at points drawn from
  /// `seed`: one in every near patch of each sum, in each y interval of the cross sums
  /// (the far tables add to every value checked). from_tables draws a fresh seed in every
  /// process, so a table edited to bias the results fails it whatever its checksum says.
  bool spot_check(std::uint64_t seed) const;

  /// A file name for the tables of (s, localization): shell_sums-s<s>-<spelling>.
  static std::string table_name(int s, Localization localization);

  Sums same(double x) const;
  Sums cross(double x, double y) const;

  /// The direct sums (no table), for tests and for radii beyond the tables.
  Sums same_direct(double x) const;
  Sums cross_direct(double x, double y) const;

  /// How many punches each sum keeps (the nominal-pressure radii follow from them).
  int same_count() const { return same_count_; }
  int cross_count() const { return cross_count_; }

  const Localization& localization() const { return localization_; }

 private:
  /// The shells of (s, localization), tables not built (build_tables() or from_tables()).
  ShellSums(int s, Localization localization, bool build);
  void build_tables();
  /// The header of tables(): what the tables' construction depends on.
  std::vector<double> header() const;
  Sums direct(const std::vector<DistanceShell>& shells, double x, double y) const;

  /// A piecewise Chebyshev table of the near shells' sums in one variable over patches of
  /// [0, hi], each patch a tensor product with a second, smooth variable (or none).
  struct Patch {
    double lo = 0.0, hi = 0.0;
    std::vector<double> coefficients;  ///< [value][k_t][interval][k_u], see shell_sums.cpp
  };

  Localization localization_;
  int s_;
  SpotAverage spot_;
  std::vector<DistanceShell> same_near_, same_far_;    ///< distances in l
  std::vector<DistanceShell> cross_near_, cross_far_;  ///< distances in l
  int same_count_ = 0;
  int cross_count_ = 0;
  bool tabulated_ = false;
  std::vector<Patch> same_patches_;   ///< in x
  std::vector<Patch> cross_patches_;  ///< in t = x / (kMergeMargin/sqrt(2) - y), by y
  std::vector<double> same_far_table_;   ///< in x
  std::vector<double> cross_far_table_;  ///< in (x, y)
};

/// Where the tables of a distributed localization may be kept between processes: load
/// returns what save stored under a name (empty if nothing). The application sets one
/// (a cache folder); without one every process builds its tables.
struct ShellSumsStore {
  std::function<std::vector<double>(const std::string& name)> load;
  std::function<void(const std::string& name, const std::vector<double>& tables)> save;
};
void set_shell_sums_store(ShellSumsStore store);

/// The sums of (s, localization), on first use read from the store (if set and its tables
/// pass from_tables) or else built (and given to the store), then shared (thread-safe).
const ShellSums& shell_sums(int s, Localization localization);

}  // namespace punchsweep::model
