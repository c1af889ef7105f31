#include "tofsim/pipeline/OutputSink.h"

#include <algorithm>

#include "tofsim/capture/VolumeCollector.h"

namespace tofsim::pipeline {

namespace {
constexpr int32_t kChannels = 3;
}

OutputSink::OutputSink(const std::filesystem::path& directory, const config::OutputConfig& output,
                       int32_t width, int32_t height, const TimeAxis& axis, bool keepInMemory,
                       bool keepDirectInMemory)
    : width_(width), height_(height), axis_(axis) {
  const io::NpyShape shape = {static_cast<std::size_t>(height), static_cast<std::size_t>(width),
                              static_cast<std::size_t>(axis.bins), kChannels};
  if (output.transient) {
    total_ = std::make_unique<io::NpyStreamWriter>(directory / "transient.npy", shape);
  }
  if (output.direct) {
    directFile_ = std::make_unique<io::NpyStreamWriter>(directory / "direct.npy", shape);
  }
  if (output.indirect) {
    indirectFile_ = std::make_unique<io::NpyStreamWriter>(directory / "indirect.npy", shape);
  }
  steady_.assign(static_cast<std::size_t>(width) * height * kChannels, 0.0);
  if (keepInMemory) volume_.emplace(width, height, axis, capture::defaultChannelNames(kChannels));
  if (keepDirectInMemory) {
    direct_.emplace(width, height, axis, capture::defaultChannelNames(kChannels));
  }
}

void OutputSink::consume(const capture::Segment& segment) {
  const std::size_t pixelFloats = static_cast<std::size_t>(axis_.bins) * kChannels;
  const std::size_t floats = segment.pixelCount * pixelFloats;
  scratch_.resize(floats);
  // total = direct + indirect in float, so each component file adds up to it.
  for (std::size_t i = 0; i < floats; ++i) scratch_[i] = segment.direct[i] + segment.indirect[i];
  if (total_) total_->append(scratch_.data(), floats);
  if (directFile_) directFile_->append(segment.direct, floats);
  if (indirectFile_) indirectFile_->append(segment.indirect, floats);
  for (std::size_t p = 0; p < segment.pixelCount; ++p) {
    double* out = &steady_[(segment.firstPixel + p) * kChannels];
    const float* in = &scratch_[p * pixelFloats];
    for (int32_t t = 0; t < axis_.bins; ++t) {
      for (int32_t c = 0; c < kChannels; ++c) out[c] += in[t * kChannels + c];
    }
  }
  const std::size_t offset = segment.firstPixel * pixelFloats;
  if (volume_) std::copy_n(scratch_.data(), floats, volume_->data() + offset);
  if (direct_) std::copy_n(segment.direct, floats, direct_->data() + offset);
}

void OutputSink::commit() {
  if (total_) total_->commit();
  if (directFile_) directFile_->commit();
  if (indirectFile_) indirectFile_->commit();
}

Image OutputSink::steady() const {
  Image image(width_, height_, kChannels);
  std::transform(steady_.begin(), steady_.end(), image.data.begin(),
                 [](double v) { return static_cast<float>(v); });
  return image;
}

}  // namespace tofsim::pipeline
