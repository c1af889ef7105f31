#include "tofsim/pipeline/OutputSink.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace tofsim::pipeline {

namespace {
constexpr int32_t kChannels = 3;
}  // namespace

std::size_t zeroNonFinite(float* values, std::size_t count) {
  std::size_t rejected = 0;
  for (std::size_t i = 0; i < count; ++i) {
    if (!std::isfinite(values[i])) {
      values[i] = 0.0f;
      ++rejected;
    }
  }
  return rejected;
}

OutputSink::OutputSink(const std::filesystem::path& directory, const config::OutputConfig& output,
                       int32_t width, int32_t height, const TimeAxis& axis, Forward forward,
                       int32_t forwardBounces)
    : width_(width),
      height_(height),
      axis_(axis),
      forwardBounces_(forwardBounces),
      forward_(std::move(forward)) {
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
  for (const int32_t k : output.bounces) {
    const std::string name = "bounce" + std::to_string(k) + ".npy";
    bounceFiles_.emplace_back(k, std::make_unique<io::NpyStreamWriter>(directory / name, shape));
  }
  steady_.assign(static_cast<std::size_t>(width) * height * kChannels, 0.0);
}

void OutputSink::consume(const capture::Segment& segment) {
  const std::size_t pixelFloats = static_cast<std::size_t>(axis_.bins) * kChannels;
  const std::size_t floats = segment.pixelCount * pixelFloats;
  const float* direct = segment.component(capture::kDirect);
  const float* indirect = segment.component(capture::kIndirect);
  directScratch_.assign(direct, direct + floats);
  indirectScratch_.assign(indirect, indirect + floats);
  nonFinite_ += zeroNonFinite(directScratch_.data(), floats);
  nonFinite_ += zeroNonFinite(indirectScratch_.data(), floats);
  scratch_.resize(floats);
  // total = direct + indirect in float, so each component file adds up to it.
  for (std::size_t i = 0; i < floats; ++i) scratch_[i] = directScratch_[i] + indirectScratch_[i];
  nonFinite_ += zeroNonFinite(scratch_.data(), floats);  // two finite floats can overflow
  if (total_) total_->append(scratch_.data(), floats);
  if (directFile_) directFile_->append(directScratch_.data(), floats);
  if (indirectFile_) indirectFile_->append(indirectScratch_.data(), floats);
  if (forwardBounces_ >= 2) cleanForwardedBounces(segment, floats);
  for (const auto& [k, file] : bounceFiles_) file->append(cleanBounce(segment, k, floats), floats);
  for (std::size_t p = 0; p < segment.pixelCount; ++p) {
    double* out = &steady_[(segment.firstPixel + p) * kChannels];
    const float* in = &scratch_[p * pixelFloats];
    for (int32_t t = 0; t < axis_.bins; ++t) {
      for (int32_t c = 0; c < kChannels; ++c) out[c] += in[t * kChannels + c];
    }
  }
  if (forward_) forward_(forwardedSpan(segment));
}

void OutputSink::cleanForwardedBounces(const capture::Segment& segment, std::size_t floats) {
  forwardedBounces_.resize(static_cast<std::size_t>(forwardBounces_));
  for (int32_t k = 1; k <= forwardBounces_; ++k) {
    const float* bounce = segment.component(capture::bounceComponent(k));
    std::vector<float>& copy = forwardedBounces_[k - 1];
    copy.assign(bounce, bounce + floats);
    zeroNonFinite(copy.data(), floats);  // counted in indirect's
  }
}

const float* OutputSink::cleanBounce(const capture::Segment& segment, int32_t k,
                                     std::size_t floats) {
  // The sensors' copy when they take bounce k (cleaned once per segment).
  if (forwardBounces_ >= 2 && k <= forwardBounces_) return forwardedBounces_[k - 1].data();
  const float* bounce = segment.component(capture::bounceComponent(k));
  bounceScratch_.assign(bounce, bounce + floats);
  zeroNonFinite(bounceScratch_.data(), floats);  // already counted in indirect's
  return bounceScratch_.data();
}

sensors::PixelSpan OutputSink::forwardedSpan(const capture::Segment& segment) const {
  sensors::PixelSpan span{
      segment.firstPixel, segment.pixelCount, scratch_.data(), directScratch_.data(), {}};
  if (forwardBounces_ == 1) span.bounces.push_back(indirectScratch_.data());
  if (forwardBounces_ >= 2) {
    for (const std::vector<float>& b : forwardedBounces_) span.bounces.push_back(b.data());
  }
  return span;
}

void OutputSink::commit() {
  if (total_) total_->commit();
  if (directFile_) directFile_->commit();
  if (indirectFile_) indirectFile_->commit();
  for (const auto& entry : bounceFiles_) entry.second->commit();
}

Image OutputSink::steady() const {
  Image image(width_, height_, kChannels);
  std::transform(steady_.begin(), steady_.end(), image.data.begin(),
                 [](double v) { return static_cast<float>(v); });
  return image;
}

}  // namespace tofsim::pipeline
