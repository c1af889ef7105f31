#include "Hdf5ChunkCodec.h"

#include <zlib.h>

#include <cstring>

#include "tofsim/util/Error.h"

namespace tofsim::io::detail {

std::vector<unsigned char> shuffleDeflate(const std::vector<float>& chunk, int level) {
  const std::size_t n = chunk.size();
  std::vector<unsigned char> planes(n * sizeof(float));
  const auto* bytes = reinterpret_cast<const unsigned char*>(chunk.data());
  for (std::size_t b = 0; b < sizeof(float); ++b) {  // byte b of every value, then b + 1
    unsigned char* plane = planes.data() + b * n;
    for (std::size_t i = 0; i < n; ++i) plane[i] = bytes[i * sizeof(float) + b];
  }
  uLongf size = compressBound(static_cast<uLong>(planes.size()));
  std::vector<unsigned char> out(size);
  const int status =
      compress2(out.data(), &size, planes.data(), static_cast<uLong>(planes.size()), level);
  TOFSIM_CHECK_MSG(status == Z_OK, "zlib compress2 failed");
  out.resize(size);
  return out;
}

}  // namespace tofsim::io::detail
