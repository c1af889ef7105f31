#include "tofsim/pipeline/VolumeFileSink.h"

namespace tofsim::pipeline {

VolumeFileSink::VolumeFileSink(const std::filesystem::path& file, std::string_view component,
                               int32_t width, int32_t height, const TimeAxis& axis)
    : component_(component),
      pixelFloats_(static_cast<std::size_t>(axis.bins) * capture::kChannels),
      writer_(file, {static_cast<std::size_t>(height), static_cast<std::size_t>(width),
                     static_cast<std::size_t>(axis.bins), capture::kChannels}) {}

void VolumeFileSink::consume(const capture::Segment& segment) {
  writer_.append(segment.component(component_), segment.pixelCount * pixelFloats_);
}

}  // namespace tofsim::pipeline
