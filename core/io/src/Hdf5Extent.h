#pragma once
// Private to tofsim_io: a dataset's extent, checked before anyone allocates
// for it. The extent is a few bytes of the file, so a damaged or hostile file
// can declare any size; every HDF5 reader here sizes its buffers from this.

#include <hdf5.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace tofsim::io::detail {

struct H5Extent {
  std::vector<std::size_t> shape;  ///< {} for a scalar
  std::size_t count = 0;           ///< values: the product of shape (1 for a scalar)
};

/// The extent of `dataset` in the file at `path`; InputError "path: field:
/// ..." when its values would overflow size_t as bytes, or are more than its
/// stored bytes (at most the file's size) can hold (deflate's 1032:1 at most,
/// plus 64 KiB for small datasets; HDF5's fill values for chunks never
/// written are refused beyond that: tofsim and tal write every chunk), or its
/// chunks disagree with it (their rank; unfiltered, their stored bytes).
H5Extent checkedExtent(hid_t dataset, const std::filesystem::path& path, const std::string& field);

}  // namespace tofsim::io::detail
