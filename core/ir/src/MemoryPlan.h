#pragma once
// How the memory budget is spent: what the backend holds for the whole render
// first, then VPL batches whose visibility maps get up to half of the rest,
// then volume segments (Algorithm 1 of Pan et al. 2019).

#include <cstddef>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/ir/IrBackend.h"
#include "tofsim/capture/SegmentPlan.h"

namespace tofsim::ir {

struct MemoryPlan {
  capture::SegmentPlan segments;
  std::size_t vplsPerBatch = 0;  ///< 0 without VPLs
  std::size_t batchCount = 0;    ///< 0 without VPLs
  std::size_t peakBytes = 0;     ///< fixed + one batch + one segment
};

/// `responseBuffers`: the difference buffers per pixel the delayed response
/// classes add (physics::responseBuffers of the table the backend was given;
/// 0 without delays). Throws InputError naming render.memory_budget (or the
/// ISM resolution) when the budget cannot hold what is fixed, one VPL's map
/// or one pixel.
MemoryPlan planMemory(const capture::RenderJob& job, const DeviceLimits& limits,
                      std::size_t fixedBytes, std::size_t vplCount,
                      std::size_t visibilityBytesPerVpl, std::size_t responseBuffers);

}  // namespace tofsim::ir
