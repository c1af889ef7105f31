#pragma once
// Private to tofsim_io: what HDF5's shuffle + deflate filters make of a
// chunk of float32 (H5Z_filter_shuffle's byte planes, then zlib's
// compress2), done by tofsim so that a block's chunks compress on every core
// and go to the file with H5Dwrite_chunk. Any HDF5 reader decodes them with
// its own filters.

#include <cstddef>
#include <vector>

namespace tofsim::io::detail {

/// The chunk's bytes through shuffle (4-byte elements) and deflate at `level`.
std::vector<unsigned char> shuffleDeflate(const std::vector<float>& chunk, int level);

}  // namespace tofsim::io::detail
