#pragma once
/// @file
/// How `punchsweep surface` prints a texture (docs/cli.md, "punchsweep surface"): JSON (the
/// contract Python's surface() returns), a table for people, CSV.

#include <iosfwd>

#include "app/point_output.hpp"
#include "texture/surface_run.hpp"

namespace punchsweep::app {

/// Writes the evaluated texture: per level its regime, t*, touchdown load, sensitivities and
/// range; per time X, areas, caps touched, loads and validity; with --R and a material the
/// physical units; with --check the time stepping's answers.
void write_surface(std::ostream& out, OutputFormat format, const texture::SurfaceRun& run);

}  // namespace punchsweep::app
