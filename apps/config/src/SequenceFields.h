#pragma once
// Private to the config module: the `sequence:` section's parameter table
// (see RunFields.h). `times` is a Custom entry, parsed in SequenceConfigParser.cpp.

#include <tuple>

#include "tofsim/config/SequenceConfig.h"
#include "tofsim/sensors/ParamField.h"

namespace tofsim::config {

// clang-format off
inline constexpr auto kSequenceFields = std::tuple{
    sensors::Field{"start", &SequenceConfig::start_s, sensors::Duration{sensors::kAnyValue},
          {.doc = "scene time of frame 0 (with `rate` and `count`)"}},
    sensors::Field{"rate", &SequenceConfig::rate_Hz, sensors::Rate{sensors::kPositive},
          {.unit = "Hz", .doc = "frames per second of scene time: frame k at `start` + k / `rate` (with `count`; not with `times`)", .unset = "none"}},
    sensors::Field{"count", &SequenceConfig::count, sensors::IntegerIn{0, 100000},
          {.doc = "frames (with `rate`), >= 1", .unset = "none"}},
    sensors::Custom{"times", "list of durations", "increasing", "none", "s",
          "the frames' scene times, in place of `start`, `rate` and `count`"},
    sensors::Field{"exposure_samples", &SequenceConfig::exposure_samples, sensors::IntegerIn{1, 64},
          {.doc = "samples of an exposure that moves: renders per CW-ToF raw over its `integration_time`, and per SPAD `exposure_time`, at the middles of equal parts of it (1: its middle); each distinct time is one render"}},
    sensors::Field{"video", &SequenceConfig::video, sensors::Flag{},
          {.doc = "`sequence.mp4`: the frames' steady images in order, one tone scale for all, stamped with their times; needs `output.steady` (an error with `output.steady: false`, where it defaults to false)"}},
};
// clang-format on

}  // namespace tofsim::config
