#include "tofsim/io/Npy.h"

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

NpyArray readNpy(const std::filesystem::path& path) {
  NpyStreamReader reader(path);
  NpyArray array;
  array.shape = reader.shape();
  array.data.resize(reader.remaining());
  reader.read(array.data.data(), array.data.size());
  return array;
}

}  // namespace tofsim::io
