#pragma once
// A rendered NLOS scan as y-tal's capture (io::TalCapture): H, the grids in
// tal's X_Y_3 order, the origins, the time axis in metres of optical path,
// and tofsim's version, seed and effective config in scene_info (the only
// place tal's reader allows anything of ours).

#include "tofsim/config/RunConfig.h"
#include "tofsim/io/TalCapture.h"
#include "tofsim/pipeline/NlosRender.h"
#include "tofsim/pipeline/NlosScan.h"

namespace tofsim::pipeline {

io::TalCapture talCaptureOf(const config::RunConfig& config, const NlosScanGeometry& scan,
                            const NlosVolume& volume);

}  // namespace tofsim::pipeline
