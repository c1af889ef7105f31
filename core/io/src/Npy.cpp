#include "tofsim/io/Npy.h"

#include <algorithm>
#include <fstream>
#include <string>

#include "NpyHeader.h"
#include "tofsim/util/Error.h"

namespace tofsim::io {

namespace {
// Headers longer than this are not produced by NumPy for any realistic shape.
constexpr std::size_t kMaxPrefixBytes = std::size_t{1} << 20;
}  // namespace

std::size_t elementCount(const NpyShape& shape) {
  std::size_t n = 1;
  for (const std::size_t d : shape) n *= d;
  return n;
}

void writeNpy(const std::filesystem::path& path, const NpyShape& shape, const float* data) {
  AtomicFile file(path);
  file.write(detail::encodeNpyHeader(shape));
  file.write(data, elementCount(shape) * sizeof(float));
  file.commit();
}

void writeNpy(const std::filesystem::path& path, const TransientVolume& volume) {
  const NpyShape shape{static_cast<std::size_t>(volume.height()),
                       static_cast<std::size_t>(volume.width()),
                       static_cast<std::size_t>(volume.bins()),
                       static_cast<std::size_t>(volume.channels())};
  TOFSIM_CHECK(elementCount(shape) == volume.size());
  writeNpy(path, shape, volume.data());
}

void writeNpy(const std::filesystem::path& path, const Image& image) {
  const NpyShape shape{static_cast<std::size_t>(image.height),
                       static_cast<std::size_t>(image.width),
                       static_cast<std::size_t>(image.channels)};
  TOFSIM_CHECK(elementCount(shape) == image.data.size());
  writeNpy(path, shape, image.data.data());
}

NpyArray readNpy(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  const std::uintmax_t fileSize = std::filesystem::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  if (ec || !in) throw InputError(FileLoc{name}, "", "cannot open .npy file");

  std::string prefix(static_cast<std::size_t>(std::min<std::uintmax_t>(fileSize, kMaxPrefixBytes)),
                     '\0');
  in.read(prefix.data(), static_cast<std::streamsize>(prefix.size()));
  if (!in) throw InputError(FileLoc{name}, "", "cannot read .npy header");
  const detail::NpyHeaderInfo info = detail::decodeNpyHeader(prefix, name);

  const std::size_t count = detail::checkedElementCount(info.shape, name);
  const std::uintmax_t needed = info.dataOffset + count * sizeof(float);
  if (fileSize != needed) {
    throw InputError(FileLoc{name}, "",
                     std::string(fileSize < needed ? "truncated" : "unexpected trailing bytes") +
                         ": shape needs " + std::to_string(count * sizeof(float)) +
                         " bytes of data, file has " +
                         std::to_string(fileSize - info.dataOffset));
  }

  NpyArray array;
  array.shape = info.shape;
  array.data.resize(count);
  in.seekg(static_cast<std::streamoff>(info.dataOffset));
  in.read(reinterpret_cast<char*>(array.data.data()),
          static_cast<std::streamsize>(count * sizeof(float)));
  if (!in) throw InputError(FileLoc{name}, "", "read failed");
  return array;
}

}  // namespace tofsim::io
