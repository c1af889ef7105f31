#include "tofsim/io/Npy.h"
#include "tofsim/io/NpyBytes.h"

#include <algorithm>
#include <cstring>

#include "NpyHeader.h"
#include "tofsim/util/Error.h"

namespace tofsim::io {

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
  const NpyShape shape{
      static_cast<std::size_t>(volume.height()), static_cast<std::size_t>(volume.width()),
      static_cast<std::size_t>(volume.bins()), static_cast<std::size_t>(volume.channels())};
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

NpyArray parseNpy(std::string_view bytes, const std::string& file) {
  const detail::NpyHeaderInfo header = detail::decodeNpyHeader(bytes, file, true);
  NpyArray array;
  array.shape = header.shape;
  const std::size_t count = detail::checkedElementCount(header.shape, file);
  const std::size_t width = header.float64 ? sizeof(double) : sizeof(float);
  const std::size_t available = bytes.size() - std::min(bytes.size(), header.dataOffset);
  if (count > available / width || available != count * width) {
    throw InputError(FileLoc{file}, "",
                     "npy data holds " + std::to_string(available) + " bytes, the shape needs " +
                         std::to_string(count) + " x " + std::to_string(width));
  }
  array.data.resize(count);
  const char* data = bytes.data() + header.dataOffset;
  for (std::size_t i = 0; i < count; ++i) {
    if (header.float64) {
      double v;
      std::memcpy(&v, data + i * width, sizeof v);
      array.data[i] = static_cast<float>(v);
    } else {
      std::memcpy(&array.data[i], data + i * width, sizeof(float));
    }
  }
  return array;
}

NpyArray readNpy(const std::filesystem::path& path) {
  NpyStreamReader reader(path);
  NpyArray array;
  array.shape = reader.shape();
  array.data.resize(reader.remaining());
  reader.read(array.data.data(), array.data.size());
  return array;
}

}  // namespace tofsim::io
