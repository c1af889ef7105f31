#pragma once
// A beam's echoes from its waveform, and the returns its mode keeps.
//
// An echo is a run of bins whose values are above returns.threshold, runs
// separated by less than returns.separation (in range) merged into one:
// its energy (`intensity`) is the sum of its bins, its time the
// energy-weighted mean of its bins' centres and its range that time's
// optical path / (eta x 2) (x 1 with time.camera_unwarp). Direct light off
// a surface lands in a bin per receiver ray, so a range is exact to half a
// bin.

#include <cstdint>
#include <vector>

#include "tofsim/lidar/LidarSpec.h"
#include "tofsim/lidar/SparseWaveforms.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::lidar {

struct Echo {
  double range_m = 0.0;
  double time_s = 0.0;     ///< arrival after the pulse left, s
  double intensity = 0.0;  ///< the echo's energy, the waveform's unit
  int32_t first_bin = 0, last_bin = 0;
};

/// The echoes of one waveform (axis.bins floats), in time order.
std::vector<Echo> findEchoes(const float* waveform, const TimeAxis& axis,
                             const ReturnSettings& returns);
/// The same of a waveform given as its nonzero bins (`count`, in bin order:
/// SparseWaveforms.h): the same echoes to the bit.
std::vector<Echo> findEchoes(const WaveformBin* bins, std::size_t count, const TimeAxis& axis,
                             const ReturnSettings& returns);

/// The returns `returns.mode` keeps of `echoes` (in time order), at most
/// returns.max, in the order the mode gives them: first; strongest; last;
/// dual: the strongest, then the last (the second strongest when the last
/// is the strongest); all: in time order. Ties go to the earlier echo.
std::vector<Echo> selectReturns(const std::vector<Echo>& echoes, const ReturnSettings& returns);

}  // namespace tofsim::lidar
