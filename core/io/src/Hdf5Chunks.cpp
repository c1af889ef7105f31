#include "Hdf5Chunks.h"

#include <algorithm>

namespace tofsim::io::detail {

namespace {
constexpr std::size_t kChunkValues = std::size_t{32} << 10;  // 128 KiB of float32
constexpr std::size_t kTimeChunk = 128;
}  // namespace

std::vector<hsize_t> captureChunk(const NpyShape& shape) {
  if (shape.empty() || std::find(shape.begin(), shape.end(), 0) != shape.end()) return {};
  std::vector<hsize_t> chunk(shape.begin(), shape.end());
  if (shape.size() == 1) {
    chunk[0] = std::min(shape[0], kChunkValues);
    return chunk;
  }
  if (shape.size() >= 3) chunk[2] = std::min(shape[2], kTimeChunk);
  std::size_t inner = 1;  // values of one (row, column) in a chunk
  for (std::size_t a = 2; a < chunk.size(); ++a) inner *= chunk[a];
  if (shape.size() == 2) {
    chunk[0] = std::clamp<std::size_t>(kChunkValues / shape[1], 1, shape[0]);
    return chunk;
  }
  chunk[0] = 1;
  chunk[1] = std::clamp<std::size_t>(kChunkValues / inner, 1, shape[1]);
  return chunk;
}

}  // namespace tofsim::io::detail
