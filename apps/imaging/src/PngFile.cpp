#include "PngFile.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <map>
#include <opencv2/imgproc.hpp>
#include <string_view>
#include <vector>

#include "tofsim/imaging/WhiteLevel.h"
#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Error.h"

namespace tofsim::imaging::detail {

double whiteLevel(const float* values, std::size_t count) {
  WhiteLevelSampler sampler(count);
  sampler.add(values, count);
  return sampler.white();
}

unsigned char toneMapped8(double value, double white, ToneMap mode) {
  const double mapped = mode == ToneMap::Log
                            ? (value > 0.0 ? 1.0 + std::log10(value / white) / 4.0 : 0.0)
                            : value / white;
  const double v = std::clamp(mapped, 0.0, 1.0);
  const double s = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  return static_cast<unsigned char>(std::lround(s * 255.0));
}

namespace {

void appendBytes(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + length);
}

[[noreturn]] void pngError(png_structp png, png_const_charp message) {
  *static_cast<std::string*>(png_get_error_ptr(png)) = message;
  png_longjmp(png, 1);
}

void pngWarning(png_structp, png_const_charp) {}

}  // namespace

// libpng rather than OpenCV's imgcodecs: imgcodecs links ~140 libraries
// (GDAL, DICOM, HEIF...) whose loading cost every process 0.05 s.
void savePng(const std::filesystem::path& path, const cv::Mat& bgr) {
  TOFSIM_CHECK(bgr.depth() == CV_8U && (bgr.channels() == 1 || bgr.channels() == 3));
  std::vector<unsigned char> bytes;
  std::string error;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, pngError, pngWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (png == nullptr || info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    throw InputError(FileLoc{path.string()}, "", "PNG encoding failed: out of memory");
  }
  if (setjmp(png_jmpbuf(png))) {  // libpng's errors come back here
    png_destroy_write_struct(&png, &info);
    throw InputError(FileLoc{path.string()}, "", "PNG encoding failed: " + error);
  }
  png_set_write_fn(png, &bytes, appendBytes, nullptr);
  png_set_compression_level(png, 1);  // OpenCV's default: fast, pictures of a few 100 kB
  png_set_IHDR(png, info, static_cast<png_uint_32>(bgr.cols), static_cast<png_uint_32>(bgr.rows), 8,
               bgr.channels() == 3 ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  if (bgr.channels() == 3) png_set_bgr(png);  // OpenCV's order in memory
  for (int y = 0; y < bgr.rows; ++y) png_write_row(png, bgr.ptr<unsigned char>(y));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  writeFileAtomically(path,
                      std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

int colormapCode(const std::string& name) {
  static const std::map<std::string, int> codes = {
      {"autumn", cv::COLORMAP_AUTUMN},     {"bone", cv::COLORMAP_BONE},
      {"jet", cv::COLORMAP_JET},           {"winter", cv::COLORMAP_WINTER},
      {"rainbow", cv::COLORMAP_RAINBOW},   {"ocean", cv::COLORMAP_OCEAN},
      {"summer", cv::COLORMAP_SUMMER},     {"spring", cv::COLORMAP_SPRING},
      {"cool", cv::COLORMAP_COOL},         {"hsv", cv::COLORMAP_HSV},
      {"pink", cv::COLORMAP_PINK},         {"hot", cv::COLORMAP_HOT},
      {"parula", cv::COLORMAP_PARULA},     {"magma", cv::COLORMAP_MAGMA},
      {"inferno", cv::COLORMAP_INFERNO},   {"plasma", cv::COLORMAP_PLASMA},
      {"viridis", cv::COLORMAP_VIRIDIS},   {"cividis", cv::COLORMAP_CIVIDIS},
      {"twilight", cv::COLORMAP_TWILIGHT}, {"twilight_shifted", cv::COLORMAP_TWILIGHT_SHIFTED},
      {"turbo", cv::COLORMAP_TURBO},       {"deepgreen", cv::COLORMAP_DEEPGREEN},
  };
  const auto it = codes.find(name);
  return it == codes.end() ? cv::COLORMAP_TURBO : it->second;
}

// Tick positions covering [lo, hi] at a step of 1, 2 or 5 times a power of
// ten, about `wanted` of them: the spacing people read without effort.
std::vector<double> niceTicks(double lo, double hi, int wanted) {
  const double raw = (hi - lo) / std::max(1, wanted);
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power * 10.0;
  for (double m : {1.0, 2.0, 5.0}) {
    if (power * m >= raw) {
      step = power * m;
      break;
    }
  }
  std::vector<double> ticks;
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step) {
    ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
  }
  return ticks;
}

void applyColormap(const cv::Mat& gray, cv::Mat& bgr, const std::string& name) {
  if (name != "coolwarm") {
    cv::applyColorMap(gray, bgr, colormapCode(name));
    return;
  }
  // Moreland's diverging cool-warm map (matplotlib's "coolwarm"): blue,
  // light grey at the centre, red; linear in RGB between the three, which
  // keeps the centre (0 for a signed quantity) the lightest colour.
  static const cv::Mat lut = [] {
    const double blue[3] = {192, 76, 59}, mid[3] = {221, 221, 221}, red[3] = {38, 4, 180};  // BGR
    cv::Mat m(256, 1, CV_8UC3);
    for (int i = 0; i < 256; ++i) {
      const double u = i / 255.0;
      const double* a = u < 0.5 ? blue : mid;
      const double* b = u < 0.5 ? mid : red;
      const double w = u < 0.5 ? 2.0 * u : 2.0 * u - 1.0;
      for (int c = 0; c < 3; ++c) {
        m.at<cv::Vec3b>(i, 0)[c] =
            static_cast<unsigned char>(std::lround(a[c] + (b[c] - a[c]) * w));
      }
    }
    return m;
  }();
  cv::applyColorMap(gray, bgr, lut);
}

std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

void drawText(cv::Mat& canvas, const std::string& text, cv::Point origin, double scale) {
  cv::putText(canvas, text, origin, cv::FONT_HERSHEY_SIMPLEX, scale, {0, 0, 0}, 1, cv::LINE_AA);
}

cv::Size textSize(const std::string& text, double scale) {
  int baseline = 0;
  return cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &baseline);
}

std::vector<std::string> wrapText(const std::string& text, int maxWidth, double scale) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find(' ', begin);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(begin, end - begin);
    const std::string longer = line.empty() ? word : line + " " + word;
    if (!line.empty() && textSize(longer, scale).width > maxWidth) {
      lines.push_back(line);
      line = word;
    } else {
      line = longer;
    }
    begin = end + 1;
  }
  if (!line.empty() || lines.empty()) lines.push_back(line);
  return lines;
}

}  // namespace tofsim::imaging::detail
