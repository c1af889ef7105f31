#include "tofsim/imaging/Video.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <vector>

#include "PngFile.h"
#include "tofsim/util/Error.h"

namespace tofsim::imaging {

namespace {

constexpr int32_t kMinSide = 256;
constexpr int32_t kBand = 24;  // pixels below the image for the time stamp



cv::Mat frameOf(const TransientVolume& volume, int32_t t, int32_t window, double white,
                ToneMap mode, const FrameSize& size) {
  const int32_t first = std::max(0, t - (window - 1) / 2);
  const int32_t last = std::min(volume.bins() - 1, t + window / 2);
  cv::Mat small(volume.height(), volume.width(), CV_8UC3);
  const int32_t channels = volume.channels();
  for (int32_t y = 0; y < volume.height(); ++y) {
    for (int32_t x = 0; x < volume.width(); ++x) {
      for (int c = 0; c < 3; ++c) {
        double v = 0.0;
        for (int32_t b = first; b <= last; ++b) v += volume.at(y, x, b, channels >= 3 ? c : 0);
        small.at<cv::Vec3b>(y, x)[2 - c] = detail::toneMapped8(v, white, mode);  // OpenCV: BGR
      }
    }
  }
  const int32_t k = (size.height - kBand) / volume.height();
  cv::Mat frame(size.height, size.width, CV_8UC3, cv::Scalar(0, 0, 0));
  cv::Mat scaled;
  cv::resize(small, scaled, cv::Size(volume.width() * k, volume.height() * k), 0, 0,
             cv::INTER_NEAREST);
  scaled.copyTo(frame(cv::Rect(0, 0, scaled.cols, scaled.rows)));
  const double t_s = volume.axis().binCenter_s(t);
  char stamp[96];
  std::snprintf(stamp, sizeof stamp, "t = %.3f ns (%.3f m)", t_s * 1e9, t_s * 299792458.0);
  cv::putText(frame, stamp, cv::Point(4, size.height - 7), cv::FONT_HERSHEY_SIMPLEX, 0.45,
              cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
  return frame;
}

}  // namespace

FrameSize videoFrameSize(int32_t imageWidth, int32_t imageHeight) {
  const int32_t side = std::max(1, std::min(imageWidth, imageHeight));
  const int32_t k = std::max(1, (kMinSide + side - 1) / side);
  const auto even = [](int32_t v) { return v + (v & 1); };
  return {even(imageWidth * k), even(imageHeight * k + kBand)};
}

int32_t videoFrameCount(int32_t bins, int32_t stride) { return (bins + stride - 1) / stride; }

void writeTransientVideo(const std::filesystem::path& mp4Path, const TransientVolume& volume,
                         const VideoOptions& options, const std::filesystem::path& pngDirectory) {
  TOFSIM_CHECK(options.stride >= 1 && options.window >= 1);
  const FrameSize size = videoFrameSize(volume.width(), volume.height());
  const double white = detail::whiteLevel(volume.data(), volume.size());
  // OpenCV picks the container from the file name, so the temporary keeps
  // the .mp4 extension.
  std::filesystem::path temp = mp4Path;
  temp.replace_extension(".tmp.mp4");
  cv::VideoWriter writer;
  if (!mp4Path.empty()) {
    writer.open(temp.string(), cv::VideoWriter::fourcc('m', 'p', '4', 'v'), options.fps,
                cv::Size(size.width, size.height), true);
  }
  if (!mp4Path.empty() && !writer.isOpened()) {
    throw InputError(mp4Path.string() +
                     ": OpenCV cannot write MP4 (fourcc mp4v); is its FFmpeg "
                     "video I/O backend installed (libopencv-videoio)?");
  }
  if (!pngDirectory.empty()) std::filesystem::create_directories(pngDirectory);
  try {
    for (int32_t t = 0; t < volume.bins(); t += options.stride) {
      const cv::Mat frame = frameOf(volume, t, options.window, white, options.toneMap, size);
      if (writer.isOpened()) writer.write(frame);
      if (!pngDirectory.empty()) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%05d.png", t);
        detail::savePng(pngDirectory / name, frame);
      }
    }
    if (writer.isOpened()) {
      writer.release();
      std::filesystem::rename(temp, mp4Path);
    }
  } catch (...) {
    writer.release();
    std::error_code ec;
    if (!mp4Path.empty()) std::filesystem::remove(temp, ec);
    throw;
  }
}

}  // namespace tofsim::imaging
