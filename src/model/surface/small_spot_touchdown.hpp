#pragma once
/// @file
/// A level's touchdown in the small-spot limit, for any periodic cell (docs/model.md,
/// section 17.6). While the tallest caps' spots are small beside the distances between the
/// cell's sites, each tallest cap is an isolated punch in the smooth periodic field of the
/// others' loads, and the gap of a lower site closes at a load found from one scalar
/// equation, no grid: the limit answers where a load curve's grid cannot resolve the spots
/// (a glassy polymer's first touch, a sparse texture, a small drop). With G the zero-mean
/// displacement of unit point loads on the cell's lattice (E* = 1) and L its Laplacian, the
/// tallest cap i under load P_i in the field u_i = sum_j [P_j G_ij + M2_j L_ij / 4] and of
/// curvature eps_i = sum_j P_j L_ij / 4 (j = i its own images: G's and L's regular parts)
/// sinks by
///     delta = u_i + K_d a_i^s + 2 eps_i a_i^2,     P_i = K_P a_i^(s+1) + (8/3) eps_i a_i^3,
/// (Sneddon's relations for the profile C r^s + eps r^2), M2_j its pressure's second moment
/// (the spot's own size in the far field, G + M2 L / 4). A lower site k closes when
///     delta - u_k + (s_k - 1) C_k y^s_k = drop_k,     y = (|grad u_k| / (s_k C_k))^(1/(s_k - 1))
/// (its cap's lowest gap, where the field tilts; a site in contact on such a slope sinks as
/// much more). The error is of order (a/d)^5 of X*:
/// against the square lattice's periodic tables 0.044 rho^5, rho the spot radius over the
/// nearest distance (1.6e-5 at rho = 0.2); the leading order alone (P G) was 0.2 rho^3.
/// Lengths in R, loads in E0* (unit compliance), as the load curve's.

#include <array>
#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "model/problem/cell_geometry.hpp"
#include "model/surface/load_curve.hpp"

namespace punchsweep::model {

/// Unit point loads at the nodes of the Lx x Ly lattice on a half-space of E* = 1, balanced
/// by a uniform pressure: the surface displacement G of zero mean over the cell by Ewald's
/// sums (1/(pi r) split by erfc(alpha r); the smooth part's transform (2/k) erfc(k/(2 alpha))),
/// to about 1e-14 of 1/sqrt(Lx Ly), and its Laplacian (away from the nodes the sum of
/// 1/(pi r^3) over them) by the same split, differentiated.
class PeriodicPointLoads {
 public:
  PeriodicPointLoads(double Lx, double Ly);

  /// G at (x, y), not at a node.
  double displacement(double x, double y) const;
  /// lim_{x -> 0} G(x) - 1/(pi |x|): the field of a node's images and the balance at it.
  double regular_displacement() const { return regular_displacement_; }
  /// G's gradient at (x, y), not at a node (central differences of G).
  std::array<double, 2> gradient(double x, double y) const;
  /// G's Laplacian at (x, y), not at a node (the sum over the nodes of 1/(pi r^3)).
  double laplacian(double x, double y) const;
  /// The Laplacian of the images' field at a node: the sum over the other nodes.
  double regular_laplacian() const { return regular_laplacian_; }

 private:
  /// Adds term(r) over the nodes' distances r from (x, y) (the node at 0 left out where
  /// `regular`), and term(k) cos(k . x) over the nonzero waves k: Ewald's two sums.
  template <class Term>
  void add_images(double& sum, double x, double y, bool regular, const Term& term) const;
  template <class Term>
  void add_waves(double& sum, double x, double y, const Term& term) const;
  double sum_real(double x, double y, bool regular) const;
  double sum_laplacian(double x, double y, bool regular) const;

