#include <string>
#include <utility>

#include "NpyHeader.h"
#include "tofsim/io/Npy.h"
#include "tofsim/util/Error.h"

namespace tofsim::io {

NpyStreamWriter::NpyStreamWriter(std::filesystem::path path, NpyShape shape)
    : file_(std::move(path)), shape_(std::move(shape)) {
  expected_ = detail::checkedElementCount(shape_, file_.finalPath().string());
  file_.write(detail::encodeNpyHeader(shape_));
}

void NpyStreamWriter::append(const float* data, std::size_t count) {
  if (count > expected_ - appended_) {
    throw InputError(FileLoc{file_.finalPath().string()}, "",
                     "npy stream overflow: appending " + std::to_string(count) + " floats after " +
                         std::to_string(appended_) + " of " + std::to_string(expected_));
  }
  file_.write(data, count * sizeof(float));
  appended_ += count;
}

void NpyStreamWriter::commit() {
  if (appended_ != expected_) {
    const std::string where = file_.finalPath().string();
    { AtomicFile incomplete = std::move(file_); }  // removes the temporary now
    throw InputError(FileLoc{where}, "",
                     "npy stream incomplete: " + std::to_string(appended_) + " of " +
                         std::to_string(expected_) + " floats appended; file not written");
  }
  file_.commit();
}

}  // namespace tofsim::io
