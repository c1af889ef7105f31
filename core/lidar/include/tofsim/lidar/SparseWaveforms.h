#pragma once
// A frame's waveforms as each beam's few nonzero bins: direct light lands
// in a bin per receiver ray, so a beam of 16 rays holds at most 16 of its
// 1000 bins. The returns are found on them (Echoes.h) without the dense
// (channels, azimuths, T) volume, which is made only where something reads
// it (waveforms.npy, streamed in blocks; a sensor on the waveforms).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tofsim/volume/TimeAxis.h"

namespace tofsim::lidar {

/// One nonzero bin of a beam's waveform.
struct WaveformBin {
  int32_t bin = 0;
  float value = 0.0f;
};

struct SparseWaveforms {
  /// Beam b (ring-major, then azimuth) holds bins[offsets[b] .. offsets[b + 1]),
  /// in bin order, one entry per bin (the rays' light summed in ray order,
  /// in float, as a dense waveform adds it).
  std::vector<std::size_t> offsets{0};
  std::vector<WaveformBin> bins;

  std::size_t beams() const { return offsets.size() - 1; }
  const WaveformBin* begin(std::size_t beam) const { return bins.data() + offsets[beam]; }
  std::size_t count(std::size_t beam) const { return offsets[beam + 1] - offsets[beam]; }
  /// Beam `beam`'s dense waveform into `waveform` (`bins` floats), zeros
  /// between its bins.
  void expand(std::size_t beam, int32_t binCount, float* waveform) const;
  /// The sum of every bin, in beam and bin order (a dense volume's sum in
  /// its order, to the bit).
  double total() const;
};

/// Sorts `rays` (a beam's rays' (bin, value), in ray order) by bin, stably,
/// and appends one entry per bin to `out`, the values of a bin summed in ray
/// order from 0 in float: the dense waveform's bins to the bit.
void appendBeamBins(std::vector<WaveformBin>& rays, std::vector<WaveformBin>& out);

}  // namespace tofsim::lidar
