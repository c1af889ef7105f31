#pragma once
// The segment loop every renderer shares: buffers for one segment's named
// components, filled segment by segment in order, the light seen straight by
// the camera added to the direct component, then handed to the sink. A
// renderer only says how to fill one segment.

#include <cstddef>
#include <functional>
#include <string_view>
#include <vector>

#include "tofsim/capture/DirectLightView.h"
#include "tofsim/capture/SegmentSink.h"
#include "tofsim/capture/SegmentPlan.h"

namespace tofsim::capture {

/// One segment's buffers while a renderer fills them: one per component, in
/// the order of the names given to streamSegments, pixels.count * T * C
/// floats each, zeroed.
struct SegmentBuffers {
  std::size_t index = 0;  ///< segment number in the plan
  PixelRange pixels;
  std::vector<float*> components;
};

using SegmentFill = std::function<void(const SegmentBuffers&)>;

/// Runs `fill` for each segment of `plan`, in order, and streams the results
/// to `sink`. `names[0]` must be capture::kDirect: the light seen straight by
/// the camera (`lightView`) goes there, or, when off the axis, to `offAxis`
/// (after what `fill` added for the segment's pixels).
void streamSegments(const SegmentPlan& plan, const TimeAxis& axis,
                    const std::vector<std::string_view>& names,
                    const capture::DirectLightView& lightView, capture::SegmentSink& sink,
                    AxisLoss& offAxis, const SegmentFill& fill);

}  // namespace tofsim::capture
