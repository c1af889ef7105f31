#pragma once
// Private to the config module: what the `sensors:` list must agree on with
// the rest of the run (names usable as folders, a CW-ToF error by bounce
// order that has its bounces, SPAD gates inside the TDC's window, channel
// weights for the volume's channels), each a
// located error on the sensor's entry.

#include "ConfigNode.h"
#include "tofsim/config/RunConfig.h"

namespace tofsim::config {

void checkSensorNames(const ConfigNode& list, const std::vector<sensors::SensorSpec>& specs);
void checkBounceOrders(const ConfigNode& list, const RunConfig& config);
void checkSpadGates(const ConfigNode& list, const RunConfig& config);
/// Each sensor's `channel_weights` (or `channel`) against the channels of the
/// volume the run gives its sensors (a camera's R, G, B; an NLOS scan's one, H).
void checkSensorChannels(const ConfigNode& list, const RunConfig& config);

}  // namespace tofsim::config
