#pragma once
// Receives the transient volume in segments: runs of consecutive pixels in row
// order, each pixel holding T bins x C channels (the (H, W, T, C) layout), so
// every segment is one contiguous slice of transient.npy. Segments arrive in
// order and cover the image exactly once; nothing needs the whole volume in
// memory.
//
// A segment carries the light split into named components: direct and
// indirect, and from the IR renderers also bounce1 .. bounceN (the light
// whose path has exactly k indirect bounces). The volume is direct + indirect
// in float, and indirect is the float sum of the bounces in bounce order, so
// each component file adds up exactly.

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace tofsim::capture {

/// Colour channels of every volume a renderer emits (R, G, B).
inline constexpr int32_t kChannels = 3;

/// Names of the components the renderers emit today.
inline constexpr std::string_view kDirect = "direct";      ///< bounce 1 and the light seen straight
inline constexpr std::string_view kIndirect = "indirect";  ///< bounces 2..n

/// The most indirect bounces a component can name (render.indirect.bounces' limit).
inline constexpr int32_t kMaxBounceComponents = 8;
/// "bounce1" .. "bounce8" (static lifetime): the light of exactly `bounce`
/// indirect bounces, 1 <= bounce <= kMaxBounceComponents.
std::string_view bounceComponent(int32_t bounce);

struct SegmentComponent {
  std::string_view name;          ///< a string with static lifetime, e.g. kDirect
  const float* values = nullptr;  ///< Segment::pixelCount * T * C floats
};

struct Segment {
  std::size_t firstPixel = 0;  ///< y * width + x of the first pixel
  std::size_t pixelCount = 0;
  /// Direct first; a renderer always lists the same components in the same
  /// order (indirect is all zero when indirect light is off).
  std::vector<SegmentComponent> components;

  /// The values of the component called `name`; TOFSIM_CHECK fails when the
  /// segment has none (a consumer asking for a component no renderer emits).
  const float* component(std::string_view name) const;
};

class SegmentSink {
 public:
  virtual ~SegmentSink() = default;
  virtual void consume(const Segment& segment) = 0;
};

/// Feeds every segment to several consumers (files, sensors, video), in the
/// order given. The consumers are not owned and must outlive the tee.
class TeeSink : public SegmentSink {
 public:
  explicit TeeSink(std::vector<SegmentSink*> consumers);
  void consume(const Segment& segment) override;

 private:
  std::vector<SegmentSink*> consumers_;
};

}  // namespace tofsim::capture
