#include "tofsim/io/Npy.h"

#include <algorithm>
#include <string>

#include "NpyHeader.h"
#include "tofsim/util/Error.h"

namespace tofsim::io {

namespace {
// Headers longer than this are not produced by NumPy for any realistic shape.
constexpr std::size_t kMaxPrefixBytes = std::size_t{1} << 20;
}  // namespace

NpyStreamReader::NpyStreamReader(const std::filesystem::path& path) : name_(path.string()) {
  std::error_code ec;
  const std::uintmax_t fileSize = std::filesystem::file_size(path, ec);
  in_.open(path, std::ios::binary);
  if (ec || !in_) throw InputError(FileLoc{name_}, "", "cannot open .npy file");

  std::string prefix(static_cast<std::size_t>(std::min<std::uintmax_t>(fileSize, kMaxPrefixBytes)),
                     '\0');
  in_.read(prefix.data(), static_cast<std::streamsize>(prefix.size()));
  if (!in_) throw InputError(FileLoc{name_}, "", "cannot read .npy header");
  const detail::NpyHeaderInfo info = detail::decodeNpyHeader(prefix, name_);

  count_ = detail::checkedElementCount(info.shape, name_);
  const std::uintmax_t needed = info.dataOffset + count_ * sizeof(float);
  if (fileSize != needed) {
    throw InputError(FileLoc{name_}, "",
                     std::string(fileSize < needed ? "truncated" : "unexpected trailing bytes") +
                         ": shape needs " + std::to_string(count_ * sizeof(float)) +
                         " bytes of data, file has " + std::to_string(fileSize - info.dataOffset));
  }
  shape_ = info.shape;
  in_.seekg(static_cast<std::streamoff>(info.dataOffset));
}

void NpyStreamReader::read(float* out, std::size_t count) {
  TOFSIM_CHECK(count <= remaining());
  in_.read(reinterpret_cast<char*>(out), static_cast<std::streamsize>(count * sizeof(float)));
  if (!in_) throw InputError(FileLoc{name_}, "", "read failed");
  read_ += count;
}

}  // namespace tofsim::io
