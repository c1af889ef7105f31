#include "tofsim/imaging/Pictures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Error.h"

namespace tofsim::imaging {

namespace {

double percentile(std::vector<float> values, double q) {
  values.erase(std::remove_if(values.begin(), values.end(),
                              [](float v) { return !(v > 0.0f) || !std::isfinite(v); }),
               values.end());
  if (values.empty()) return 1.0;
  const std::size_t k = std::min(values.size() - 1, static_cast<std::size_t>(q * values.size()));
  std::nth_element(values.begin(), values.begin() + static_cast<long>(k), values.end());
  return values[k];
}

unsigned char srgb8(double linear) {
  const double v = std::clamp(linear, 0.0, 1.0);
  const double s = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  return static_cast<unsigned char>(std::lround(s * 255.0));
}

// PNG bytes encoded in memory, then written atomically.
void savePng(const std::filesystem::path& path, const cv::Mat& bgr) {
  std::vector<unsigned char> bytes;
  if (!cv::imencode(".png", bgr, bytes)) {
    throw InputError(FileLoc{path.string()}, "", "PNG encoding failed");
  }
  writeFileAtomically(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace

void writeToneMappedPng(const std::filesystem::path& path, const Image& image, ToneMap mode) {
  TOFSIM_CHECK(image.channels == 1 || image.channels == 3);
  const double white = percentile(image.data, 0.995);
  cv::Mat out(image.height, image.width, CV_8UC3);
  for (int32_t y = 0; y < image.height; ++y) {
    for (int32_t x = 0; x < image.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        const double v = image.at(y, x, image.channels == 3 ? c : 0);
        double mapped = v / white;
        if (mode == ToneMap::Log) mapped = v > 0.0 ? 1.0 + std::log10(v / white) / 4.0 : 0.0;
        out.at<cv::Vec3b>(y, x)[2 - c] = srgb8(mapped);  // OpenCV stores BGR
      }
    }
  }
  savePng(path, out);
}

void writeColormappedPng(const std::filesystem::path& path, const Image& image,
                         const std::string& label, double lo, double hi) {
  TOFSIM_CHECK(image.channels == 1);
  if (lo == hi) {
    lo = INFINITY;
    hi = -INFINITY;
    for (float v : image.data) {
      if (std::isfinite(v)) {
        lo = std::min(lo, static_cast<double>(v));
        hi = std::max(hi, static_cast<double>(v));
      }
    }
    if (!(hi > lo)) hi = lo + 1.0;
  }
  // Upscale small images so the labels stay readable.
  const int scale = std::max(1, 256 / std::max(image.width, image.height));
  const int w = image.width * scale, h = image.height * scale;
  const int bar = 24, margin = 90;
  cv::Mat gray(image.height, image.width, CV_8UC1);
  cv::Mat valid(image.height, image.width, CV_8UC1);
  for (int32_t y = 0; y < image.height; ++y) {
    for (int32_t x = 0; x < image.width; ++x) {
      const double v = image.at(y, x, 0);
      valid.at<unsigned char>(y, x) = std::isfinite(v) ? 255 : 0;
      gray.at<unsigned char>(y, x) =
          static_cast<unsigned char>(std::lround(std::clamp((v - lo) / (hi - lo), 0.0, 1.0) * 255.0));
    }
  }
  cv::Mat colored;
  cv::applyColorMap(gray, colored, cv::COLORMAP_TURBO);
  colored.setTo(cv::Scalar(0, 0, 0), valid == 0);
  cv::Mat big;
  cv::resize(colored, big, cv::Size(w, h), 0, 0, cv::INTER_NEAREST);
  cv::Mat canvas(std::max(h, 120), w + bar + margin + 10, CV_8UC3, cv::Scalar(255, 255, 255));
  big.copyTo(canvas(cv::Rect(0, 0, w, h)));
  cv::Mat ramp(canvas.rows - 40, 1, CV_8UC1);
  for (int i = 0; i < ramp.rows; ++i) {
    ramp.at<unsigned char>(i, 0) = static_cast<unsigned char>(255 - 255 * i / std::max(1, ramp.rows - 1));
  }
  cv::Mat rampColored, rampWide;
  cv::applyColorMap(ramp, rampColored, cv::COLORMAP_TURBO);
  cv::resize(rampColored, rampWide, cv::Size(bar, ramp.rows), 0, 0, cv::INTER_NEAREST);
  rampWide.copyTo(canvas(cv::Rect(w + 6, 20, bar, ramp.rows)));
  char text[64];
  std::snprintf(text, sizeof text, "%.4g", hi);
  cv::putText(canvas, text, {w + bar + 10, 30}, cv::FONT_HERSHEY_SIMPLEX, 0.4, {0, 0, 0}, 1, cv::LINE_AA);
  std::snprintf(text, sizeof text, "%.4g", lo);
  cv::putText(canvas, text, {w + bar + 10, canvas.rows - 22}, cv::FONT_HERSHEY_SIMPLEX, 0.4, {0, 0, 0}, 1,
              cv::LINE_AA);
  cv::putText(canvas, label, {w + 4, canvas.rows - 6}, cv::FONT_HERSHEY_SIMPLEX, 0.4, {0, 0, 0}, 1,
              cv::LINE_AA);
  savePng(path, canvas);
}

}  // namespace tofsim::imaging
