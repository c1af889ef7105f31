// writeColormappedPng: a scalar image through a colormap, with a colour bar
// that says what it shows (ticks, clipped ends, the range's origin, no data).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <utility>
#include <vector>

#include "PngFile.h"
#include "tofsim/imaging/Pictures.h"
#include "tofsim/util/Error.h"

namespace tofsim::imaging {

namespace {
using detail::drawText;
using detail::shortNumber;
using detail::textSize;

bool isData(double v, const ColorScale& scale) {
  return std::isfinite(v) && !(scale.nonPositiveIsNoData && v <= 0.0);
}

// The range of the values, ignoring the extreme 0.5 % at each end (as the
// tone map's 99.5th percentile white), and tightened to Tukey's outer fences
// (quartiles -+ 3 IQR) when those are narrower: a few outliers (hot pixels,
// a glint) or a minority of wild ones (pixels with no signal, whose CW-ToF
// depth is noise over the whole unambiguous range) then do not squeeze the
// rest of the picture into one colour. Mostly-dark pictures (a quarter of
// the pixels at the minimum, e.g. a streak image, whose signal is the sparse
// bright part) keep the percentile range. `sorted` holds the valid values.
std::pair<double, double> robustRange(const std::vector<float>& v, bool diverging) {
  if (v.empty()) return {diverging ? -1.0 : 0.0, 1.0};
  const auto at = [&](double q) {
    return static_cast<double>(v[std::min(v.size() - 1, static_cast<std::size_t>(q * v.size()))]);
  };
  double lo = at(0.005), hi = at(0.995);
  const double q1 = at(0.25), q3 = at(0.75);
  if (q1 > v.front() && q3 > q1) {
    lo = std::max(lo, q1 - 3.0 * (q3 - q1));
    hi = std::min(hi, q3 + 3.0 * (q3 - q1));
  }
  if (diverging) {  // symmetric about 0: equal errors either way, equal colours
    const double m = std::max(std::abs(lo), std::abs(hi));
    return {m > 0.0 ? -m : -1.0, m > 0.0 ? m : 1.0};
  }
  return {lo, hi > lo ? hi : lo + 1.0};
}

// Range, clipping and percentiles of the valid values.
ColorScaleUsed chooseRange(const Image& image, const ColorScale& scale) {
  std::vector<float> v;
  for (float x : image.data) {
    if (isData(x, scale)) v.push_back(x);
  }
  std::sort(v.begin(), v.end());
  ColorScaleUsed used;
  used.noDataPixels = static_cast<int>(image.data.size() - v.size());
  used.automatic = !scale.range;
  std::tie(used.lo, used.hi) = scale.range ? std::pair((*scale.range)[0], (*scale.range)[1])
                                           : robustRange(v, scale.diverging);
  TOFSIM_CHECK(used.hi > used.lo);
  if (!v.empty()) {
    const auto below = std::lower_bound(v.begin(), v.end(), used.lo) - v.begin();
    const auto upTo = std::upper_bound(v.begin(), v.end(), used.hi) - v.begin();
    used.clippedLow = below > 0;
    used.clippedHigh = upTo < static_cast<std::ptrdiff_t>(v.size());
    used.loPercentile = 100.0 * static_cast<double>(below) / static_cast<double>(v.size());
    used.hiPercentile = 100.0 * static_cast<double>(upTo) / static_cast<double>(v.size());
  }
  return used;
}

std::string percentile(double p) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", p);
  return text;
}

// One line under the picture: where the range came from and what it cut.
std::string caption(const ColorScaleUsed& used, const ColorScale& scale) {
  std::string text = used.automatic ? "auto range" : "fixed range (" + scale.rangeSource + ")";
  if (used.automatic && (used.clippedLow || used.clippedHigh)) {
    text += ", clipped at percentiles " + percentile(used.loPercentile) + " / " +
            percentile(used.hiPercentile);
  } else if (used.clippedLow || used.clippedHigh) {
    text += ", clipped";
  }
  return text;
}

cv::Mat colourIndices(const Image& image, const ColorScale& scale, const ColorScaleUsed& used,
                      cv::Mat& noData) {
  cv::Mat gray(image.height, image.width, CV_8UC1);
  noData = cv::Mat(image.height, image.width, CV_8UC1);
  for (int32_t y = 0; y < image.height; ++y) {
    for (int32_t x = 0; x < image.width; ++x) {
      const double v = image.at(y, x, 0);
      noData.at<unsigned char>(y, x) = isData(v, scale) ? 0 : 255;
      const double u = std::isfinite(v) ? (v - used.lo) / (used.hi - used.lo) : 0.0;
      gray.at<unsigned char>(y, x) =
          static_cast<unsigned char>(std::lround(std::clamp(u, 0.0, 1.0) * 255.0));
    }
  }
  return gray;
}

// A triangle beyond one end of the bar in that end's colour: values lie
// beyond it (matplotlib's colour bar "extend").
void endTriangle(cv::Mat& canvas, const cv::Rect& bar, bool top, const cv::Vec3b& colour) {
  const int h = 12, yBase = top ? bar.y - 1 : bar.y + bar.height;
  const int yTip = top ? yBase - h : yBase + h;
  const std::vector<cv::Point> points = {
      {bar.x, yBase}, {bar.x + bar.width - 1, yBase}, {bar.x + bar.width / 2, yTip}};
  cv::fillConvexPoly(canvas, points, cv::Scalar(colour[0], colour[1], colour[2]), cv::LINE_8);
  cv::polylines(canvas, points, true, {0, 0, 0}, 1, cv::LINE_8);
}

void rowTicks(cv::Mat& canvas, const RowAxis& axis, const cv::Rect& img, int rows) {
  const double scale = static_cast<double>(img.height) / rows;
  const double end = axis.start + axis.step * rows;
  for (double t : detail::niceTicks(axis.start, end, 6)) {
    const int y = img.y + static_cast<int>(std::lround((t - axis.start) / axis.step * scale));
    if (y < img.y || y > img.y + img.height) continue;
    cv::line(canvas, {img.x - 5, y}, {img.x - 1, y}, {0, 0, 0}, 1);
    const std::string text = shortNumber(t);
    drawText(canvas, text, {img.x - 8 - textSize(text, 0.4).width, y + 4}, 0.4);
  }
  drawText(canvas, axis.label, {4, img.y - 6}, 0.4);
}
}  // namespace

