#pragma once
// A frame's returns: each beam's echoes (Echoes.h) as the mode keeps them,
// as images and as points.

#include <vector>

#include "tofsim/lidar/DirectWaveforms.h"
#include "tofsim/lidar/LidarSpec.h"
#include "tofsim/lidar/SparseWaveforms.h"
#include "tofsim/lidar/PointCloudFiles.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::lidar {

struct LidarReturns {
  /// (channels, azimuths): the mode's first return's range (m) and energy
  /// (the waveform's unit); 0 where a beam has none.
  Image range_m, intensity;
  /// Every kept return, beam by beam (ring-major, then azimuth, then return).
  std::vector<LidarPoint> points;
  std::size_t beamsWithReturns = 0;
};

/// The returns of `waveforms` (renderDirectWaveforms' volume); a beam fires
/// beamFiringOffset_s (RollingScan.h) after the scan's start: `rate_Hz` is
/// the turns (spinning) or frames (raster) per second.
LidarReturns lidarReturns(const LidarSpec& spec, const TransientVolume& waveforms,
                          double rate_Hz);
/// The same of the beams' nonzero bins (the same returns to the bit), on
/// `threads` threads (0: all; the same bytes on any count).
LidarReturns lidarReturns(const LidarSpec& spec, const SparseWaveforms& waveforms,
                          const TimeAxis& axis, double rate_Hz, int threads = 1);
/// Of a render's waveforms: its volume where kept (what was added to it
/// included), else its nonzero bins.
LidarReturns lidarReturns(const LidarSpec& spec, const LidarWaveforms& waveforms,
                          double rate_Hz, int threads = 1);

}  // namespace tofsim::lidar
