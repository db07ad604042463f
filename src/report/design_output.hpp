#pragma once
/// @file
/// How a design (engine/design.hpp) is printed (docs/design.md): JSON (the contract Python's
/// design() returns) and a table for people, lengths and pressures in the material's units.

#include <iosfwd>
#include <string>

#include "engine/design.hpp"

namespace punchsweep::report {

/// The design as `punchsweep design --format json` prints it.
std::string design_json(const engine::DesignResult& d);

/// The design as a table: the window, its centre and margin, each requirement's edge with
/// its binding temperature and corner, and the notes.
void write_design_table(std::ostream& out, const engine::DesignResult& d);

}  // namespace punchsweep::report
