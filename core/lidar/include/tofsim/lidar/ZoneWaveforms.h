#pragma once
// A multizone direct-ToF sensor's histograms (scan: zones): each zone is a
// beam whose receiver rays tile the zone's solid angle, lit by the flood
// emitter (ScanGrid.h), its direct light added by addBeamWaveform
// (DirectWaveforms.h) exactly as a spinning lidar's beam.

#include "tofsim/lidar/DirectWaveforms.h"

namespace tofsim::lidar {

/// Every zone's waveform (rows x columns pixels), on `threads` threads (0:
/// all), one zone per task: the same bytes for any thread count.
LidarWaveforms renderZoneWaveforms(const LidarSpec& spec, const WaveformScene& scene,
                                   const TimeAxis& axis, int threads);

}  // namespace tofsim::lidar
