#pragma once
// The lidar benches' one frame (tofsim_lidar_beams, tofsim_lidar_multipath):
// a spinning lidar 1.8 m above configs/scenes/lidar_street.gltf's street
// (spin axis +y, azimuth 0 along +x), `channels` from -15 to +15 degrees x
// `azimuths` over the turn, 300 ps bins (4.5 cm of range: 1000 bins reach
// 45 m); and the benches' stopwatch.

#include <chrono>
#include <cstdint>
#include <ctime>

#include "tofsim/lidar/LidarSpec.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::bench {

struct StreetFrame {
  lidar::LidarSpec spec;
  TimeAxis axis;
};

inline StreetFrame streetFrame(int channels, int azimuths, int32_t bins) {
  StreetFrame f;
  f.spec.position_world = {0.0f, 1.8f, 0.0f};
  f.spec.up_world = {0.0f, 1.0f, 0.0f};
  f.spec.forward_world = {1.0f, 0.0f, 0.0f};
  for (int c = 0; c < channels; ++c) {
    f.spec.elevations_deg.push_back(channels == 1 ? 0.0 : -15.0 + 30.0 * c / (channels - 1));
  }
  f.spec.azimuth_step_deg = 360.0 / azimuths;
  f.axis.bin_width_s = 300e-12;
  f.axis.bins = bins;
  return f;
}

inline double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

/// The CPU time the process has used, all its threads (s).
inline double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

}  // namespace tofsim::bench
