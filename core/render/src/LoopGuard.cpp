#include "LoopGuard.h"

#include "tofsim/render/GlRegionLimits.h"
#include "tofsim/util/Error.h"

namespace tofsim::render {

void throwIfGuardRaised(uint32_t flags, const std::string& invocation) {
  if ((flags & kRegionCrossingsOverflow) != 0) {
    throw InputError(invocation + " followed a leg that crosses a medium region's surface more "
                     "than " + std::to_string(kGlRegionCrossings) +
                     " times (the GL shaders keep that many crossings per region and leg): use "
                     "render.backend: cpu, or a region mesh with fewer folds");
  }
  if ((flags & kLoopTripsNearLimit) != 0) {
    throw InputError(invocation +
                     " came near the GL implementation's loop-trip limit (llvmpipe: 65535), so "
                     "light could be lost; use visibility: ism or a smaller scene for exact "
                     "visibility");
  }
}

}  // namespace tofsim::render
