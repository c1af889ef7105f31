#pragma once
// Private to the config module: reads the `sequence:` section.

#include "ConfigNode.h"
#include "tofsim/config/SequenceConfig.h"

namespace tofsim::config {

/// The frame times are filled in (times_s); errors name the key and its line.
SequenceConfig parseSequence(const ConfigNode& node);

}  // namespace tofsim::config
