#pragma once
// SPAD device presets (`preset: <name>`): published values of real devices
// that fill a SPAD's defaults before the config's own keys are read (every
// explicit key wins). Each value names its source; a value a preset sets
// without one is listed as assumed. Values and sources from
// shared/research/detector-models.md, section 4 (source keys resolve there).

#include <span>
#include <string_view>

#include "tofsim/sensors/DevicePreset.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors {

using SpadPresetValue = PresetValue;
using SpadPreset = DevicePreset<SpadParams>;

/// Every preset, in the order the docs list them.
std::span<const SpadPreset> spadPresets();

/// The preset called `name`, or nullptr.
const SpadPreset* findSpadPreset(std::string_view name);

}  // namespace tofsim::sensors
