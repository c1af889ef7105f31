#pragma once
// Line plots for people (PNG through OpenCV): a few curves over a common,
// evenly spaced x axis, e.g. SPAD histograms of selected pixels.

#include <filesystem>
#include <string>
#include <vector>

namespace tofsim::imaging {

struct LinePlot {
  /// One curve per entry, all of the same length (bins); point i is drawn at
  /// the centre of bin i, x = x0 + (i + 0.5) dx.
  std::vector<std::vector<float>> series;
  std::vector<std::string> labels;  ///< legend, one per series (missing: "series N")
  double x0 = 0.0;                  ///< leading edge of bin 0, in xUnit
  double dx = 1.0;                  ///< bin width, in xUnit, > 0
  std::string xUnit;                ///< e.g. "ns"
  std::string xLabel;               ///< what x is, e.g. "arrival time"; shown as "xLabel [xUnit]"
  std::string yLabel;               ///< e.g. "counts"
  std::string title;
  int width_px = 800;
  int height_px = 500;
};

/// Draws axes with ticks and values, the curves, a legend and the title.
/// The y axis starts at 0 unless a value is negative. Written atomically.
void writeLinePlotPng(const std::filesystem::path& path, const LinePlot& plot);

}  // namespace tofsim::imaging
