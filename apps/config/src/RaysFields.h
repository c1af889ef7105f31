#pragma once
// Private to the config module: the `rays:` section's parameter table (see
// RunFields.h), a capture whose pixels are the rays of a file (RayFile.h).

#include <tuple>

#include "RunFields.h"

namespace tofsim::config {

// clang-format off
// `file` and `resolution` are read by RayFile.cpp (the rays, then their
// image, whose default size is the file's count).
inline constexpr auto kRaysFields = std::tuple{
    Custom{"file", "path", "", "required", "-",
           "the rays, one a row: a .npy (N, 6) float32 or float64, or a CSV of six columns ox, oy, oz, dx, dy, dz (m, world frame; a header row and `#` lines allowed), relative to the config; directions are normalised (a zero one is an error); read without following links"},
    Custom{"resolution", "[int, int]", "", "[N, 1]", "pixel",
           "width, height of the image the rays fill row by row; their product is N"},
    In{"last_leg_counts", &RaysConfig::imager, &capture::RayListImager::last_leg_counts, Flag{},
       {.doc = "false: the leg from a ray's hit back to its origin takes no time (the arrival is timed at the hit)"}},
};
// clang-format on

}  // namespace tofsim::config
