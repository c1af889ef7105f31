#pragma once
// Private to the config module: checks of a loaded run that tie sections
// together (the VPL count a light and render.indirect ask for, what only
// the CPU backend gathers, a sequence's video, what an nlos capture cannot
// write), each a located error on the key that decides.

#include "ConfigNode.h"
#include "tofsim/config/RunConfig.h"

namespace tofsim::config {

void checkVplCount(const ConfigNode& root, const RunConfig& config);
void checkBackendCapabilities(const ConfigNode& root, const RunConfig& config);
/// Also turns sequence.video off where output.steady is off and it was not asked for.
void checkSequenceVideo(const ConfigNode& sequence, RunConfig& config);
void checkNlosRun(const ConfigNode& root);

}  // namespace tofsim::config