  double Lx_, Ly_, area_, alpha_;
  int images_x_, images_y_, waves_x_, waves_y_;
  double regular_displacement_ = 0.0, regular_laplacian_ = 0.0;
};

/// One site's touchdown in the limit.
struct SmallSpotTouchdown {
  /// The load at which its gap closes, in E0* (0 for the tallest sites; +infinity where the
  /// limit does not answer: the site does not close before the tallest spots reach
  /// kSmallSpotMaxRatio of their nearest distance, or the cell is not one it takes).
  double X = std::numeric_limits<double>::infinity();
  /// The tallest spots' largest radius at X over the nearest distance from a tallest tip to
  /// another tallest tip (or its own image) or to this site: the limit's small parameter.
  double spot_ratio = std::numeric_limits<double>::quiet_NaN();
};

/// Up to this spot ratio the limit holds a touchdown to about 1.4e-5 of itself (the square
/// lattice's periodic tables: 0.044 rho^5).
constexpr double kSmallSpotMaxRatio = 0.2;
/// The limit answers cells of at most this many sites (a dense solve of the loads of those in
/// contact per trial load, a round of trial loads per touchdown: the cost grows as the sites'
/// fourth power: a whole surface run of a scattered supercell took 0.21 s for 32 caps, 4.2 s
/// for 128, 38 s for 242, its touchdowns and states; a height
/// map's summits are the curve's).
constexpr std::size_t kSmallSpotMaxSites = 256;

/// SmallSpotLimit::counting's answer: the drop, and whether every trial's count of every
/// cap fell steadily as the level sank (always for one level's caps).
struct SmallSpotCount {
  double drop = 0.0;
  bool steady = true;
};

/// The limit for one cell: its fields between every pair of sites, built once (a few ms for
/// tens of sites), read at any load. Copies share them; the geometry must outlive it.
class SmallSpotLimit {
 public:
  /// `closing_level` >= 1: the level level_closure closes (a design's), whose sites the other
  /// levels' touchdowns are then found without, once.
  explicit SmallSpotLimit(const CellGeometry& geometry, int closing_level = 0);

  /// Whether the limit takes the cell (small_spot_touchdowns' conditions).
  bool answers() const { return cell_ != nullptr; }
  /// small_spot_touchdowns, the sites of `skipped_level` left out (they neither touch nor
  /// carry load: the level a design moves).
  std::vector<SmallSpotTouchdown> touchdowns(int skipped_level = -1) const;
  /// The drop of the closing level's tallest cap (each other cap keeping its offset below
  /// it) at which its first cap closes at load X (E0*): reference::LevelClosure's answer, in
  /// the limit, the other levels at their drops. Empty where the limit does not hold there (a
  /// spot beyond kSmallSpotMaxRatio, a site of another level unanswered by X, a cone tilted
  /// off its tip, a drop past where a taller cap's surface covers the level's tip) or no
  /// closing level was given.
  std::optional<double> level_closure(double X) const;
  /// Counting every cap of the cell (counting()'s level).
  static constexpr int kEveryLevel = -1;
  /// reference::LevelClosure::counting's answer in the limit: the drop of the closing level's
  /// tallest cap (each other cap of it keeping its offset below it) at which `caps` of
  /// `level`'s caps (kEveryLevel: of every cap) have touched at load X, the other levels at
  /// their drops; for the closing level's caps or every cap the deepest such drop, for
  /// another level's (which touch the sooner the deeper the closing level lies, as it carries
  /// less) the least. By bisection over the drop to 1e-10 of the deepest (the closing level's
  /// tips still on the surface), each trial the limit's touchdowns of the cell with the level
  /// there. Empty where a trial's count is not the limit's to say (a cap it leaves unanswered
  /// might have touched by X), where the answer is not a crossing between drop 0 and the
  /// deepest (none there, or every drop), where every cap's count does not fall steadily with
  /// the drop, or no closing level was given: the contact solves answer there.
  std::optional<SmallSpotCount> counting(double X, std::size_t caps, int level) const;
  /// The cell's states at increasing loads in the limit, given its touchdowns
  /// (touchdowns()): each site in contact by X (touched before X) an isolated punch in the
  /// others' field, its load and its spot's area summed by level (a load curve's samples),
  /// up to the first load where the limit does not hold (a site it leaves unanswered might
  /// have touched by then, a spot past kSmallSpotMaxRatio of its nearest distance, the state
  /// not found), each state started from the last.
  std::vector<LoadCurveSample> samples(const std::vector<double>& loads, const std::vector<SmallSpotTouchdown>& touched) const;

