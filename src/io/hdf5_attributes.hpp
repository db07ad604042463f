#pragma once
/// @file
/// The attributes every HDF5 file of the engine writes the same way (the regime map, the
/// surface map): UTF-8 strings, scalars and arrays, and the units convention (docs/maps.md,
/// "Units"): units = "1" with the scale in scaled_by for a quantity in the model's scales.

#include <hdf5.h>

#include <string>

#include "io/hdf5_handle.hpp"

namespace punchsweep::io {

/// A property list of class `cls`.
Handle make_property_list(hid_t cls, const std::string& what);
/// The variable-length UTF-8 string type.
Handle string_type(const std::string& what);
/// Creates attribute `name` on `object` with `count` values (0: a scalar) and writes them.
void write_attribute(hid_t object, const char* name, hid_t file_type, hid_t memory_type, const void* values,
                     hsize_t count, const std::string& where);
void write_string_attribute(hid_t object, const char* name, const std::string& value, const std::string& where);
void write_double_attribute(hid_t object, const char* name, double value, const std::string& where);
/// units = "1" (a pure number, as UDUNITS reads it) and, unless `scale` is "1", the scale
/// it is measured in as `scaled_by`.
void write_scale(hid_t object, const std::string& scale, const std::string& where);

}  // namespace punchsweep::io
