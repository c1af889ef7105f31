#pragma once
// A preset's capture order carried over to other frequencies or phase steps
// (a sweep over `frequencies` of `preset: kinect-v2`). The rule, written
// once here and in configs/README.md (`capture_order`): the preset's order
// must be frequency-major (the raws of one frequency together) with one step
// order for every frequency. The frequencies then follow the preset's block
// order when their count is the preset's, else index order when the preset's
// is index order; the steps follow the preset's step order when their count
// is the preset's, else the same rule on the new count when the preset's is
// ascending (n) or descending from 0 ((N - n) mod N, Kinect's). Anything else
// cannot be derived: the config must list the order itself.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tofsim/sensors/CwTofDevice.h"

namespace tofsim::sensors {

/// `pattern` (an order over presetFrequencies x presetSteps raws) applied to
/// frequencies x steps raws, or nullopt when the rule above does not carry
/// it over. A pattern of exactly those raws is returned as it is.
std::optional<std::vector<CwTofCaptureStep>> deriveCwTofCaptureOrder(
    const std::vector<CwTofCaptureStep>& pattern, int32_t presetFrequencies, int32_t presetSteps,
    int32_t frequencies, int32_t steps);

/// An order as a config writes it: "[[0, 0], [0, 2], ...]".
std::string cwtofCaptureOrderText(const std::vector<CwTofCaptureStep>& order);

}  // namespace tofsim::sensors
