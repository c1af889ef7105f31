#include "tofsim/lidar/LidarReturns.h"

#include "tofsim/lidar/BeamPattern.h"
#include "tofsim/lidar/Echoes.h"
#include "tofsim/lidar/ScanGrid.h"

namespace tofsim::lidar {

LidarReturns lidarReturns(const LidarSpec& spec, const TransientVolume& waveforms,
                          double rotation_rate_Hz) {
  const int32_t channels = spec.channels();
  const int32_t azimuths = spec.azimuths();
  LidarReturns out{Image(azimuths, channels, 1), Image(azimuths, channels, 1), {}, 0};
  for (int32_t ring = 0; ring < channels; ++ring) {
    for (int32_t a = 0; a < azimuths; ++a) {
      const float* w = waveforms.data() + waveforms.index(ring, a, 0, 0);
      const std::vector<Echo> kept =
          selectReturns(findEchoes(w, waveforms.axis(), spec.returns), spec.returns);
      if (kept.empty()) continue;
      ++out.beamsWithReturns;
      out.range_m.at(ring, a, 0) = static_cast<float>(kept[0].range_m);
      out.intensity.at(ring, a, 0) = static_cast<float>(kept[0].intensity);
      const glm::vec3 d = beamDirection(spec, ring, a);
      // A grid scan's beams all fire at the frame's start (a flash, a
      // multizone sensor); its points' azimuth is the column's angle.
      const double fired_s = spec.gridScan() ? 0.0
                                             : (spec.azimuthOf_deg(a) - spec.azimuth_start_deg) /
                                                   360.0 / rotation_rate_Hz;
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
  }
  return out;
}

}  // namespace tofsim::lidar
