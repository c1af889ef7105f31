#include "Hdf5Extent.h"

#include <algorithm>
#include <cstdint>
#include <limits>

#include "Hdf5Handle.h"
#include "tofsim/util/Error.h"

namespace tofsim::io::detail {

namespace {

// Deflate's largest expansion (1032:1) with a margin, and what small
// datasets may lack in storage (compact or scalar ones).
constexpr std::uintmax_t kMaxInflation = 1100;
constexpr std::uintmax_t kStorageSlack = 65536;

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& field,
                       const std::string& message) {
  throw InputError(FileLoc{path.string()}, field, message);
}

// libhdf5 1.10.8 trusts two more sizes of the file that later releases
// check: a chunk's rank against the dataspace's (else it sizes its per-chunk
// bookkeeping from garbage: gigabytes for a scalar), and, without filters,
// each chunk's stored bytes against the chunk's (else it copies a whole
// chunk out of the shorter buffer it read; checked here as a sum).
void checkChunks(hid_t dataset, hid_t space, int rank, std::uintmax_t stored,
                 std::size_t valueBytes, const std::filesystem::path& path,
                 const std::string& field) {
  const H5PropList dcpl(
      h5Check(H5Dget_create_plist(dataset), path, field, "cannot read its layout"));
  if (H5Pget_layout(dcpl.get()) != H5D_CHUNKED) return;
  hsize_t chunk[H5S_MAX_RANK] = {};
  const int chunkRank = H5Pget_chunk(dcpl.get(), H5S_MAX_RANK, chunk);
  if (chunkRank != rank) {
    fail(path, field,
         "has chunks of rank " + std::to_string(chunkRank) + " in a dataspace of rank " +
             std::to_string(rank));
  }
  if (H5Pget_nfilters(dcpl.get()) != 0) return;
  std::uintmax_t chunkBytes = valueBytes;
  for (int a = 0; a < chunkRank; ++a) {
    if (chunk[a] == 0 || chunkBytes > std::numeric_limits<std::uintmax_t>::max() / chunk[a]) {
      fail(path, field, "has chunks of an impossible size");
    }
    chunkBytes *= chunk[a];
  }
  hsize_t chunks = 0;  // (1.10.8 takes no H5S_ALL here: the whole dataspace)
  h5Check(H5Dget_num_chunks(dataset, space, &chunks), path, field, "cannot count its chunks");
  if (stored % chunkBytes != 0 || stored / chunkBytes != chunks) {
    fail(path, field,
         "stores " + std::to_string(stored) + " bytes in " + std::to_string(chunks) +
             " unfiltered chunks of " + std::to_string(chunkBytes) + " bytes");
  }
}

}  // namespace

H5Extent checkedExtent(hid_t dataset, const std::filesystem::path& path, const std::string& field) {
  const H5Space space(h5Check(H5Dget_space(dataset), path, field, "cannot read its dataspace"));
  const int rank =
      h5Check(H5Sget_simple_extent_ndims(space.get()), path, field, "cannot read its shape");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  h5Check(H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr), path, field,
          "cannot read its shape");
  H5Extent extent;
  extent.count = 1;
  for (const hsize_t d : dims) {
    if (d != 0 && extent.count > std::numeric_limits<std::size_t>::max() / sizeof(float) / d) {
      fail(path, field, "is too large");
    }
    extent.count *= static_cast<std::size_t>(d);
    extent.shape.push_back(static_cast<std::size_t>(d));
  }
  const H5Type type(h5Check(H5Dget_type(dataset), path, field, "cannot read its type"));
  // The stored bytes as the file's chunk index declares them, which a damaged
  // file may inflate too: at most the file's own size.
  std::error_code ec;
  const std::uintmax_t fileBytes = std::filesystem::file_size(path, ec);
  const std::uintmax_t stored =
      std::min<std::uintmax_t>(H5Dget_storage_size(dataset), ec ? 0 : fileBytes);
  const std::size_t valueBytes = std::max<std::size_t>(H5Tget_size(type.get()), 1);
  if (extent.count > (stored * kMaxInflation + kStorageSlack) / valueBytes) {
    fail(path, field,
         "declares " + std::to_string(extent.count) + " values, more than its " +
             std::to_string(stored) + " stored bytes can hold");
  }
  checkChunks(dataset, space.get(), rank, stored, valueBytes, path, field);
  return extent;
}

}  // namespace tofsim::io::detail
