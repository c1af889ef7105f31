#pragma once
// Private to core/lidar: a frame's traced light in fixed blocks of beams
// (ring-major), each block's own (a cache line per block header: threads
// share none while they fill them), gathered into the frame's waveforms in
// block order, so that the bytes do not depend on the thread count.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tofsim/lidar/DirectWaveforms.h"

namespace tofsim::lidar {

constexpr std::size_t kBeamBlock = 256;

struct alignas(64) BlockBins {
  std::vector<WaveformBin> bins;  ///< the block's beams' nonzero bins, beam after beam
  std::vector<uint32_t> counts;   ///< bins per beam of the block
  WaveformLoss lost;              ///< summed over the block's beams in order
};

/// The frame's waveforms of its blocks (kBeamBlock beams each, the last
/// shorter): the sparse bins, the loss summed in block order and, with
/// keepVolume, the dense volume written a block per task on `workers`.
LidarWaveforms gatherWaveforms(const std::vector<BlockBins>& blocks, int32_t channels,
                               int32_t azimuths, const TimeAxis& axis, int workers,
                               bool keepVolume);

}  // namespace tofsim::lidar
