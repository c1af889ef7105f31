#pragma once
// SPAD device presets (`preset: <name>`): published values of real devices
// that fill a SPAD's defaults before the config's own keys are read (every
// explicit key wins). Each value names its source; a value a preset sets
// without one is listed as assumed. Values and sources from
// shared/research/detector-models.md, section 4 (source keys resolve there).

#include <span>
#include <string_view>

#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors {

/// One config key a preset sets: its source, or nullptr where it is assumed
/// (then `source` says why that value).
struct SpadPresetValue {
  const char* key;     ///< the config key (kSpadFields / kBinsFields name)
  const char* source;  ///< "[PH300] 4 ps base resolution"; nullptr: assumed
  const char* note;    ///< for an assumed value: what it stands for
};

struct SpadPreset {
  const char* name;
  const char* device;  ///< one line: what the device is, what the preset leaves out
  void (*apply)(SpadParams&);
  std::span<const SpadPresetValue> values;  ///< in the order apply sets them
  std::span<const char* const> sources;     ///< source key -> reference, one line each
};

/// Every preset, in the order the docs list them.
std::span<const SpadPreset> spadPresets();

/// The preset called `name`, or nullptr.
const SpadPreset* findSpadPreset(std::string_view name);

}  // namespace tofsim::sensors
