#include "Hdf5Handle.h"

#include "tofsim/util/Error.h"

namespace tofsim::io::detail {

H5QuietErrors::H5QuietErrors() {
  H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

H5QuietErrors::~H5QuietErrors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

namespace {
// Walked upward, the first entry is where HDF5 detected the problem ("unable
// to open file: ... errno = 2, ... 'No such file or directory'"): the most
// useful line; the API-level entries above it only repeat "failed".
herr_t keepFirst(unsigned n, const H5E_error2_t* error, void* out) {
  if (n == 0 && error->desc) *static_cast<std::string*>(out) = error->desc;
  return 0;
}
}  // namespace

void throwH5(const std::filesystem::path& path, const std::string& field, const std::string& what) {
  std::string detail;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, keepFirst, &detail);
  H5Eclear2(H5E_DEFAULT);
  // One line, as InputError's what() is (HDF5's messages embed ctime's '\n').
  for (char& ch : detail) {
    if (ch == '\n') ch = ' ';
  }
  throw InputError(FileLoc{path.string()}, field,
                   detail.empty() ? what : what + " (HDF5: " + detail + ")");
}

}  // namespace tofsim::io::detail
