#pragma once
// A sensor's device presets (`preset: <name>`): published values of a real
// device that fill the sensor's defaults before the config's own keys are
// read (every explicit key wins). Each value names its source; a value a
// preset sets without one is listed as assumed, with what it stands for.
// The same shape for every sensor type (SpadPresets.h, CwTofPresets.h), so
// the config layer and the metadata treat them alike.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tofsim::sensors {

/// One config key a preset sets: its source, or nullptr where it is assumed
/// (then `note` says why that value).
struct PresetValue {
  const char* key;     ///< the config key (the sensor's field name)
  const char* source;  ///< "[PH300] 4 ps base resolution"; nullptr: assumed
  const char* note;    ///< for an assumed value: what it stands for
};

template <class Params>
struct DevicePreset {
  const char* name;
  const char* device;  ///< one line: what the device is, what the preset leaves out
  void (*apply)(Params&);
  std::span<const PresetValue> values;   ///< in the order apply sets them
  std::span<const char* const> sources;  ///< source key -> reference, one line each
  /// The device's pixel array; the image is the camera's, so another size
  /// is a warning (presetImageWarnings), not an error. 0: not checked.
  int32_t width = 0, height = 0;
};

/// The preset called `name` among `presets`, or nullptr.
template <class Params>
const DevicePreset<Params>* findPreset(std::span<const DevicePreset<Params>> presets,
                                       std::string_view name) {
  for (const DevicePreset<Params>& p : presets) {
    if (name == p.name) return &p;
  }
  return nullptr;
}

/// One warning when a width x height image is not the preset's pixel array
/// (the camera decides the image: the preset's other values still apply);
/// empty when it is, or the preset gives none, or there is no preset.
template <class Params>
std::vector<std::string> presetImageWarnings(const DevicePreset<Params>* preset, int32_t width,
                                             int32_t height) {
  if (!preset || preset->width <= 0 || (width == preset->width && height == preset->height)) {
    return {};
  }
  return {"the image is " + std::to_string(width) + " x " + std::to_string(height) +
          " (camera.width x camera.height) but preset '" + preset->name + "' is a " +
          std::to_string(preset->width) + " x " + std::to_string(preset->height) +
          " device: its raws, ranges and noise are applied to the camera's pixels as they are"};
}

}  // namespace tofsim::sensors
