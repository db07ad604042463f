#pragma once

#include <hdf5.h>

#include <stdexcept>
#include <string>
#include <utility>

namespace punchsweep::io {

/// HDF5 failure, with the operation and the object it concerned.
class Hdf5Error : public std::runtime_error {
 public:
  explicit Hdf5Error(const std::string& what) : std::runtime_error(what) {}
};

/// Owns one HDF5 identifier and closes it with the matching H5*close (thin RAII wrapper,
/// so no code path leaks a handle or needs scattered close calls).
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);

  Handle() = default;
  /// Takes ownership of `id`; throws Hdf5Error naming `what` if id < 0.
  Handle(hid_t id, Closer close, const std::string& what);
  ~Handle() { reset(); }
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, H5I_INVALID_HID)), close_(other.close_) {}
  Handle& operator=(Handle&& other) noexcept;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  hid_t get() const { return id_; }
  operator hid_t() const { return id_; }  // NOLINT: used where the C API wants hid_t
  void reset();

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer close_ = nullptr;
};

/// Throws Hdf5Error naming `what` when an HDF5 call returned a negative status.
inline void check(herr_t status, const std::string& what) {
  if (status < 0) throw Hdf5Error("HDF5: " + what + " failed");
}

}  // namespace punchsweep::io
