#pragma once
/// @file
/// A periodic texture's cell as a user writes it (`punchsweep surface --cell FILE`,
/// docs/cli.md): one [cell] section of `key = value` lines,
///
///     [cell]
///     Lx = 250um          # the cell, repeated in x and y (R, or a length with --R)
///     Ly = 433.013um
///     s = 2               # the sites' shape (default 2 and 0.5) unless a site names its own
///     C = 0.5
///     site = 0, 0, 0, 0   # x, y, drop, level[, s, C]: one line per punch
///
/// read into a model::CellGeometry. Every message names the file, the line, the key, the
/// value and what is valid.

#include <string>
#include <vector>

#include "input/scaled_value.hpp"
#include "model/problem/cell_geometry.hpp"

namespace punchsweep::input {

/// The cell of the file's text; `origin` (the file name) starts every message. Lengths in
/// R, or with a length unit where `scales` knows R. Throws UsageError for a line that is no
/// `key = value` of [cell], an unknown or repeated key (but site), a bad number, or a cell
/// model::geometry_error refuses, or a site whose tip is not on the texture's surface.
/// `notes` (where given) receives what the file leaves to a reader's guess: a level 0 that
/// is not the tallest, and bare lengths (read in R) beside lengths with units.
model::CellGeometry parse_cell(const std::string& text, const std::string& origin, const PhysicalScales& scales,
                               std::vector<std::string>* notes = nullptr);

/// The file `path` read (read_text_file) and parsed.
model::CellGeometry read_cell_file(const std::string& path, const PhysicalScales& scales,
                                   std::vector<std::string>* notes = nullptr);

}  // namespace punchsweep::input
