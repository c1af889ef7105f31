#include "tofsim/lidar/SparseWaveforms.h"

#include <algorithm>

namespace tofsim::lidar {

void SparseWaveforms::expand(std::size_t beam, int32_t binCount, float* waveform) const {
  std::fill_n(waveform, binCount, 0.0f);
  const WaveformBin* b = begin(beam);
  for (std::size_t i = 0, n = count(beam); i < n; ++i) waveform[b[i].bin] = b[i].value;
}

double SparseWaveforms::total() const {
  double sum = 0.0;
  for (const WaveformBin& b : bins) sum += b.value;
  return sum;
}

void appendBeamBins(std::vector<WaveformBin>& rays, std::vector<WaveformBin>& out) {
  // Insertion sort: a beam's few rays, mostly in order already; stable.
  for (std::size_t i = 1; i < rays.size(); ++i) {
    const WaveformBin x = rays[i];
    std::size_t j = i;
    for (; j > 0 && rays[j - 1].bin > x.bin; --j) rays[j] = rays[j - 1];
    rays[j] = x;
  }
  for (std::size_t i = 0; i < rays.size();) {
    WaveformBin sum{rays[i].bin, 0.0f};
    for (; i < rays.size() && rays[i].bin == sum.bin; ++i) sum.value += rays[i].value;
    out.push_back(sum);
  }
}

}  // namespace tofsim::lidar
