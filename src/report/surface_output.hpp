#pragma once
/// @file
/// How `punchsweep surface` prints a texture (docs/cli.md, "punchsweep surface"): JSON (the
/// contract Python's surface() returns), a table for people, CSV.

#include <iosfwd>
#include <string>

#include "report/point_output.hpp"
#include "engine/surface_run.hpp"

namespace punchsweep::report {

/// Writes the evaluated texture: per level its regime, t*, touchdown load, sensitivities and
/// range; per time X, areas, caps touched, loads and validity; with --R and a material the
/// physical units; with --check the time stepping's answers; with an ensemble (--seeds)
/// its statistics (JSON's `ensemble`; the table's and CSV's rows are then the ensemble's).
void write_surface(std::ostream& out, OutputFormat format, const engine::SurfaceRun& run,
                   const engine::SurfaceEnsemble* ensemble = nullptr);

/// The texture of `punchsweep surface`'s keywords evaluated (engine::evaluate_surface) and
/// written as the command's JSON (what `--format json` prints), with its ensemble where
/// --seeds asks one: Python's surface().
std::string surface_json(const input::Keywords& keywords);

}  // namespace punchsweep::report
