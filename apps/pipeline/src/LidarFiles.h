#pragma once
// Private to the pipeline: what a lidar run writes (configs/README.md,
// `lidar`): waveforms.npy (channels, azimuths, T), range and intensity
// images (npy, EXR, PNG), beam_directions.npy, points.ply and points.pcd,
// the sensors' files on the waveforms, lidar.json.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/config/RunConfig.h"
#include "tofsim/lidar/DirectWaveforms.h"
#include "tofsim/lidar/LidarReturns.h"
#include "tofsim/pipeline/Progress.h"

namespace tofsim::pipeline {

struct LidarFrame {
  const lidar::LidarWaveforms* waveforms = nullptr;
  const lidar::LidarReturns* returns = nullptr;
  double seconds = 0.0;  ///< the waveforms' render
  int threads = 1;
  /// With a scattering medium: per point of `returns`, 1 where it is the
  /// medium's (a false return: BeamBackscatter.h); nullptr without one.
  const std::vector<uint8_t>* fogReturns = nullptr;
};

/// Whether the run adds a scattering medium's backscatter to the beams'
/// waveforms (BeamBackscatter.h): with a scattering medium, every scan (a
/// zone scan's flood along each zone's receiver rays).
bool hasBeamBackscatter(const config::RunConfig& config);

/// Writes the frame's files into `dir`; returns their names (relative). lidar.json
/// lists config.effective.yaml, which the run writes next (RunFolder::finish).
std::vector<std::string> writeLidarFiles(const config::RunConfig& config, const LidarFrame& frame,
                                         const std::filesystem::path& dir,
                                         const Progress& progress);

}  // namespace tofsim::pipeline
