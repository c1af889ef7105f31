#include "tofsim/capture/SegmentStream.h"

#include <algorithm>
#include <memory>

#include "tofsim/util/Error.h"
#include "tofsim/util/ZeroedBuffer.h"

namespace tofsim::capture {

void streamSegments(const SegmentPlan& plan, const TimeAxis& axis,
                    const std::vector<std::string_view>& names,
                    const capture::DirectLightView& lightView, capture::SegmentSink& sink,
                    AxisLoss& offAxis, const SegmentFill& fill) {
  TOFSIM_CHECK(!names.empty() && names[0] == capture::kDirect);
  const std::size_t floatsPerPixel = static_cast<std::size_t>(axis.bins) * capture::kChannels;
  // Zero and resident from the kernel (ZeroedBuffer.h): the first segment
  // needs no pass of its own over them, the later ones zero what they use.
  std::vector<util::ZeroedBuffer<float>> storage;
  SegmentBuffers buffers;
  for (std::size_t c = 0; c < names.size(); ++c) {
    storage.emplace_back(plan.pixelsPerSegment * floatsPerPixel);
    buffers.components.push_back(storage.back().data());
  }
  capture::Segment segment;
  for (std::size_t s = 0; s < plan.segmentCount; ++s) {
    buffers.index = s;
    buffers.pixels = plan.segment(s);
    const std::size_t floats = buffers.pixels.count * floatsPerPixel;
    if (s > 0) {
      for (float* c : buffers.components) std::fill_n(c, floats, 0.0f);
    }
    fill(buffers);
    offAxis += lightView.addTo(buffers.pixels.first, buffers.pixels.count, axis, capture::kChannels,
                               buffers.components[0]);
    segment.firstPixel = buffers.pixels.first;
    segment.pixelCount = buffers.pixels.count;
    segment.components.clear();
    for (std::size_t c = 0; c < names.size(); ++c) {
      segment.components.push_back({names[c], buffers.components[c]});
    }
    sink.consume(segment);
  }
}

}  // namespace tofsim::capture
