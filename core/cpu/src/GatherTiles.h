#pragma once
// Private to the CPU backend: how its gathers cut a segment's pixels into
// tasks (CpuBackend.cpp's indirect gathers, CpuDirectGather.cpp's direct).

#include <cstddef>

#include "tofsim/capture/SegmentSink.h"

namespace tofsim::cpu {

inline constexpr int kChannels = capture::kChannels;
inline constexpr std::size_t kTilePixels = 16;  // pixels per task: their histograms stay in L2

}  // namespace tofsim::cpu
