#pragma once

#include <limits>
#include <string>
#include <string_view>

namespace punchsweep::model {

/// Which localization model stands in for the lattice around a punch (docs/model.md,
/// section 11). The paper's keeps the neighbours at the two nearest distances as point
/// loads and puts the nominal pressure beyond them; the family keeps D distances and may
/// spread each neighbour over its own spot.
struct Localization {
  /// D: the punches of either level within the D nearest distinct distances about a punch
  /// are kept (lattice.hpp, kept_neighbours), in both phases; in the single-level phase the
  /// level-1 ones carry load. 2 is the paper's: four at l/sqrt(2) and four at l.
  int shells = 2;
  /// Neighbours spread over their own spots (the m = 0 average of their pressure about
  /// the punch); false: point loads at their distances, the paper's choice.
  bool distributed = false;
  /// "periodic": no localization at all; the elastic state of the whole periodic cell, from
  /// its tables (docs/model.md, section 14). shells and distributed are then not read.
  bool periodic = false;

  /// Distributed neighbours count as merged spots within this share of touching: the
  /// family needs separate spots for its ring averages (which cost ever more quadrature as
  /// a gap closes, and whose error grows there: docs/model.md, section 11), so its states
  /// keep 2 a_i < kMergeMargin l and a1 + a2 < kMergeMargin l/sqrt(2), and the validity
  /// rules apply with these limits. 1 for point loads and the paper's model.
  static constexpr double kMergeMargin = 0.98;
  /// The periodic model has no such limit: merged spots are part of its solution.
  double merge_margin() const {
    return periodic ? std::numeric_limits<double>::infinity() : distributed ? kMergeMargin : 1.0;
  }

  /// The most shells a model may keep.
  static constexpr int kMaxShells = 1000;
  /// "refined": the family's member whose measured accuracy against the periodic BEM is
  /// best (docs/model.md, section 11): the neighbours within this many distances, spread.
  static constexpr int kRefinedShells = 200;

  /// The periodic model's reach in s: up to it its tables give t* within 2e-4 of the cell's
  /// own boundary elements; beyond, flatter caps' edges are more than their grid resolves
  /// (1.5e-3 at s = 24; at s = 32 a contact solve misses its tolerance). docs/model.md 14.7.
  static constexpr int kMaxPeriodicExponent = 16;
  /// Empty where this model answers shape exponent s, else one sentence naming s, the
  /// model's range and the models that answer it.
  std::string exponent_error(int s) const;

  /// The spelling "paper": the engine's own eqs 9.5/9.10 and 9.12-9.19.
  bool is_paper() const { return shells == 2 && !distributed && !periodic; }
  /// "paper", "periodic", "shells:D" (distributed) or "point-shells:D".
  std::string spelling() const;
};

/// The model of a point, a sweep and Python's classify when none is named: the periodic
/// cell's tabulated solution (docs/model.md, section 14), exact wherever the contact only
/// grows and valid where spots merge.
inline constexpr std::string_view kDefaultLocalization = "periodic";

/// What parse_localization accepts, each spelling with a few words on it, for help texts
/// and errors: "periodic (...), paper (...), refined (...), shells:D (...) or
/// point-shells:D (...), 1 <= D <= kMaxShells".
std::string localization_spellings();

/// Parses "paper", "periodic", "refined" (= shells:kRefinedShells), "shells:D" (D distances of
/// distributed neighbours) or "point-shells:D" (of point loads), 1 <= D <= kMaxShells.
/// Throws std::invalid_argument naming the valid forms.
Localization parse_localization(std::string_view text);

}  // namespace punchsweep::model
