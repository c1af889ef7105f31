#include "tofsim/lidar/LidarReturns.h"

#include "tofsim/lidar/BeamPattern.h"
#include "tofsim/lidar/Echoes.h"
#include "tofsim/lidar/RollingScan.h"

namespace tofsim::lidar {

namespace {

// Beam (ring, a)'s returns of its echoes into `out`.
void addBeamReturns(const LidarSpec& spec, int32_t ring, int32_t a, const std::vector<Echo>& echoes,
                    double rotation_rate_Hz, LidarReturns& out) {
  const std::vector<Echo> kept = selectReturns(echoes, spec.returns);
  if (kept.empty()) return;
  ++out.beamsWithReturns;
  out.range_m.at(ring, a, 0) = static_cast<float>(kept[0].range_m);
  out.intensity.at(ring, a, 0) = static_cast<float>(kept[0].intensity);
  const glm::vec3 d = beamDirection(spec, ring, a);
  const double fired_s = firingOffset_s(spec, a, rotation_rate_Hz);
  for (std::size_t k = 0; k < kept.size(); ++k) {
    LidarPoint p;
    const glm::vec3 x = spec.position_world + static_cast<float>(kept[k].range_m) * d;
    p.x = x.x;
    p.y = x.y;
    p.z = x.z;
    p.intensity = static_cast<float>(kept[k].intensity);
    p.ring = static_cast<uint16_t>(ring);
    p.azimuth_deg = static_cast<float>(spec.azimuthOf_deg(a));
    p.return_index = static_cast<uint8_t>(k);
    p.time_offset_s = static_cast<float>(fired_s);
    out.points.push_back(p);
  }
}

// Every beam's returns, its echoes from echoesOf(ring, a).
template <typename EchoesOf>
LidarReturns returnsOf(const LidarSpec& spec, double rotation_rate_Hz, const EchoesOf& echoesOf) {
  const int32_t channels = spec.channels();
  const int32_t azimuths = spec.azimuths();
  LidarReturns out{Image(azimuths, channels, 1), Image(azimuths, channels, 1), {}, 0};
  for (int32_t ring = 0; ring < channels; ++ring) {
    for (int32_t a = 0; a < azimuths; ++a) {
      addBeamReturns(spec, ring, a, echoesOf(ring, a), rotation_rate_Hz, out);
    }
  }
  return out;
}

}  // namespace

LidarReturns lidarReturns(const LidarSpec& spec, const TransientVolume& waveforms,
                          double rotation_rate_Hz) {
  return returnsOf(spec, rotation_rate_Hz, [&](int32_t ring, int32_t a) {
    const float* w = waveforms.data() + waveforms.index(ring, a, 0, 0);
    return findEchoes(w, waveforms.axis(), spec.returns);
  });
}

LidarReturns lidarReturns(const LidarSpec& spec, const SparseWaveforms& waveforms,
                          const TimeAxis& axis, double rotation_rate_Hz) {
  const auto azimuths = static_cast<std::size_t>(spec.azimuths());
  return returnsOf(spec, rotation_rate_Hz, [&](int32_t ring, int32_t a) {
    const std::size_t beam = static_cast<std::size_t>(ring) * azimuths + a;
    return findEchoes(waveforms.begin(beam), waveforms.count(beam), axis, spec.returns);
  });
}

LidarReturns lidarReturns(const LidarSpec& spec, const LidarWaveforms& waveforms,
                          double rotation_rate_Hz) {
  if (waveforms.volume.size() > 0) return lidarReturns(spec, waveforms.volume, rotation_rate_Hz);
  return lidarReturns(spec, waveforms.sparse, waveforms.axis, rotation_rate_Hz);
}

}  // namespace tofsim::lidar
