#include "tofsim/lidar/ZoneWaveforms.h"

#include "tofsim/lidar/ScanGrid.h"
#include "tofsim/util/ParallelFor.h"

namespace tofsim::lidar {

LidarWaveforms renderZoneWaveforms(const LidarSpec& spec, const WaveformScene& scene,
                                   const TimeAxis& axis, int threads) {
  const int32_t rows = spec.channels();
  const int32_t columns = spec.azimuths();
  LidarWaveforms out;
  out.volume = TransientVolume(columns, rows, axis, {"intensity"});
  out.axis = axis;
  const double field_sr = fieldSolidAngle_sr(spec);
  const auto zones = static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns);
  std::vector<WaveformLoss> lost(zones);
  float* data = out.volume.data();
  const std::size_t stride = out.volume.pixelStride();
  parallelForBlocks(zones, 1, resolveThreads(threads), [&](std::size_t begin, std::size_t end) {
    for (std::size_t z = begin; z < end; ++z) {
      const auto row = static_cast<int32_t>(z / static_cast<std::size_t>(columns));
      const auto column = static_cast<int32_t>(z % static_cast<std::size_t>(columns));
      lost[z] = addBeamWaveform(spec, zoneRays(spec, row, column, field_sr), scene, axis, row,
                                column, data + z * stride);
    }
  });
  for (const WaveformLoss& l : lost) {  // in zone order: the same sum for any thread count
    out.lost.before += l.before;
    out.lost.after += l.after;
  }
  return out;
}

}  // namespace tofsim::lidar
