#pragma once
// Private to the config module: the `time:` section's parameter table (see RunFields.h).

#include <array>
#include <tuple>

#include "RunFields.h"

namespace tofsim::config {

// clang-format off
// The keys of `time`, on the run's time axis (RunConfig::render.time, whose
// defaults are kDefaultTimeAxis).
inline constexpr auto kTimeFields = std::tuple{
    Field{"start", &TimeAxis::start_s, Picoseconds{kAnyValue},
          {.doc = "leading edge of bin 0 (time from the light's impulse to arrival at the camera)"}},
    Field{"bin_width", &TimeAxis::bin_width_s, Picoseconds{kPositive},
          {.doc = "bin width"}},
    Field{"bins", &TimeAxis::bins, IntegerIn{1, kMaxTimeBins},
          {.doc = "number of bins"}},
    Field{"index_of_refraction", &TimeAxis::index_of_refraction, Number{{.min = 1.0}},
          {.doc = "of the medium filling the scene (slows light)"}},
    Field{"camera_unwarp", &TimeAxis::camera_unwarp, Flag{},
          {.doc = "drop the surface -> camera delay (time at the surface)"}},
};
// clang-format on

}  // namespace tofsim::config