 private:
  struct Cell;
  const CellGeometry& geometry_;
  std::vector<std::size_t> tallest_;
  std::shared_ptr<const Cell> cell_;
  int closing_level_ = 0;
  std::vector<SmallSpotTouchdown> others_;  ///< touchdowns(closing_level_), where it is >= 1
  /// deepest_exposed_drop of the closing level, where it is >= 1
  double deepest_ = std::numeric_limits<double>::infinity();
};

/// Each site's touchdown in the limit: the sites touch in turn, each later one in the field
/// of every site in contact before it (each an isolated punch of its own drop), as long as
/// every spot stays within kSmallSpotMaxRatio of the nearest distance; past that the sites
/// are not answered (X +infinity). Answered (else every X +infinity) where a level-0 site
/// lies at drop 0 (the tallest; other level-0 sites, a scattered supercell's, touch in turn
/// as the lower levels' do) and there are at most kSmallSpotMaxSites sites; a site of
/// exponent 1 (a cone) only while the field's slope at its tip stays below C.
std::vector<SmallSpotTouchdown> small_spot_touchdowns(const CellGeometry& geometry);

/// `curve` (of `geometry`) with each site's touchdown taken from the limit wherever it holds
/// (`limit`: small_spot_touchdowns(geometry), found once for every grid's curve), below the curve's X_resolved or above it (there too the
/// limit is the closer, the grid's error falling only as the spots' nodes grow), and the
/// levels' touchdowns with them; LoadCurve::level_small_spot says which levels. A site the
/// curve finds hidden or never touching stays the curve's. Returns the sites answered.
std::size_t answer_small_spots(LoadCurve& curve, const CellGeometry& geometry, const std::vector<SmallSpotTouchdown>& limit);

/// `curve` (of `limit`'s geometry, its touchdowns answered by answer_small_spots with
/// `touched`, limit.touchdowns()) from the limit wherever it holds, where it holds up to the curve's X_resolved: its samples up to the
/// last load the limit holds at replaced by the limit's states (samples()), at loads from
/// the geometry alone (a decade below the first touchdown past the tallest tips on,
/// kSmallSpotSamplesPerDecade a decade, at every touchdown, and refined after each), and
/// X_resolved then the first of them: the areas and loads of spots too small for the grid
/// read as the limit's, as its touchdowns are, and past X_resolved too (there too it is the
/// closer while it holds); the same on every grid and whatever the curve's reach (a curve
/// stopped within the limit's reach goes on to it). Returns whether it did (the curve stays
/// as it was where the limit stops short of X_resolved).
bool resolve_small_spots(LoadCurve& curve, const SmallSpotLimit& limit, const std::vector<SmallSpotTouchdown>& touched);

/// The last load at which resolve_small_spots reads the limit's states of `limit`'s cell
/// (`touched` its touchdowns), where the curve's first sample is `below` or any cell with a
/// touchdown past the tallest tips (found from the geometry alone, as resolve_small_spots'
/// loads are); 0 where the limit does not take the cell or holds at none of them. A grid
/// that resolves the spots below it hands over to the limit's states there (--grid auto).
double small_spot_reach(const SmallSpotLimit& limit, const std::vector<SmallSpotTouchdown>& touched, double below);

/// Samples a decade of load for resolve_small_spots (the curve's readings interpolate
/// between them: log area linear in log X, or linear in X from a touchdown).
constexpr int kSmallSpotSamplesPerDecade = 16;

}  // namespace punchsweep::model