ColorScaleUsed writeColormappedPng(const std::filesystem::path& path, const Image& image,
                                   const std::string& label, const ColorScale& scale) {
  TOFSIM_CHECK(image.channels == 1);
  ColorScaleUsed used = chooseRange(image, scale);
  const std::string colormap = scale.diverging ? "coolwarm" : scale.colormap;
  cv::Mat noData, colored, big;
  detail::applyColormap(colourIndices(image, scale, used, noData), colored, colormap);
  colored.setTo(cv::Scalar(kNoDataGrey, kNoDataGrey, kNoDataGrey), noData);
  // Upscale small images (whole pixels, no smoothing) so they and the labels
  // stay readable.
  const int up = std::max(1, 256 / std::max(image.width, image.height));
  const int w = image.width * up, h = image.height * up;
  cv::resize(colored, big, cv::Size(w, h), 0, 0, cv::INTER_NEAREST);

  // Layout: title on top (wrapped), row ticks (if any) left of the image,
  // colour bar with five ticks and end triangles on the right, the caption
  // and the no-data swatch below.
  const int pad = 10, barW = 20, tri = 14, barH = std::max(h, 160), lineH = 18;
  int tickW = 0;
  for (int k = 0; k <= 4; ++k) {
    tickW = std::max(tickW, textSize(shortNumber(used.lo + (used.hi - used.lo) * k / 4)).width);
  }
  int left = pad;
  if (scale.rows) {
    for (double t : detail::niceTicks(scale.rows->start,
                                      scale.rows->start + scale.rows->step * image.height, 6)) {
      left = std::max(left, 14 + textSize(shortNumber(t), 0.4).width);
    }
  }
  const int barX = left + w + 12;
  const std::string note = caption(used, scale);
  const int width =
      std::max({barX + barW + 8 + tickW + pad, 320, left + textSize(note, 0.4).width + pad});
  const std::vector<std::string> title = detail::wrapText(label, width - 2 * pad);
  const int titleH = 10 + lineH * static_cast<int>(title.size()) + (scale.rows ? lineH : 0);
  const int barY = titleH + tri;
  const int bottom = barY + barH + tri + 4;
  cv::Mat canvas(bottom + 2 * lineH + 4, width, CV_8UC3, cv::Scalar(255, 255, 255));
  const cv::Rect img(left, barY, w, h), bar(barX, barY, barW, barH);
  big.copyTo(canvas(img));
  for (std::size_t i = 0; i < title.size(); ++i) {
    drawText(canvas, title[i], {pad, 20 + lineH * static_cast<int>(i)});
  }
  if (scale.rows) rowTicks(canvas, *scale.rows, img, image.height);

  cv::Mat ramp(barH, 1, CV_8UC1), rampColored, rampWide;
  for (int i = 0; i < barH; ++i) {
    ramp.at<unsigned char>(i, 0) =
        static_cast<unsigned char>(255 - 255 * i / std::max(1, barH - 1));
  }
  detail::applyColormap(ramp, rampColored, colormap);
  cv::resize(rampColored, rampWide, cv::Size(barW, barH), 0, 0, cv::INTER_NEAREST);
  rampWide.copyTo(canvas(bar));
  cv::rectangle(canvas, bar, {0, 0, 0}, 1);
  if (used.clippedHigh) endTriangle(canvas, bar, true, rampColored.at<cv::Vec3b>(0, 0));
  if (used.clippedLow) endTriangle(canvas, bar, false, rampColored.at<cv::Vec3b>(barH - 1, 0));
  for (int k = 0; k <= 4; ++k) {
    const int y = barY + (barH - 1) - (barH - 1) * k / 4;
    cv::line(canvas, {barX + barW, y}, {barX + barW + 4, y}, {0, 0, 0}, 1);
    drawText(canvas, shortNumber(used.lo + (used.hi - used.lo) * k / 4), {barX + barW + 7, y + 5});
  }
  drawText(canvas, note, {left, bottom + 12}, 0.4);
  if (used.noDataPixels > 0) {
    const cv::Rect swatch(left, bottom + lineH + 2, 14, 12);
    canvas(swatch).setTo(cv::Scalar(kNoDataGrey, kNoDataGrey, kNoDataGrey));
    cv::rectangle(canvas, swatch, {0, 0, 0}, 1);
    drawText(canvas, scale.noDataLabel, {left + 20, bottom + lineH + 12}, 0.4);
  }
  detail::savePng(path, canvas);
  used.imageRect = {img.x, img.y, img.width, img.height};
  used.barRect = {bar.x, bar.y, bar.width, bar.height};
  return used;
}

}  // namespace tofsim::imaging
