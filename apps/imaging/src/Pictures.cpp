#include "tofsim/imaging/Pictures.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "PngFile.h"
#include "tofsim/util/Error.h"

namespace tofsim::imaging {

using detail::savePng;

void writeToneMappedPng(const std::filesystem::path& path, const Image& image, ToneMap mode,
                        const std::optional<std::array<double, 2>>& range) {
  TOFSIM_CHECK(image.channels == 1 || image.channels == 3);
  const double black = range ? (*range)[0] : 0.0;
  const double white =
      range ? (*range)[1] - black : detail::whiteLevel(image.data.data(), image.data.size());
  cv::Mat out(image.height, image.width, CV_8UC3);
  for (int32_t y = 0; y < image.height; ++y) {
    for (int32_t x = 0; x < image.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        const double v = image.at(y, x, image.channels == 3 ? c : 0) - black;
        out.at<cv::Vec3b>(y, x)[2 - c] = detail::toneMapped8(v, white, mode);  // OpenCV: BGR
      }
    }
  }
  savePng(path, out);
}

}  // namespace tofsim::imaging
