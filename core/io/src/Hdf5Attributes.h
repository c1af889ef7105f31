#pragma once
// Private to tofsim_io: attributes of an HDF5 object, as h5py writes and reads
// them (variable-length UTF-8 strings, float64, int64).

#include <hdf5.h>

#include <filesystem>
#include <optional>
#include <string>

#include "tofsim/io/Hdf5Capture.h"

namespace tofsim::io::detail {

/// Writes (or replaces) `attribute` on `object`; InputError "path: field: ..."
/// when HDF5 fails.
void writeAttribute(hid_t object, const H5Attribute& attribute, const std::filesystem::path& path,
                    const std::string& field);

/// The scalar string attribute `name` of `object` (variable or fixed length),
/// nothing when it has none; InputError when it is not a string.
std::optional<std::string> readStringAttribute(hid_t object, const std::string& name,
                                               const std::filesystem::path& path,
                                               const std::string& field);

}  // namespace tofsim::io::detail
