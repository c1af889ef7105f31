#include "BinMajorSpill.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

namespace {

[[noreturn]] void failIo(const std::filesystem::path& path, const char* what) {
  throw InputError(FileLoc{path.string()}, "",
                   std::string(what) + " the video's bin-major temporary: " + std::strerror(errno));
}

// pwrite/pread of all `bytes`, resuming after short transfers.
template <typename Transfer, typename Pointer>
void transferAll(Transfer transfer, int fd, Pointer data, std::size_t bytes, off_t offset,
                 const std::filesystem::path& path, const char* what) {
  while (bytes > 0) {
    const ssize_t n = transfer(fd, data, bytes, offset);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) failIo(path, what);
    data += n;
    bytes -= static_cast<std::size_t>(n);
    offset += n;
  }
}

}  // namespace

BinMajorSpill::BinMajorSpill(std::filesystem::path path, const sensors::VolumeShape& shape)
    : path_(std::move(path)), shape_(shape), white_(shape.pixelCount() * shape.pixelFloats()) {
  fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (fd_ < 0) failIo(path_, "cannot create");
}

BinMajorSpill::~BinMajorSpill() {
  if (fd_ >= 0) ::close(fd_);
  std::error_code ec;
  std::filesystem::remove(path_, ec);
}

void BinMajorSpill::append(const sensors::PixelSpan& span) {
  TOFSIM_CHECK(span.firstPixel == appended_ && appended_ + span.pixelCount <= shape_.pixelCount());
  const std::size_t C = static_cast<std::size_t>(shape_.channels);
  const std::size_t pixelFloats = shape_.pixelFloats();
  white_.add(span.volume, span.pixelCount * pixelFloats);
  gather_.resize(span.pixelCount * C);
  for (int32_t t = 0; t < shape_.axis.bins; ++t) {
    for (std::size_t p = 0; p < span.pixelCount; ++p) {
      const float* in = span.volume + p * pixelFloats + static_cast<std::size_t>(t) * C;
      for (std::size_t c = 0; c < C; ++c) gather_[p * C + c] = in[c];
    }
    const auto offset = static_cast<off_t>(
        (static_cast<std::size_t>(t) * shape_.pixelCount() + span.firstPixel) * C * sizeof(float));
    transferAll(::pwrite, fd_, reinterpret_cast<const char*>(gather_.data()),
                gather_.size() * sizeof(float), offset, path_, "cannot write");
  }
  appended_ += span.pixelCount;
}

void BinMajorSpill::readBin(int32_t t, float* out) const {
  const std::size_t floats = shape_.pixelCount() * static_cast<std::size_t>(shape_.channels);
  const auto offset = static_cast<off_t>(static_cast<std::size_t>(t) * floats * sizeof(float));
  transferAll(::pread, fd_, reinterpret_cast<char*>(out), floats * sizeof(float), offset, path_,
              "cannot read");
}

imaging::BinFrames BinMajorSpill::frames() {
  TOFSIM_CHECK(appended_ == shape_.pixelCount());
  imaging::BinFrames frames;
  frames.width = shape_.width;
  frames.height = shape_.height;
  frames.channels = shape_.channels;
  frames.axis = shape_.axis;
  frames.white = white_.white();
  frames.readBin = [this](int32_t t, float* out) { readBin(t, out); };
  return frames;
}

}  // namespace tofsim::pipeline
