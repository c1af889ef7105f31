#pragma once
// Private to the config module: the CW-ToF device keys that are not plain
// values (SensorFields.h Custom entries): the fixed-pattern maps
// (`delay_map`, `gain_map`, `offset_map`, 2-D float32 .npy), the companding
// curve (`companding`, a list of [input, output] or a two-column .csv) and
// the capture order (`capture_order`, a list of [f, n]); and the checks
// between device keys. Every error is located at its key (and file line).

#include <yaml-cpp/yaml.h>

#include <string_view>

#include "ConfigNode.h"
#include "tofsim/capture/Camera.h"
#include "tofsim/sensors/CwTof.h"

namespace tofsim::config {

/// Parses the Custom device key `key` of node n into p; false when `key` is
/// not one of them. `frequencies` and `phase_steps` are read before (table
/// order), so the capture order is checked against them.
bool parseCwTofDeviceKey(const ConfigNode& n, std::string_view key, sensors::CwTofParams& p);

/// The checks between keys, after every key is read.
void checkCwTofDevice(const ConfigNode& n, const sensors::CwTofParams& p);

/// The maps' shapes against the image.
void checkCwTofMapsFitImage(const ConfigNode& n, const sensors::CwTofParams& p,
                            const capture::Camera& camera);

/// Emits the Custom device key `key` of p into n (nothing at its default);
/// false when `key` is not one of them.
bool emitCwTofDeviceKey(YAML::Node& n, std::string_view key, const sensors::CwTofParams& p);

}  // namespace tofsim::config
