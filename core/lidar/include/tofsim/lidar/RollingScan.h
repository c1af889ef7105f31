#pragma once
// A rolling scan (issue 43): a spinning lidar's azimuth columns fire one
// after another as it turns, so a scene that moves during the turn is seen
// by each column where it is at that column's own time (the rolling
// distortion of a moving scene). Column a fires at
//
//   start + (azimuth_a - azimuth_start) / 360 / rotation_rate
//
// (the channels of a column at once), and is traced against the scene at
// that time: the caller moves the scene there (glTF animations,
// scene::AnimatedScene) and rebuilds its rays, a scene update per column.

#include <cstdint>
#include <functional>

#include "tofsim/lidar/DirectWaveforms.h"
#include "tofsim/lidar/LidarSpec.h"

namespace tofsim::lidar {

/// When azimuth column `azimuth` fires after the turn's start, s.
double firingOffset_s(const LidarSpec& spec, int32_t azimuth, double rotation_rate_Hz);

/// The scene at scene time t_s, ready to trace (valid until the next call).
using SceneAtTime = std::function<const WaveformScene&(double t_s)>;

/// Every beam's direct-light waveform, column a traced against
/// sceneAt(start_s + firingOffset_s(a)); the columns in order, a column's
/// beams on `threads` threads: the same bytes for any thread count, and
/// renderDirectWaveforms' bytes for a scene that does not move.
LidarWaveforms renderRollingWaveforms(const LidarSpec& spec, const SceneAtTime& sceneAt,
                                      const TimeAxis& axis, double start_s,
                                      double rotation_rate_Hz, int threads, bool keepVolume);

}  // namespace tofsim::lidar
