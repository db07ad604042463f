#pragma once
/// @file
/// `punchsweep surface`: a periodic texture (a square or hexagonal lattice of two or three
/// levels, a cell file, a measured map, a scattered supercell) under a material and a load
/// history, from the elastic load curve of its cell (docs/model.md, section 17): each
/// level's touch (immediate, delayed t*, never), the areas and the sites in contact in time.

#include <iosfwd>
#include <string>
#include <vector>

#include "input/command_options.hpp"
#include "engine/surface_evaluation.hpp"

namespace punchsweep::app {

/// `punchsweep surface ...`; returns the exit code, throws UsageError for bad input (before
/// printing anything).
int run_surface_command(const std::vector<std::string>& args, std::ostream& out);

/// `surface --dry-run`'s lines for `cost`.
void write_curve_cost(std::ostream& out, const engine::CurveCost& cost);

}  // namespace punchsweep::app
