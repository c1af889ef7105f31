#pragma once
// Private to the config library: the names runs of a batch get when the file
// does not name them (BatchExpansion.cpp, BatchConfigLoader.cpp).

#include <cstddef>
#include <string>
#include <vector>

#include "tofsim/config/RunConfig.h"

namespace tofsim::config {

/// "run%04zu" plus "_<last key part>-<value>" per varied key, cut to
/// kMaxRunName characters.
std::string batchRunName(std::size_t index, const std::vector<Override>& varied);

}  // namespace tofsim::config
