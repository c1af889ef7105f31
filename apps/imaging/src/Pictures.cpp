#include "tofsim/imaging/Pictures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <tuple>
#include <utility>
#include <vector>

#include "PngFile.h"
#include "tofsim/util/Error.h"

namespace tofsim::imaging {

using detail::drawText;
using detail::savePng;
using detail::shortNumber;

namespace {



// The range of the finite values, ignoring the extreme 0.5 % at each end (as
// the tone map's 99.5th percentile white), and tightened to Tukey's outer
// fences (quartiles -+ 3 IQR) when those are narrower: a few outliers (hot
// pixels, a glint) or a minority of wild ones (pixels with no signal, whose
// CW-ToF depth is noise over the whole unambiguous range) then do not
// squeeze the rest of the picture into one colour. Mostly-dark pictures (a
// quarter of the pixels at the minimum, e.g. a streak image, whose signal is
// the sparse bright part) keep the percentile range.
std::pair<double, double> robustRange(const std::vector<float>& data) {
  std::vector<float> v;
  v.reserve(data.size());
  for (float x : data) {
    if (std::isfinite(x)) v.push_back(x);
  }
  if (v.empty()) return {0.0, 1.0};
  std::sort(v.begin(), v.end());
  const auto at = [&](double q) {
    return static_cast<double>(v[std::min(v.size() - 1, static_cast<std::size_t>(q * v.size()))]);
  };
  double lo = at(0.005), hi = at(0.995);
  const double q1 = at(0.25), q3 = at(0.75);
  if (q1 > v.front() && q3 > q1) {
    lo = std::max(lo, q1 - 3.0 * (q3 - q1));
    hi = std::min(hi, q3 + 3.0 * (q3 - q1));
  }
  return {lo, hi > lo ? hi : lo + 1.0};
}

}  // namespace

void writeToneMappedPng(const std::filesystem::path& path, const Image& image, ToneMap mode) {
  TOFSIM_CHECK(image.channels == 1 || image.channels == 3);
  const double white = detail::whiteLevel(image.data.data(), image.data.size());
  cv::Mat out(image.height, image.width, CV_8UC3);
  for (int32_t y = 0; y < image.height; ++y) {
    for (int32_t x = 0; x < image.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        const double v = image.at(y, x, image.channels == 3 ? c : 0);
        out.at<cv::Vec3b>(y, x)[2 - c] = detail::toneMapped8(v, white, mode);  // OpenCV: BGR
      }
    }
  }
  savePng(path, out);
}

void writeColormappedPng(const std::filesystem::path& path, const Image& image,
                         const std::string& label, const std::string& colormap, double lo,
                         double hi) {
  TOFSIM_CHECK(image.channels == 1);
  if (lo == hi) std::tie(lo, hi) = robustRange(image.data);
  const int code = detail::colormapCode(colormap);
  cv::Mat gray(image.height, image.width, CV_8UC1);
  cv::Mat invalid(image.height, image.width, CV_8UC1);
  for (int32_t y = 0; y < image.height; ++y) {
    for (int32_t x = 0; x < image.width; ++x) {
      const double v = image.at(y, x, 0);
      invalid.at<unsigned char>(y, x) = std::isfinite(v) ? 0 : 255;
      gray.at<unsigned char>(y, x) = static_cast<unsigned char>(
          std::lround(std::clamp((v - lo) / (hi - lo), 0.0, 1.0) * 255.0));
    }
  }
  cv::Mat colored, big;
  cv::applyColorMap(gray, colored, code);
  colored.setTo(cv::Scalar(0, 0, 0), invalid);
  // Upscale small images (whole pixels, no smoothing) so they and the labels
  // stay readable.
  const int scale = std::max(1, 256 / std::max(image.width, image.height));
  const int w = image.width * scale, h = image.height * scale;
  cv::resize(colored, big, cv::Size(w, h), 0, 0, cv::INTER_NEAREST);

  // Layout: title on top (wrapped to the picture's width), image on the
  // left, colour bar with five ticks on the right.
  const int pad = 10, barW = 20, barH = std::max(h, 160);
  int tickW = 0;
  for (int k = 0; k <= 4; ++k) {
    tickW = std::max(tickW, detail::textSize(shortNumber(lo + (hi - lo) * k / 4)).width);
  }
  const int barX = pad + w + 12;
  const int width = std::max(barX + barW + 8 + tickW + pad, 320);
  const std::vector<std::string> title = detail::wrapText(label, width - 2 * pad);
  const int lineH = 18, titleH = 10 + lineH * static_cast<int>(title.size());
  cv::Mat canvas(titleH + barH + pad, width, CV_8UC3, cv::Scalar(255, 255, 255));
  big.copyTo(canvas(cv::Rect(pad, titleH, w, h)));
  for (std::size_t i = 0; i < title.size(); ++i) {
    drawText(canvas, title[i], {pad, 20 + lineH * static_cast<int>(i)});
  }
  cv::Mat ramp(barH, 1, CV_8UC1), rampColored, rampWide;
  for (int i = 0; i < barH; ++i) {
    ramp.at<unsigned char>(i, 0) =
        static_cast<unsigned char>(255 - 255 * i / std::max(1, barH - 1));
  }
  cv::applyColorMap(ramp, rampColored, code);
  cv::resize(rampColored, rampWide, cv::Size(barW, barH), 0, 0, cv::INTER_NEAREST);
  rampWide.copyTo(canvas(cv::Rect(barX, titleH, barW, barH)));
  cv::rectangle(canvas, cv::Rect(barX, titleH, barW, barH), {0, 0, 0}, 1);
  for (int k = 0; k <= 4; ++k) {
    const int y = titleH + (barH - 1) - (barH - 1) * k / 4;
    cv::line(canvas, {barX + barW, y}, {barX + barW + 4, y}, {0, 0, 0}, 1);
    drawText(canvas, shortNumber(lo + (hi - lo) * k / 4), {barX + barW + 7, y + 5});
  }
  savePng(path, canvas);
}

}  // namespace tofsim::imaging
