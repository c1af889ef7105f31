#pragma once
// Private to tofsim_io: the chunk shape of a dataset in capture.h5.

#include <hdf5.h>

#include <vector>

#include "tofsim/io/Npy.h"

namespace tofsim::io::detail {

/// Chunks of about 128 KiB (under h5py's 1 MiB chunk cache, so a partial read
/// decompresses each chunk once). Rank >= 3, (rows, columns, T, ...): one
/// row, a run of columns, up to 128 of axis 2 (the time bins) and all of the
/// axes after it: a pixel's histogram reads ceil(T / 128) chunks, a time
/// slice one chunk per run of columns of each row. Rank 2: whole rows; rank 1:
/// runs. Empty when the dataset cannot be chunked (rank 0, a zero axis).
std::vector<hsize_t> captureChunk(const NpyShape& shape);

}  // namespace tofsim::io::detail
