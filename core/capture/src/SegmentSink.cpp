#include "tofsim/capture/SegmentSink.h"

#include <algorithm>
#include <string>

#include "tofsim/util/Error.h"

namespace tofsim::capture {

std::string_view bounceComponent(int32_t bounce) {
  static constexpr std::string_view kNames[kMaxBounceComponents] = {
      "bounce1", "bounce2", "bounce3", "bounce4", "bounce5", "bounce6", "bounce7", "bounce8"};
  TOFSIM_CHECK(bounce >= 1 && bounce <= kMaxBounceComponents);
  return kNames[bounce - 1];
}

const float* Segment::component(std::string_view name) const {
  const auto it = std::find_if(components.begin(), components.end(),
                               [&](const SegmentComponent& c) { return c.name == name; });
  TOFSIM_CHECK_MSG(it != components.end(), "segment has no component " + std::string(name));
  return it->values;
}

TeeSink::TeeSink(std::vector<SegmentSink*> consumers) : consumers_(std::move(consumers)) {
  for (const SegmentSink* c : consumers_) TOFSIM_CHECK(c != nullptr);
}

void TeeSink::consume(const Segment& segment) {
  for (SegmentSink* c : consumers_) c->consume(segment);
}

}  // namespace tofsim::capture
