#pragma once
// Private to tofsim_io: HDF5's C API with owned identifiers and exceptions.
// Every hid_t the io code opens lives in an H5Handle, so an exception on any
// path closes what was opened (HDF5 keeps an unclosed file, and the memory of
// an in-memory one, until the process exits). HDF5's predefined types
// (H5T_NATIVE_FLOAT, ...) are not owned and never wrapped.

#include <hdf5.h>

#include <filesystem>
#include <string>
#include <utility>

namespace tofsim::io::detail {

using H5CloseFn = herr_t (*)(hid_t);

/// One HDF5 identifier, closed by the function matching its kind. Move-only;
/// an invalid id (< 0) is not closed.
template <H5CloseFn Close>
class H5Handle {
 public:
  H5Handle() = default;
  explicit H5Handle(hid_t id) : id_(id) {}
  ~H5Handle() { close(); }
  H5Handle(const H5Handle&) = delete;
  H5Handle& operator=(const H5Handle&) = delete;
  H5Handle(H5Handle&& other) noexcept : id_(std::exchange(other.id_, H5I_INVALID_HID)) {}
  H5Handle& operator=(H5Handle&& other) noexcept {
    if (this != &other) {
      close();
      id_ = std::exchange(other.id_, H5I_INVALID_HID);
    }
    return *this;
  }

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  /// Closes now; false when HDF5 reports a failure (H5Fclose flushes the
  /// file, so there a failure is a failed write and must not be ignored).
  bool close() noexcept {
    if (id_ < 0) return true;
    const herr_t status = Close(std::exchange(id_, H5I_INVALID_HID));
    return status >= 0;
  }

 private:
  hid_t id_ = H5I_INVALID_HID;
};

using H5File = H5Handle<H5Fclose>;
using H5Dataset = H5Handle<H5Dclose>;
using H5Space = H5Handle<H5Sclose>;
using H5Type = H5Handle<H5Tclose>;
using H5PropList = H5Handle<H5Pclose>;

/// While alive, HDF5 prints nothing (its default handler dumps the whole error
/// stack to stderr); the exceptions below are the only report. Restores the
/// previous handler, so a caller's own choice survives.
class H5QuietErrors {
 public:
  H5QuietErrors();
  ~H5QuietErrors();
  H5QuietErrors(const H5QuietErrors&) = delete;
  H5QuietErrors& operator=(const H5QuietErrors&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

/// Throws InputError "path: field: what (HDF5: <the most specific message on
/// its error stack>)". `field` may be empty (the file as a whole).
[[noreturn]] void throwH5(const std::filesystem::path& path, const std::string& field,
                          const std::string& what);

/// `status`, or throwH5 when it is negative (HDF5's failure for ids and herr_t).
template <class T>
T h5Check(T status, const std::filesystem::path& path, const std::string& field,
          const std::string& what) {
  if (status < 0) throwH5(path, field, what);
  return status;
}

}  // namespace tofsim::io::detail
