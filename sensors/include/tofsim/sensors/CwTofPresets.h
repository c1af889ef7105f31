#pragma once
// CW-ToF device presets (`preset: <name>`): published values of real cameras
// that fill a CW-ToF sensor's defaults before the config's own keys are read
// (every explicit key wins). Each value names its source; a value a preset
// sets without one (Azure Kinect's frequencies, say) is listed as assumed.
// Values and sources from shared/research/detector-models.md, sections 2.3-2.5
// and 4 (source keys resolve there). The same shape as SpadPresets.h.

#include <span>
#include <string_view>

#include "tofsim/sensors/CwTof.h"
#include "tofsim/sensors/DevicePreset.h"

namespace tofsim::sensors {

using CwTofPreset = DevicePreset<CwTofParams>;

/// Every preset, in the order the docs list them.
std::span<const CwTofPreset> cwtofPresets();

/// The preset called `name`, or nullptr.
const CwTofPreset* findCwTofPreset(std::string_view name);

}  // namespace tofsim::sensors
