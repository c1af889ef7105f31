#include "tofsim/lidar/DirectWaveforms.h"

#include <cmath>

#include "tofsim/ir/HitVertex.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/util/ParallelFor.h"

namespace tofsim::lidar {

WaveformLoss addBeamWaveform(const LidarSpec& spec, const std::vector<BeamRay>& rays,
                             const WaveformScene& scene, const TimeAxis& axis, int32_t ring,
                             int32_t azimuth, float* waveform) {
  const BeamFrame frame = beamFrame(beamDirection(spec, ring, azimuth), spec.up_world);
  const double legs = axis.camera_unwarp ? 1.0 : 2.0;
  const double eta = axis.index_of_refraction;
  const double start_m = axis.start_m();
  const double width_m = axis.bin_width_m();
  const bool medium = scene.medium.present();
  const glm::vec3 sigmaT = scene.medium.sigmaT();
  WaveformLoss lost;
  for (const BeamRay& ray : rays) {
    const glm::vec3 d = rayDirection(frame, ray.offset_rad);
    const std::optional<rays::SurfaceHit> hit = scene.rays->intersect(spec.position_world, d);
    if (!hit || !(hit->distance_m > 0.0f)) continue;
    const physics::ScatterVertex v = ir::hitVertex(*hit, scene.materials);
    const glm::vec3 back = -d;
    const float cosine = glm::dot(hit->normal_world, back);
    if (!(cosine > 0.0f)) continue;
    glm::vec3 f = physics::scatter(v, hit->normal_world, back, back).f;
    // Both legs through the medium that fills the scene.
    if (medium) f *= physics::mediumTransmittance(sigmaT, 2.0f * hit->distance_m);
    const double r = hit->distance_m;
    const double value = spec.power_W * ray.share * ((double(f.r) + f.g + f.b) / 3.0) * cosine /
                         (r * r);
    const double bin = std::floor((legs * eta * r - start_m) / width_m);
    if (bin < 0.0) {
      lost.before += value;
    } else if (bin >= axis.bins) {
      lost.after += value;
    } else {
      waveform[static_cast<std::size_t>(bin)] += static_cast<float>(value);
    }
  }
  return lost;
}

LidarWaveforms renderDirectWaveforms(const LidarSpec& spec, const WaveformScene& scene,
                                     const TimeAxis& axis, int threads) {
  const int32_t channels = spec.channels();
  const int32_t azimuths = spec.azimuths();
  LidarWaveforms out{TransientVolume(azimuths, channels, axis, {"intensity"}), {}};
  const std::vector<BeamRay> rays = beamRays(spec.beam_rays, spec.divergence_rad, spec.profile);
  const auto beams = static_cast<std::size_t>(channels) * static_cast<std::size_t>(azimuths);
  constexpr std::size_t kBlock = 256;
  std::vector<WaveformLoss> lost((beams + kBlock - 1) / kBlock);
  float* data = out.volume.data();
  const std::size_t stride = out.volume.pixelStride();
  parallelForBlocks(beams, kBlock, resolveThreads(threads), [&](std::size_t begin, std::size_t end) {
    WaveformLoss& l = lost[begin / kBlock];
    for (std::size_t b = begin; b < end; ++b) {
      const auto ring = static_cast<int32_t>(b / static_cast<std::size_t>(azimuths));
      const auto azimuth = static_cast<int32_t>(b % static_cast<std::size_t>(azimuths));
      const WaveformLoss beam =
          addBeamWaveform(spec, rays, scene, axis, ring, azimuth, data + b * stride);
      l.before += beam.before;
      l.after += beam.after;
    }
  });
  for (const WaveformLoss& l : lost) {  // in block order: the same sum for any thread count
    out.lost.before += l.before;
    out.lost.after += l.after;
  }
  return out;
}

}  // namespace tofsim::lidar
