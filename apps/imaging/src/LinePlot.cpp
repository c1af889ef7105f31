#include "tofsim/imaging/LinePlot.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "PngFile.h"
#include "tofsim/util/Error.h"

namespace tofsim::imaging {

namespace {

using detail::drawText;
using detail::niceTicks;
using detail::shortNumber;
using detail::textSize;

// Tableau-10 colours, as BGR: distinguishable, and readable on white.
const cv::Scalar kColors[] = {{180, 119, 31},  {14, 127, 255}, {44, 160, 44},   {40, 39, 214},
                              {189, 103, 148}, {75, 86, 140},  {194, 119, 227}, {127, 127, 127},
                              {34, 189, 188},  {207, 190, 23}};

/// The data's extent: x over every bin, y over every finite value and 0,
/// with headroom above.
struct PlotRange {
  double xLo = 0.0, xHi = 1.0, yLo = 0.0, yHi = 1.0;
};

PlotRange plotRange(const LinePlot& plot, std::size_t bins) {
  PlotRange r;
  for (const std::vector<float>& s : plot.series) {
    for (float v : s) {
      if (!std::isfinite(v)) continue;
      r.yLo = std::min(r.yLo, static_cast<double>(v));
      r.yHi = std::max(r.yHi, static_cast<double>(v));
    }
  }
  if (!(r.yHi > r.yLo)) r.yHi = r.yLo + 1.0;
  r.yHi += 0.05 * (r.yHi - r.yLo);  // headroom so the peak does not touch the frame
  r.xLo = plot.x0;
  r.xHi = plot.x0 + plot.dx * static_cast<double>(std::max<std::size_t>(bins, 1));
  return r;
}

/// Where data coordinates land: the plot area in the canvas and the range it shows.
struct PlotFrame {
  cv::Rect area;
  PlotRange range;

