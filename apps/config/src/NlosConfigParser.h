#pragma once
// Private to the config module: reads the `nlos:` section.

#include "ConfigNode.h"
#include "tofsim/config/NlosConfig.h"

namespace tofsim::config {

NlosConfig parseNlos(const ConfigNode& node);

}  // namespace tofsim::config
