#include "tofsim/lidar/LidarReturns.h"

#include "tofsim/lidar/BeamPattern.h"
#include "tofsim/lidar/Echoes.h"
#include "tofsim/lidar/RollingScan.h"
#include "tofsim/lidar/ScanGrid.h"
#include "tofsim/util/ParallelFor.h"

namespace tofsim::lidar {

namespace {

// Beam (ring, a)'s kept returns as points into `out`.
void addBeamPoints(const LidarSpec& spec, int32_t ring, int32_t a, const std::vector<Echo>& kept,
                   double rotation_rate_Hz, LidarReturns& out) {
  ++out.beamsWithReturns;
  const glm::vec3 d = beamDirection(spec, ring, a);
  // A beam's firing time in the scan (RollingScan.h: a zone scan's flood at
  // the frame's start); a grid scan's points' azimuth is the column's angle.
  const double fired_s = beamFiringOffset_s(spec, ring, a, rotation_rate_Hz);
  const double azimuth_deg = spec.gridScan() ? gridAzimuth_deg(spec, a) : spec.azimuthOf_deg(a);
  for (std::size_t k = 0; k < kept.size(); ++k) {
    LidarPoint p;
    const glm::vec3 x = spec.position_world + static_cast<float>(kept[k].range_m) * d;
    p.x = x.x;
    p.y = x.y;
    p.z = x.z;
    p.intensity = static_cast<float>(kept[k].intensity);
    p.ring = static_cast<uint16_t>(ring);
    p.azimuth_deg = static_cast<float>(azimuth_deg);
    p.return_index = static_cast<uint8_t>(k);
    p.time_offset_s = static_cast<float>(fired_s);
    out.points.push_back(p);
  }
}

// Every beam's returns, its echoes from echoesOf(ring, a), on `threads`
// threads over fixed blocks of beams whose points are joined in beam order.
template <typename EchoesOf>
LidarReturns returnsOf(const LidarSpec& spec, double rotation_rate_Hz, int threads,
                       const EchoesOf& echoesOf) {
  const int32_t channels = spec.channels();
  const int32_t azimuths = spec.azimuths();
  LidarReturns out{Image(azimuths, channels, 1), Image(azimuths, channels, 1), {}, 0};
  const auto beams = static_cast<std::size_t>(channels) * static_cast<std::size_t>(azimuths);
  constexpr std::size_t kBlock = 1024;
  struct alignas(64) Block {
    LidarReturns part;  // its points and count; the images are the frame's
  };
  std::vector<Block> blocks((beams + kBlock - 1) / kBlock);
  parallelForBlocks(beams, kBlock, threads, [&](std::size_t begin, std::size_t end) {
    LidarReturns& part = blocks[begin / kBlock].part;
    for (std::size_t b = begin; b < end; ++b) {
      const auto ring = static_cast<int32_t>(b / static_cast<std::size_t>(azimuths));
      const auto a = static_cast<int32_t>(b % static_cast<std::size_t>(azimuths));
      // Each beam's own pixel of the frame's images; its points into the block's.
      const std::vector<Echo> kept = selectReturns(echoesOf(ring, a), spec.returns);
      if (kept.empty()) continue;
      out.range_m.at(ring, a, 0) = static_cast<float>(kept[0].range_m);
      out.intensity.at(ring, a, 0) = static_cast<float>(kept[0].intensity);
      addBeamPoints(spec, ring, a, kept, rotation_rate_Hz, part);
    }
  });
  for (Block& block : blocks) {
    out.beamsWithReturns += block.part.beamsWithReturns;
    out.points.insert(out.points.end(), block.part.points.begin(), block.part.points.end());
  }
  return out;
}

}  // namespace

LidarReturns lidarReturns(const LidarSpec& spec, const TransientVolume& waveforms,
                          double rotation_rate_Hz) {
  return returnsOf(spec, rotation_rate_Hz, 1, [&](int32_t ring, int32_t a) {
    const float* w = waveforms.data() + waveforms.index(ring, a, 0, 0);
    return findEchoes(w, waveforms.axis(), spec.returns);
  });
}

LidarReturns lidarReturns(const LidarSpec& spec, const SparseWaveforms& waveforms,
                          const TimeAxis& axis, double rotation_rate_Hz, int threads) {
  const auto azimuths = static_cast<std::size_t>(spec.azimuths());
  return returnsOf(spec, rotation_rate_Hz, threads, [&](int32_t ring, int32_t a) {
    const std::size_t beam = static_cast<std::size_t>(ring) * azimuths + a;
    return findEchoes(waveforms.begin(beam), waveforms.count(beam), axis, spec.returns);
  });
}

LidarReturns lidarReturns(const LidarSpec& spec, const LidarWaveforms& waveforms,
                          double rotation_rate_Hz, int threads) {
  if (waveforms.volume.size() > 0) return lidarReturns(spec, waveforms.volume, rotation_rate_Hz);
  return lidarReturns(spec, waveforms.sparse, waveforms.axis, rotation_rate_Hz, threads);
}

}  // namespace tofsim::lidar
