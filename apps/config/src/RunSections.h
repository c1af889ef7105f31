#pragma once
// Private to the config module: the sections of a run config a table
// declares (RunFields.h, TimeFields.h, LightFields.h, OutputFields.h), read
// into the RunConfig with the checks that tie a key to another.

#include "ConfigNode.h"
#include "tofsim/config/RunConfig.h"

namespace tofsim::config {

void parseLight(const ConfigNode& node, LightConfig& out);
void parseTime(const ConfigNode& node, TimeAxis& time);
/// `render`, with `render.indirect` and `render.reference`.
void parseRender(const ConfigNode& node, RunConfig& out);
/// `output`; its bounce components are checked against `config`'s renderer.
void parseOutput(const ConfigNode& node, const RunConfig& config, OutputConfig& o);

}  // namespace tofsim::config
