#pragma once
// A whole .npy already read into memory (a file opened without following
// links), float32 or float64: the readers of small input tables whose
// values may come as float64 (a ray list's rays).

#include <string>
#include <string_view>

#include "tofsim/io/Npy.h"

namespace tofsim::io {

/// float32, or float64 ('<f8') rounded to float. Throws InputError naming
/// `file` as readNpy does, and for a size that does not match the shape.
NpyArray parseNpy(std::string_view bytes, const std::string& file);

}  // namespace tofsim::io
