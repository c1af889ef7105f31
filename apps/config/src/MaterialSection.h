#pragma once
// Private to the config module: issue 41's `materials:` section (a glTF
// material's settings by its name) and the `scattering_delay` mapping it
// shares with a glTF material's extras (MaterialDelays.cpp), read alike from
// both, with located errors (core/physics/temporal_response.md):
//   scattering_delay: {model: exponential, lifetime: 2.5 ns, fraction: 0.6}
//   scattering_delay: {model: gaussian, mean: 80 ps, sigma: 20 ps}
//   scattering_delay: {model: table, file: kernel.csv, delay_unit: ns}
//   scattering_delay: none   (instant: the extras' delay dropped)
// with `fraction` in [0, 1] (default 1) and an optional `reemission`, a 3x3
// matrix whose rows are the re-emitted channel and whose columns are the
// absorbed one (out = M in), each column summing to at most 1.

#include <yaml-cpp/yaml.h>

#include "ConfigNode.h"
#include "tofsim/config/RunConfig.h"

namespace tofsim::config {

/// `parent.scattering_delay` (required), checked against the render's axis
/// (a Gaussian's or a table's filter within physics::kMaxResponseTaps bins).
ScatteringDelayConfig parseScatteringDelay(const ConfigNode& parent, const TimeAxis& axis);

/// `materials:` into config.materials (the time axis read before it).
void parseMaterials(const ConfigNode& node, RunConfig& config);

/// The effective config's `materials:` (a mapping, empty when none).
YAML::Node materialsNode(const std::vector<MaterialConfig>& materials);

}  // namespace tofsim::config
