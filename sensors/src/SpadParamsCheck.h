#pragma once
// Private to the SPAD model: the parameters' invariants. The config layer
// reports bad input with its location first; a failure here is a caller's bug
// (TOFSIM_CHECK), checked where the model opens.

#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors::detail {

void checkSpadParams(const SpadParams& p);

}  // namespace tofsim::sensors::detail
