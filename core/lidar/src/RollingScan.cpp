#include "tofsim/lidar/RollingScan.h"

#include <algorithm>
#include <stdexcept>

#include "WaveformBlocks.h"
#include "tofsim/lidar/MultipathWaveforms.h"
#include "tofsim/util/ParallelFor.h"

namespace tofsim::lidar {

double firingOffset_s(const LidarSpec& spec, int32_t azimuth, double rotation_rate_Hz) {
  return (spec.azimuthOf_deg(azimuth) - spec.azimuth_start_deg) / 360.0 / rotation_rate_Hz;
}

double beamFiringOffset_s(const LidarSpec& spec, int32_t ring, int32_t azimuth, double rate_Hz) {
  switch (spec.scan) {
    case ScanPattern::Spinning:
      return firingOffset_s(spec, azimuth, rate_Hz);
    case ScanPattern::Raster: {
      const double rows = spec.grid.rows, columns = spec.grid.columns;
      return ((rows - 1.0 - ring) * columns + azimuth) / (rows * columns * rate_Hz);
    }
    case ScanPattern::Zones:
      break;
  }
  return 0.0;
}

std::vector<FiringGroup> firingGroups(const LidarSpec& spec, double rate_Hz) {
  const int32_t channels = spec.channels();
  const int32_t azimuths = spec.azimuths();
  const auto beamOf = [&](int32_t ring, int32_t a) {
    return static_cast<std::size_t>(ring) * static_cast<std::size_t>(azimuths) +
           static_cast<std::size_t>(a);
  };
  std::vector<FiringGroup> groups;
  if (spec.scan == ScanPattern::Raster) {  // top row first, each left to right
    for (int32_t ring = channels - 1; ring >= 0; --ring) {
      for (int32_t a = 0; a < azimuths; ++a) {
        groups.push_back({beamFiringOffset_s(spec, ring, a, rate_Hz), {beamOf(ring, a)}});
      }
    }
    return groups;
  }
  const bool spinning = spec.scan == ScanPattern::Spinning;
  for (int32_t a = 0; a < (spinning ? azimuths : 1); ++a) {
    FiringGroup g{spinning ? firingOffset_s(spec, a, rate_Hz) : 0.0, {}};
    for (int32_t ring = 0; ring < channels; ++ring) {
      if (spinning) {
        g.beams.push_back(beamOf(ring, a));
      } else {  // the flood: every zone at once
        for (int32_t z = 0; z < azimuths; ++z) g.beams.push_back(beamOf(ring, z));
      }
    }
    groups.push_back(std::move(g));
  }
  return groups;
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
                                      const TimeAxis& axis, double start_s, double rate_Hz,
                                      int threads, bool keepVolume) {
  if (spec.scan == ScanPattern::Zones) {
    throw std::invalid_argument("a zone scan's flood is one exposure: it has no rolling scan");
  }
  const int32_t channels = spec.channels();
  const int32_t azimuths = spec.azimuths();
  const ReceiverRays rays(beamRays(spec.beam_rays, spec.divergence_rad, spec.profile));
  const auto beams = static_cast<std::size_t>(channels) * static_cast<std::size_t>(azimuths);
  const int workers = resolveThreads(threads);
  std::vector<BeamLight> light(beams);
  for (const FiringGroup& group : firingGroups(spec, rate_Hz)) {
    const WaveformScene& scene = sceneAt(start_s + group.offset_s);
    parallelFor(group.beams.size(), workers, [&](std::size_t i) {
      const std::size_t b = group.beams[i];
      BeamLight& beam = light[b];
      std::vector<WaveformBin> rayBins;
      beamRayBins(spec, rays, scene, axis, static_cast<int32_t>(b / azimuths),
                  static_cast<int32_t>(b % azimuths), rayBins, beam.lost);
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

namespace {

// Per-beam losses summed as a still frame's pass sums them: per block of
// `block` beams in order, then the blocks in order.
void addLossInBlocks(const std::vector<WaveformLoss>& perBeam, std::size_t block,
                     WaveformLoss& lost) {
  for (std::size_t begin = 0; begin < perBeam.size(); begin += block) {
    WaveformLoss l;
    for (std::size_t b = begin; b < std::min(perBeam.size(), begin + block); ++b) {
      l.before += perBeam[b].before;
      l.after += perBeam[b].after;
    }
    lost.before += l.before;
    lost.after += l.after;
  }
}

}  // namespace

BeamSurfaces addRollingLight(const LidarSpec& spec, const MultipathSettings& multipath,
                             const SceneAtTime& sceneAt, const TimeAxis& axis, double start_s,
                             double rate_Hz, int threads, LidarWaveforms& waveforms) {
  const std::vector<FiringGroup> groups = firingGroups(spec, rate_Hz);
  if (groups.empty()) return {};
  const capture::Medium medium = sceneAt(start_s + groups.front().offset_s).medium;
  if (!multipath.enabled() && !medium.scatters()) return {};
  if (waveforms.volume.size() == 0) {
    throw std::invalid_argument("addRollingLight adds to the dense volume: render with keepVolume");
  }
  const int32_t azimuths = spec.azimuths();
  const auto beams = static_cast<std::size_t>(spec.channels()) * static_cast<std::size_t>(azimuths);
  std::optional<BackscatterLight> backscatter;
  BeamSurfaces surfaces;
  if (medium.scatters()) {
    backscatter.emplace(spec, medium, axis);
    surfaces.raysPerBeam = backscatter->raysPerBeam();
    surfaces.bins.assign(beams * static_cast<std::size_t>(surfaces.raysPerBeam), -1);
  }
  const MultipathRays rays = multipath.enabled() ? multipathRays(spec, multipath) : MultipathRays{};
  std::vector<WaveformLoss> multipathLost(beams), backscatterLost(beams);
  float* data = waveforms.volume.data();
  const std::size_t stride = waveforms.volume.pixelStride();
  const int workers = resolveThreads(threads);
  for (const FiringGroup& group : groups) {
    const WaveformScene& scene = sceneAt(start_s + group.offset_s);
    parallelFor(group.beams.size(), workers, [&](std::size_t i) {
      const std::size_t b = group.beams[i];
      const auto ring = static_cast<int32_t>(b / static_cast<std::size_t>(azimuths));
      const auto a = static_cast<int32_t>(b % static_cast<std::size_t>(azimuths));
      float* waveform = data + b * stride;
      // As a still frame: the multipath first, then the backscatter (the same
      // float additions in the same order per beam).
      if (multipath.enabled()) {
        multipathLost[b] = addBeamMultipath(spec, multipath, rays, scene, axis,
                                            beamDirection(spec, ring, a), b, waveform);
      }
      if (backscatter) {
        backscatterLost[b] = backscatter->addBeam(
            *scene.rays, ring, a, waveform,
            surfaces.bins.data() + b * static_cast<std::size_t>(surfaces.raysPerBeam));
      }
    });
  }
  if (multipath.enabled()) addLossInBlocks(multipathLost, kMultipathBlock, waveforms.lost);
  if (backscatter) addLossInBlocks(backscatterLost, kBackscatterBlock, waveforms.lost);
  return surfaces;
}

}  // namespace tofsim::lidar
