#pragma once
// Private to the pipeline: the one JSON form of a render's stats, a camera's
// in transient.json and an NLOS capture's in H.json ("stats"; RenderStats.h
// gives them as text to the Python module).

#include <nlohmann/json.hpp>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/pipeline/NlosRender.h"

namespace tofsim::pipeline {

/// Time, segments, VPLs, sampled pixels, GPU memory, the energy on and off
/// the time axis (result.onAxisEnergy filled in), rejected non-finite
/// values and the time by pass.
nlohmann::json renderStatsJson(const capture::RenderResult& result);

/// Time, captures, scene preparations, VPLs and the device of an NLOS capture.
nlohmann::ordered_json nlosStatsJson(const NlosVolume& volume);

}  // namespace tofsim::pipeline
