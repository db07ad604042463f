#include "io/regime_map_reader.hpp"

#include <hdf5.h>

#include <stdexcept>

#include "io/hdf5_handle.hpp"

namespace punchsweep::io {

std::string read_map_identity(const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // our messages say what failed
  const htri_t hdf5 = H5Fis_hdf5(path.c_str());
  if (hdf5 < 0) throw std::runtime_error(path + " cannot be read");
  if (hdf5 == 0) throw std::runtime_error(path + " is not an HDF5 file, so not a punchsweep regime map");
  const Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open " + path);
  if (H5Aexists(file, "identity") <= 0) {
    throw std::runtime_error(path + " is an HDF5 file but not a punchsweep regime map of this version " +
                             "(it has no 'identity' attribute)");
  }
  const Handle attribute(H5Aopen(file, "identity", H5P_DEFAULT), H5Aclose, "open attribute identity of " + path);
  const Handle type(H5Aget_type(attribute), H5Tclose, "read the type of identity in " + path);
  if (H5Tget_class(type) != H5T_STRING || H5Tis_variable_str(type) <= 0) {
    throw std::runtime_error(path + ": its 'identity' attribute is not a string, so it is no punchsweep regime map");
  }
  char* text = nullptr;
  check(H5Aread(attribute, type, &text), "read attribute identity of " + path);
  std::string identity = text != nullptr ? text : "";
  const Handle space(H5Aget_space(attribute), H5Sclose, "read the space of identity in " + path);
  H5Dvlen_reclaim(type, space, H5P_DEFAULT, &text);
  return identity;
}

}  // namespace punchsweep::io
