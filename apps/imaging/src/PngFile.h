#pragma once
// Private to the imaging module: PNG encoding and the drawing helpers the
// picture writers share.

#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "tofsim/imaging/Pictures.h"

namespace tofsim::imaging::detail {

/// WhiteLevelSampler's white of `count` floats (WhiteLevel.h): the white point
/// of both tone maps.
double whiteLevel(const float* values, std::size_t count);

/// One linear value as an 8-bit sRGB byte under a tone map: Global maps
/// `white` to 255 linearly, Log maps four decades below `white` to [0, 255].
unsigned char toneMapped8(double value, double white, ToneMap mode);

/// Encodes `bgr` as PNG in memory, then writes it atomically (the file
/// appears under its name only when complete).
void savePng(const std::filesystem::path& path, const cv::Mat& bgr);

/// OpenCV's COLORMAP_* for a matplotlib-style name; unknown names give turbo,
/// so a misspelt colormap still produces a readable picture.
int colormapCode(const std::string& name);

/// gray (CV_8UC1) through the colormap `name` into bgr: colormapCode's maps,
/// and "coolwarm", a diverging map whose centre (128) is light grey.
void applyColormap(const cv::Mat& gray, cv::Mat& bgr, const std::string& name);

/// Tick positions covering [lo, hi] at a step of 1, 2 or 5 times a power of
/// ten, about `wanted` of them.
std::vector<double> niceTicks(double lo, double hi, int wanted);

/// "%.4g" of a value, for tick and colour-bar labels.
std::string shortNumber(double value);

/// Text in the Hershey simplex font, black, anti-aliased; `origin` is the
/// baseline's left end.
void drawText(cv::Mat& canvas, const std::string& text, cv::Point origin, double scale = 0.45);
/// Width and height in pixels of drawText's rendering.
cv::Size textSize(const std::string& text, double scale = 0.45);

/// `text` broken at spaces into lines no wider than maxWidth pixels (a
/// single word wider than that gets a line of its own).
std::vector<std::string> wrapText(const std::string& text, int maxWidth, double scale = 0.45);

}  // namespace tofsim::imaging::detail
