#include "tofsim/lidar/RollingScan.h"

#include "WaveformBlocks.h"
#include "tofsim/util/ParallelFor.h"

namespace tofsim::lidar {

double firingOffset_s(const LidarSpec& spec, int32_t azimuth, double rotation_rate_Hz) {
  return (spec.azimuthOf_deg(azimuth) - spec.azimuth_start_deg) / 360.0 / rotation_rate_Hz;
}

AnimatedWaveformScene::AnimatedWaveformScene(const scene::AnimatedScene& animated,
                                             scene::Scene scene,
                                             std::vector<physics::ScatterVertex> materials,
                                             const capture::Medium& medium, int threads)
    : animated_(animated), scene_(std::move(scene)), threads_(threads) {
  traced_.materials = std::move(materials);
  traced_.medium = medium;
}

const WaveformScene& AnimatedWaveformScene::at(double t_s) {
  if (time_s_ == t_s) return traced_;
  animated_.updateScene(scene_, t_s);
  if (!rays_ || !rays_->updateMeshes(animated_.movingMeshes())) {
    rays_.reset();  // it holds the scene's meshes: gone before the new one
    rays_.emplace(scene_, threads_);
  }
  traced_.rays = &*rays_;
  time_s_ = t_s;
  return traced_;
}

namespace {

struct alignas(64) BeamLight {  // a line each: a column's rings fill theirs on several threads
  std::vector<WaveformBin> bins;
  WaveformLoss lost;
};

}  // namespace

LidarWaveforms renderRollingWaveforms(const LidarSpec& spec, const SceneAtTime& sceneAt,
                                      const TimeAxis& axis, double start_s,
                                      double rotation_rate_Hz, int threads, bool keepVolume) {
  const int32_t channels = spec.channels();
  const int32_t azimuths = spec.azimuths();
  const ReceiverRays rays(beamRays(spec.beam_rays, spec.divergence_rad, spec.profile));
  const auto beams = static_cast<std::size_t>(channels) * static_cast<std::size_t>(azimuths);
  const int workers = resolveThreads(threads);
  std::vector<BeamLight> light(beams);
  for (int32_t a = 0; a < azimuths; ++a) {
    const WaveformScene& scene = sceneAt(start_s + firingOffset_s(spec, a, rotation_rate_Hz));
    parallelFor(static_cast<std::size_t>(channels), workers, [&](std::size_t ring) {
      BeamLight& beam = light[ring * static_cast<std::size_t>(azimuths) + a];
      std::vector<WaveformBin> rayBins;
      beamRayBins(spec, rays, scene, axis, static_cast<int32_t>(ring), a, rayBins, beam.lost);
      appendBeamBins(rayBins, beam.bins);
    });
  }
  // The beams in renderDirectWaveforms' blocks, their loss summed as it sums it.
  std::vector<BlockBins> blocks((beams + kBeamBlock - 1) / kBeamBlock);
  for (std::size_t b = 0; b < beams; ++b) {
    BlockBins& block = blocks[b / kBeamBlock];
    block.bins.insert(block.bins.end(), light[b].bins.begin(), light[b].bins.end());
    block.counts.push_back(static_cast<uint32_t>(light[b].bins.size()));
    block.lost.before += light[b].lost.before;
    block.lost.after += light[b].lost.after;
    light[b] = {};
  }
  return gatherWaveforms(blocks, channels, azimuths, axis, workers, keepVolume);
}

}  // namespace tofsim::lidar
