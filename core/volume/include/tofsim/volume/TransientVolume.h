#pragma once
// A per-pixel time histogram: the scene's impulse response as seen by a camera.
//
// Layout is (H, W, T, C) in C order, the layout of transient.npy:
//   value(y, x, t, c) = data[((y * W + x) * T + t) * C + c]
// Row y = 0 is the top of the image. Values are linear radiance
// (W / (m^2 sr)) integrated over each time bin, so summing over t gives the
// steady-state radiance.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "tofsim/volume/TimeAxis.h"

namespace tofsim {

class TransientVolume {
 public:
  TransientVolume() = default;
  TransientVolume(int32_t width, int32_t height, TimeAxis axis, std::vector<std::string> channels);

  int32_t width() const { return width_; }
  int32_t height() const { return height_; }
  int32_t bins() const { return axis_.bins; }
  int32_t channels() const { return static_cast<int32_t>(channelNames_.size()); }
  const TimeAxis& axis() const { return axis_; }
  const std::vector<std::string>& channelNames() const { return channelNames_; }

  std::size_t index(int32_t y, int32_t x, int32_t t, int32_t c) const {
    return ((static_cast<std::size_t>(y) * width_ + x) * axis_.bins + t) * channels() + c;
  }
  float& at(int32_t y, int32_t x, int32_t t, int32_t c) { return data_[index(y, x, t, c)]; }
  float at(int32_t y, int32_t x, int32_t t, int32_t c) const { return data_[index(y, x, t, c)]; }

  /// Floats per pixel (T * C) and per image row (W * T * C).
  std::size_t pixelStride() const { return static_cast<std::size_t>(axis_.bins) * channels(); }
  std::size_t rowStride() const { return pixelStride() * width_; }

  float* data() { return data_.data(); }
  const float* data() const { return data_.data(); }
  std::size_t size() const { return data_.size(); }
  std::vector<float>& values() { return data_; }
  const std::vector<float>& values() const { return data_; }

 private:
  int32_t width_ = 0;
  int32_t height_ = 0;
  TimeAxis axis_;
  std::vector<std::string> channelNames_;
  std::vector<float> data_;
};

/// A float image (H, W, C), C order; row 0 is the top.
struct Image {
  int32_t width = 0;
  int32_t height = 0;
  int32_t channels = 0;
  std::vector<float> data;

  Image() = default;
  Image(int32_t w, int32_t h, int32_t c)
      : width(w), height(h), channels(c), data(static_cast<std::size_t>(w) * h * c, 0.0f) {}
  float& at(int32_t y, int32_t x, int32_t c) {
    return data[(static_cast<std::size_t>(y) * width + x) * channels + c];
  }
  float at(int32_t y, int32_t x, int32_t c) const {
    return data[(static_cast<std::size_t>(y) * width + x) * channels + c];
  }
};

/// Sum over time of every pixel: the steady-state image. Accumulates in double
/// so the result is the correctly rounded sum of the float bins.
Image steadyImage(const TransientVolume& volume);

}  // namespace tofsim
