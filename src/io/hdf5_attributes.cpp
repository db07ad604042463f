#include "io/hdf5_attributes.hpp"

namespace punchsweep::io {

Handle make_property_list(hid_t cls, const std::string& what) { return Handle(H5Pcreate(cls), H5Pclose, what); }

Handle string_type(const std::string& what) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, what);
  check(H5Tset_size(type, H5T_VARIABLE), what);
  check(H5Tset_cset(type, H5T_CSET_UTF8), what);
  return type;
}

void write_attribute(hid_t object, const char* name, hid_t file_type, hid_t memory_type, const void* values,
                     hsize_t count, const std::string& where) {
  const std::string what = std::string("write attribute '") + name + "' " + where;
  Handle space(count == 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &count, nullptr), H5Sclose, what);
  Handle attribute(H5Acreate2(object, name, file_type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, what);
  check(H5Awrite(attribute, memory_type, values), what);
}

void write_string_attribute(hid_t object, const char* name, const std::string& value, const std::string& where) {
  const Handle type = string_type(std::string("make a string type for '") + name + "' " + where);
  const char* text = value.c_str();
  write_attribute(object, name, type, type, &text, 0, where);
}

void write_double_attribute(hid_t object, const char* name, double value, const std::string& where) {
  write_attribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value, 0, where);
}

void write_scale(hid_t object, const std::string& scale, const std::string& where) {
  write_string_attribute(object, "units", "1", where);
  if (scale != "1") write_string_attribute(object, "scaled_by", scale, where);
}

}  // namespace punchsweep::io
