#pragma once
/// @file
/// The time-stepping reference for a periodic cell of any geometry (model::CellGeometry on
/// the grid of make_cell): the viscoelastic contact stepped in time (ViscoelasticStepper),
/// each site's touch found by narrowing the step in which its tip first carries pressure.
/// It assumes nothing of the contact's history, so it checks the load curve's reading
/// (docs/model.md, section 17) where that rests on the contact only growing. Units: times
/// in the law's unit, pressures in E0*, lengths in R.

#include <vector>

#include "model/contact/regime.hpp"
#include "model/laws/creep_law.hpp"
#include "model/numerics/stop_request.hpp"
#include "model/problem/cell_geometry.hpp"
#include "model/problem/load_shape.hpp"
#include "reference/contact_solver.hpp"
#include "reference/periodic_grid.hpp"
#include "reference/step_sizer.hpp"

namespace punchsweep::reference {

struct CellReferenceOptions {
  std::vector<double> times{0.0, 0.5, 1.0, 2.0, 5.0};  ///< snapshot times, >= 0, increasing
  StepControl steps{};
  ContactSolverOptions solver{};
  /// The step in which a site's tip first carries pressure is halved until it is at most
  /// this long; the touch is its middle.
  double t_star_resolution = 1e-3;
  model::StopRequest stop{};
};

/// The cell at one time, measured on the grid.
struct CellSnapshot {
  double t = 0.0;
  std::vector<double> level_load;  ///< P_L(t): the pressure over each level's share, in R^2 E0*
  /// Each level's contact area (level_contact_areas, the rims of the creep-scaled pressure
  /// w = int J dp), in R^2.
  std::vector<double> level_area;
  double area_fraction = 0.0;
  double sites_touched = 0.0;  ///< sites whose tip carries pressure, over all sites
};

struct CellReference {
  /// Per site: the time its tip first carries pressure (0 for the tallest sites and any
  /// pressed at once), +infinity where it has not by the last snapshot time.
  std::vector<double> site_touch;
  /// Per level: its regime and t* (its first site's touch): immediate at t = 0 or while a
  /// ramp rises, delayed, never (untouched in the long-term state, elastic at J(inf), for a
  /// law with finite J(inf)); a level delayed past the last time has t* +infinity.
  std::vector<model::Regime> level_regime;
  std::vector<double> level_t_star;
  std::vector<CellSnapshot> series;
  int steps = 0;
  int solves = 0;
  bool converged = true;
};

/// Steps the cell under mean pressure pbar0 phi(t) (`loading`) on the material `creep`.
/// Throws std::invalid_argument for bad options, model::Stopped on a stop request.
CellReference evaluate_cell_reference(const model::CellGeometry& geometry, const Cell& cell, double pbar0,
                                      const model::CreepLaw& creep, const model::LoadShape& loading,
                                      const CellReferenceOptions& options = {});

}  // namespace punchsweep::reference
