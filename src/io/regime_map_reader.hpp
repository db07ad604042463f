#pragma once

#include <string>

namespace punchsweep::io {

/// The global attribute `identity` of the regime map at `path`: the lines that define its
/// content, joined by '\n' (RegimeMapWriter). Throws std::runtime_error saying why when
/// `path` cannot be read, is not an HDF5 file, or is not a punchsweep regime map (an HDF5
/// file without that attribute, such as a map written before punchsweep recorded it).
std::string read_map_identity(const std::string& path);

}  // namespace punchsweep::io
