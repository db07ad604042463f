#pragma once

#include <string>
#include <string_view>

namespace punchsweep::model {

/// Which localization model stands in for the lattice around a punch (docs/model.md,
/// section 11). The paper's keeps the nearest shell of neighbours as point loads and puts
/// the nominal pressure beyond it; the family keeps K shells and may spread each
/// neighbour over its own spot.
struct Localization {
  /// K: in the single-level phase, the distance shells of level-1 neighbours kept around a
  /// punch and around a square centre (1: the paper's four at l, and four at l/sqrt(2)
  /// around the centre); in the two-level phase, the distinct distances of either level
  /// kept around a punch (2: the paper's four at l/sqrt(2) and four at l). A refined model
  /// for both phases must keep one set, so that they join at touchdown (issue 12).
  int shells = 1;
  /// Neighbours spread over their own spots (the m = 0 average of their pressure about
  /// the punch); false: point loads at their distances, the paper's choice.
  bool distributed = false;

  /// The most shells a model may keep.
  static constexpr int kMaxShells = 1000;

  /// The spelling "paper": the engine's own eqs 9.5/9.10 and 9.12-9.19.
  bool is_paper() const { return shells == 1 && !distributed; }
  /// "paper", "shells:K" (distributed) or "point-shells:K".
  std::string spelling() const;
};

/// Parses "paper", "shells:K" (K distributed shells) or "point-shells:K" (K shells of point
/// loads), 1 <= K <= kMaxShells. Throws std::invalid_argument naming the valid forms.
Localization parse_localization(std::string_view text);

}  // namespace punchsweep::model
