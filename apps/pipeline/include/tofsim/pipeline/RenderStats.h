#pragma once
// A render's stats as transient.json and H.json write them ("stats"), as JSON
// text: the Python module's RenderResult.stats and NlosResult.stats are read
// from it, so the files and the module cannot drift.

#include <string>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/pipeline/NlosRender.h"

namespace tofsim::pipeline {

/// One JSON object (result.onAxisEnergy filled in).
std::string renderStatsText(const capture::RenderResult& result);
/// One JSON object, H.json's stats.
std::string nlosStatsText(const NlosVolume& volume);

}  // namespace tofsim::pipeline
