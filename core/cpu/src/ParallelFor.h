#pragma once
// The CPU backend's parallel loop is the shared one (tofsim/util/ParallelFor.h).

#include "tofsim/util/ParallelFor.h"

namespace tofsim::cpu {
using tofsim::parallelFor;
}  // namespace tofsim::cpu