  int px(double x) const {
    return area.x + static_cast<int>(
                        std::lround((x - range.xLo) / (range.xHi - range.xLo) * (area.width - 1)));
  }
  int py(double y) const {
    return area.y + area.height - 1 -
           static_cast<int>(
               std::lround((y - range.yLo) / (range.yHi - range.yLo) * (area.height - 1)));
  }
};

/// Grid lines, ticks and their numbers on both axes, and the area's frame.
void drawAxes(cv::Mat& canvas, const PlotFrame& f, const std::vector<double>& yTicks) {
  const cv::Rect& area = f.area;
  const cv::Scalar grid(225, 225, 225), black(0, 0, 0);
  for (double t : niceTicks(f.range.xLo, f.range.xHi, 8)) {
    const int x = f.px(t);
    cv::line(canvas, {x, area.y}, {x, area.y + area.height - 1}, grid, 1);
    cv::line(canvas, {x, area.y + area.height}, {x, area.y + area.height + 4}, black, 1);
    const std::string text = shortNumber(t);
    drawText(canvas, text, {x - textSize(text, 0.4).width / 2, area.y + area.height + 18}, 0.4);
  }
  for (double t : yTicks) {
    if (t > f.range.yHi) continue;
    const int y = f.py(t);
    cv::line(canvas, {area.x, y}, {area.x + area.width - 1, y}, grid, 1);
    cv::line(canvas, {area.x - 5, y}, {area.x - 1, y}, black, 1);
    const std::string text = shortNumber(t);
    drawText(canvas, text, {area.x - 8 - textSize(text, 0.4).width, y + 4}, 0.4);
  }
  cv::rectangle(canvas, area, black, 1);
}

/// Each series as a line through its bins' centres, skipping non-finite values.
void drawSeries(cv::Mat& canvas, const PlotFrame& f, const LinePlot& plot, std::size_t bins) {
  for (std::size_t s = 0; s < plot.series.size(); ++s) {
    std::vector<cv::Point> points;
    for (std::size_t i = 0; i < bins; ++i) {
      const float v = plot.series[s][i];
      if (!std::isfinite(v)) continue;
      points.emplace_back(f.px(plot.x0 + (static_cast<double>(i) + 0.5) * plot.dx), f.py(v));
    }
    cv::polylines(canvas, points, false, kColors[s % std::size(kColors)], 1, cv::LINE_AA);
  }
}

/// Legend in the top-right corner of the plot area, on a white box so curves
/// under it do not hide the text.
void drawLegend(cv::Mat& canvas, const cv::Rect& area, const LinePlot& plot) {
  int legendW = 0;
  std::vector<std::string> labels;
  for (std::size_t s = 0; s < plot.series.size(); ++s) {
    labels.push_back(s < plot.labels.size() ? plot.labels[s] : "series " + std::to_string(s));
    legendW = std::max(legendW, textSize(labels.back(), 0.4).width);
  }
  if (labels.empty()) return;
  const cv::Rect box(area.x + area.width - legendW - 44, area.y + 6, legendW + 38,
                     static_cast<int>(labels.size()) * 16 + 6);
  cv::rectangle(canvas, box, cv::Scalar(255, 255, 255), cv::FILLED);
  cv::rectangle(canvas, box, cv::Scalar(160, 160, 160), 1);
  for (std::size_t s = 0; s < labels.size(); ++s) {
    const int y = box.y + 14 + static_cast<int>(s) * 16;
    cv::line(canvas, {box.x + 6, y - 4}, {box.x + 26, y - 4}, kColors[s % std::size(kColors)], 2);
    drawText(canvas, labels[s], {box.x + 32, y}, 0.4);
  }
}

/// The title, the x axis' label (with its unit) and the y axis' label, the
/// latter above the axis, whose top is at `top`.
void drawLabels(cv::Mat& canvas, const cv::Rect& area, int top, const LinePlot& plot) {
  drawText(canvas, plot.title, {area.x, 22}, 0.5);
  const std::string unit = plot.xUnit.empty() ? "" : " [" + plot.xUnit + "]";
  const std::string xLabel =
      plot.xLabel.empty() ? (unit.empty() ? "x" : unit.substr(1)) : plot.xLabel + unit;
  drawText(canvas, xLabel,
           {area.x + area.width / 2 - textSize(xLabel, 0.45).width / 2, plot.height_px - 10});
  // The y label sits above the axis rather than rotated beside it: OpenCV
  // draws no rotated text.
  drawText(canvas, plot.yLabel,
           {std::max(2, area.x - textSize(plot.yLabel, 0.4).width / 2), top - 4}, 0.4);
}

}  // namespace

void writeLinePlotPng(const std::filesystem::path& path, const LinePlot& plot) {
  TOFSIM_CHECK(plot.dx > 0.0);
  TOFSIM_CHECK(plot.width_px >= 200 && plot.height_px >= 150);
  const std::size_t bins = plot.series.empty() ? 0 : plot.series[0].size();
  for (const std::vector<float>& s : plot.series) TOFSIM_CHECK(s.size() == bins);

  const PlotRange range = plotRange(plot, bins);
  const std::vector<double> yTicks = niceTicks(range.yLo, range.yHi, 6);
  int yTickW = 0;
  for (double t : yTicks) yTickW = std::max(yTickW, textSize(shortNumber(t), 0.4).width);
  const int left = 30 + yTickW, right = 15, top = 36, bottom = 48;
  const PlotFrame frame{
      cv::Rect(left, top, plot.width_px - left - right, plot.height_px - top - bottom), range};
  cv::Mat canvas(plot.height_px, plot.width_px, CV_8UC3, cv::Scalar(255, 255, 255));
  drawAxes(canvas, frame, yTicks);
  drawSeries(canvas, frame, plot, bins);
  drawLegend(canvas, frame.area, plot);
  drawLabels(canvas, frame.area, top, plot);
  detail::savePng(path, canvas);
}

}  // namespace tofsim::imaging
