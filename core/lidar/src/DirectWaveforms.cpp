#include "tofsim/lidar/DirectWaveforms.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <utility>

#include "tofsim/ir/HitVertex.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/util/ParallelFor.h"
#include "WaveformBlocks.h"

namespace tofsim::lidar {

namespace {

// Where a ray's light lands on the axis: the bin of its optical path.
struct AxisMap {
  explicit AxisMap(const TimeAxis& axis)
      : legs(axis.camera_unwarp ? 1.0 : 2.0),
        eta(axis.index_of_refraction),
        start_m(axis.start_m()),
        width_m(axis.bin_width_m()),
        bins(axis.bins) {}
  double legs, eta, start_m, width_m;
  int32_t bins;
};

// The irradiance ray `d` brings back from `hit` (W m^-2 per pulse), 0 for
// light the surface does not send back.
double rayValue(const LidarSpec& spec, float share, const rays::SurfaceHit& hit,
                const glm::vec3& d, const WaveformScene& scene) {
  if (!(hit.distance_m > 0.0f)) return -1.0;
  const physics::ScatterVertex v = ir::hitVertex(hit, scene.materials);
  const glm::vec3 back = -d;
  const float cosine = glm::dot(hit.normal_world, back);
  if (!(cosine > 0.0f)) return -1.0;
  glm::vec3 f = physics::scatter(v, hit.normal_world, back, back).f;
  // Both legs through the medium that fills the scene.
  if (scene.medium.present()) {
    f *= physics::mediumTransmittance(scene.medium.sigmaT(), 2.0f * hit.distance_m);
  }
  const double r = hit.distance_m;
  return spec.power_W * share * ((double(f.r) + f.g + f.b) / 3.0) * cosine / (r * r);
}

}  // namespace

ReceiverRays::ReceiverRays(std::vector<BeamRay> beamRays) : rays(std::move(beamRays)) {
  for (const BeamRay& r : rays) tilts.push_back(rayTilt(r.offset_rad));
}

namespace {

// Ray `d`'s light off `hit` into its bin of `out`, or into `lost` off the axis.
void addRayLight(const LidarSpec& spec, float share, const std::optional<rays::SurfaceHit>& hit,
                 const glm::vec3& d, const WaveformScene& scene, const AxisMap& map,
                 std::vector<WaveformBin>& out, WaveformLoss& lost) {
  if (!hit) return;
  const double value = rayValue(spec, share, *hit, d, scene);
  if (value < 0.0) return;
  const double r = hit->distance_m;
  const double bin = std::floor((map.legs * map.eta * r - map.start_m) / map.width_m);
  if (bin < 0.0) {
    lost.before += value;
  } else if (bin >= map.bins) {
    lost.after += value;
  } else {
    out.push_back({static_cast<int32_t>(bin), static_cast<float>(value)});
  }
}

// Traces the receiver rays of beams i in [0, count) (beamAt(i): its ring and
// azimuth) as packets of kPacketSize rays from the lidar's position (each
// one bundle: RayScene::intersectPacket), filled across beams where a beam
// has fewer rays (one origin, neighbouring directions: coherent), and calls
// light(i, ray, hit, direction) for every ray, in beam then ray order.
template <typename BeamAt, typename Light>
void tracePacked(const LidarSpec& spec, const ReceiverRays& receiver, const WaveformScene& scene,
                 std::size_t count, const BeamAt& beamAt, const Light& light) {
  constexpr int kPacket = rays::RayScene::kPacketSize;
  std::array<glm::vec3, kPacket> d;
  std::array<std::optional<rays::SurfaceHit>, kPacket> hits;
  std::array<std::size_t, kPacket> beamOf, rayOf;
  int n = 0;
  const auto flush = [&] {
    scene.rays->intersectPacket(spec.position_world, d.data(), n, hits.data());
    for (int i = 0; i < n; ++i) light(beamOf[i], rayOf[i], hits[i], d[i]);
    n = 0;
  };
  for (std::size_t i = 0; i < count; ++i) {
    const auto [ring, azimuth] = beamAt(i);
    const BeamFrame frame = beamFrame(beamDirection(spec, ring, azimuth), spec.up_world);
    for (std::size_t r = 0; r < receiver.rays.size(); ++r) {
      d[n] = rayDirection(frame, receiver.tilts[r]);
      beamOf[n] = i;
      rayOf[n] = r;
      if (++n == kPacket) flush();
    }
  }
  if (n > 0) flush();
}

}  // namespace

void beamRayBins(const LidarSpec& spec, const ReceiverRays& receiver, const WaveformScene& scene,
                 const TimeAxis& axis, int32_t ring, int32_t azimuth,
                 std::vector<WaveformBin>& out, WaveformLoss& lost) {
  const AxisMap map(axis);
  tracePacked(
      spec, receiver, scene, 1, [&](std::size_t) { return std::pair(ring, azimuth); },
      [&](std::size_t, std::size_t r, const std::optional<rays::SurfaceHit>& hit,
          const glm::vec3& d) {
        addRayLight(spec, receiver.rays[r].share, hit, d, scene, map, out, lost);
      });
}

WaveformLoss addBeamWaveform(const LidarSpec& spec, const std::vector<BeamRay>& rays,
                             const WaveformScene& scene, const TimeAxis& axis, int32_t ring,
                             int32_t azimuth, float* waveform) {
  std::vector<WaveformBin> bins;
  WaveformLoss lost;
  beamRayBins(spec, ReceiverRays(rays), scene, axis, ring, azimuth, bins, lost);
  for (const WaveformBin& b : bins) waveform[b.bin] += b.value;
  return lost;
}

void LidarWaveforms::beamWaveform(std::size_t beam, float* out) const {
  if (volume.size() > 0) {
    const float* w = volume.data() + beam * volume.pixelStride();
    std::copy_n(w, volume.bins(), out);
  } else {
    sparse.expand(beam, axis.bins, out);
  }
}

LidarWaveforms renderDirectWaveforms(const LidarSpec& spec, const WaveformScene& scene,
                                     const TimeAxis& axis, int threads, bool keepVolume) {
  const int32_t channels = spec.channels();
  const int32_t azimuths = spec.azimuths();
  const ReceiverRays rays(beamRays(spec.beam_rays, spec.divergence_rad, spec.profile));
  const auto beams = static_cast<std::size_t>(channels) * static_cast<std::size_t>(azimuths);
  std::vector<BlockBins> blocks((beams + kBeamBlock - 1) / kBeamBlock);
  const int workers = resolveThreads(threads);
  parallelForBlocks(beams, kBeamBlock, workers, [&](std::size_t begin, std::size_t end) {
    BlockBins& block = blocks[begin / kBeamBlock];
    block.bins.reserve((end - begin) * rays.rays.size());
    block.counts.reserve(end - begin);
    const AxisMap map(axis);
    std::vector<WaveformBin> rayBins;  // the current beam's rays' bins, in ray order
    WaveformLoss lost, beamLost;       // summed here, stored once
    std::size_t current = 0;           // of the block's beams
    const auto finishBeam = [&] {
      lost.before += beamLost.before;
      lost.after += beamLost.after;
      const std::size_t before = block.bins.size();
      appendBeamBins(rayBins, block.bins);
      block.counts.push_back(static_cast<uint32_t>(block.bins.size() - before));
      rayBins.clear();
      beamLost = {};
      ++current;
    };
    tracePacked(
        spec, rays, scene, end - begin,
        [&](std::size_t i) {
          const std::size_t b = begin + i;
          return std::pair(static_cast<int32_t>(b / static_cast<std::size_t>(azimuths)),
                           static_cast<int32_t>(b % static_cast<std::size_t>(azimuths)));
        },
        [&](std::size_t i, std::size_t r, const std::optional<rays::SurfaceHit>& hit,
            const glm::vec3& d) {
          while (current < i) finishBeam();
          addRayLight(spec, rays.rays[r].share, hit, d, scene, map, rayBins, beamLost);
        });
    while (current < end - begin) finishBeam();
    block.lost = lost;
  });
  return gatherWaveforms(blocks, channels, azimuths, axis, workers, keepVolume);
}

LidarWaveforms gatherWaveforms(const std::vector<BlockBins>& blocks, int32_t channels,
                               int32_t azimuths, const TimeAxis& axis, int workers,
                               bool keepVolume) {
  const auto beams = static_cast<std::size_t>(channels) * static_cast<std::size_t>(azimuths);
  LidarWaveforms out;
  out.axis = axis;
  if (keepVolume) out.volume = TransientVolume(azimuths, channels, axis, {"intensity"});
  SparseWaveforms& sparse = out.sparse;
  sparse.offsets.reserve(beams + 1);
  std::size_t total = 0;
  for (const BlockBins& block : blocks) total += block.bins.size();
  sparse.bins.reserve(total);
  for (const BlockBins& block : blocks) {  // in block order: the same sum for any thread count
    out.lost.before += block.lost.before;
    out.lost.after += block.lost.after;
    sparse.bins.insert(sparse.bins.end(), block.bins.begin(), block.bins.end());
    for (uint32_t c : block.counts) sparse.offsets.push_back(sparse.offsets.back() + c);
  }
  if (keepVolume) {  // the volume is zero: each block writes its beams' bins alone
    float* data = out.volume.data();
    const std::size_t stride = out.volume.pixelStride();
    parallelForBlocks(beams, kBeamBlock, workers, [&](std::size_t begin, std::size_t end) {
      for (std::size_t b = begin; b < end; ++b) {
        const WaveformBin* bin = sparse.begin(b);
        for (std::size_t i = 0, n = sparse.count(b); i < n; ++i) {
          data[b * stride + bin[i].bin] = bin[i].value;
        }
      }
    });
  }
  return out;
}

}  // namespace tofsim::lidar
