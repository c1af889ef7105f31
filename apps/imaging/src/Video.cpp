#include "tofsim/imaging/Video.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <vector>

#include "PngFile.h"
#include "VideoModule.h"
#include "tofsim/util/Error.h"

namespace tofsim::imaging {

namespace {

constexpr int32_t kMinSide = 256;
constexpr int32_t kBand = 24;  // pixels below the image for the time stamp

// The bins of one frame's window, read once each as the frames advance.
class BinWindow {
 public:
  explicit BinWindow(const BinFrames& frames) : frames_(frames) {}
  // Bins first .. last (first never decreasing from call to call).
  const std::map<int32_t, std::vector<float>>& bins(int32_t first, int32_t last) {
    bins_.erase(bins_.begin(), bins_.lower_bound(first));
    const std::size_t floats =
        static_cast<std::size_t>(frames_.width) * frames_.height * frames_.channels;
    for (int32_t b = first; b <= last; ++b) {
      if (bins_.count(b)) continue;
      std::vector<float>& values = bins_[b];
      values.resize(floats);
      frames_.readBin(b, values.data());
    }
    return bins_;
  }

 private:
  const BinFrames& frames_;
  std::map<int32_t, std::vector<float>> bins_;
};

cv::Mat frameOf(const BinFrames& frames, BinWindow& window, int32_t t, int32_t width, ToneMap mode,
                const FrameSize& size) {
  const int32_t first = std::max(0, t - (width - 1) / 2);
  const int32_t last = std::min(frames.axis.bins - 1, t + width / 2);
  const std::map<int32_t, std::vector<float>>& bins = window.bins(first, last);
  const int32_t W = frames.width, H = frames.height, channels = frames.channels;
  cv::Mat small(H, W, CV_8UC3);
  for (int32_t y = 0; y < H; ++y) {
    for (int32_t x = 0; x < W; ++x) {
      const std::size_t pixel = (static_cast<std::size_t>(y) * W + x) * channels;
      for (int c = 0; c < 3; ++c) {
        double v = 0.0;
        for (int32_t b = first; b <= last; ++b) {
          v += bins.at(b)[pixel + (channels >= 3 ? c : 0)];
        }
        small.at<cv::Vec3b>(y, x)[2 - c] =
            detail::toneMapped8(v, frames.white, mode);  // OpenCV: BGR
      }
    }
  }
  const int32_t k = (size.height - kBand) / H;
  cv::Mat frame(size.height, size.width, CV_8UC3, cv::Scalar(0, 0, 0));
  cv::Mat scaled;
  cv::resize(small, scaled, cv::Size(W * k, H * k), 0, 0, cv::INTER_NEAREST);
  scaled.copyTo(frame(cv::Rect(0, 0, scaled.cols, scaled.rows)));
  std::string stamp;
  if (frames.stamp) {
    stamp = frames.stamp(t);
  } else {
    const double t_s = frames.axis.binCenter_s(t);
    char text[96];
    std::snprintf(text, sizeof text, "t = %.3f ns (%.3f m)", t_s * 1e9, t_s * 299792458.0);
    stamp = text;
  }
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

BinFrames binFramesOf(const TransientVolume& volume) {
  BinFrames frames;
  frames.width = volume.width();
  frames.height = volume.height();
  frames.channels = volume.channels();
  frames.axis = volume.axis();
  frames.white = detail::whiteLevel(volume.data(), volume.size());
  frames.readBin = [&volume](int32_t t, float* out) {
    for (int32_t y = 0; y < volume.height(); ++y) {
      for (int32_t x = 0; x < volume.width(); ++x) {
        for (int32_t c = 0; c < volume.channels(); ++c) *out++ = volume.at(y, x, t, c);
      }
    }
  };
  return frames;
}

void requireVideoEncoder() { detail::loadVideoModule(); }

void writeTransientVideo(const std::filesystem::path& mp4Path, const BinFrames& frames,
                         const VideoOptions& options, const std::filesystem::path& pngDirectory) {
  TOFSIM_CHECK(options.stride >= 1 && options.window >= 1);
  const FrameSize size = videoFrameSize(frames.width, frames.height);
  BinWindow window(frames);
  // OpenCV picks the container from the file name, so the temporary keeps
  // the .mp4 extension.
  std::filesystem::path temp = mp4Path;
  temp.replace_extension(".tmp.mp4");
  std::optional<detail::Mp4Writer> writer;
  if (!mp4Path.empty()) writer.emplace(temp, options.fps, size.width, size.height);
  if (!pngDirectory.empty()) std::filesystem::create_directories(pngDirectory);
  try {
    for (int32_t t = 0; t < frames.axis.bins; t += options.stride) {
      const cv::Mat frame = frameOf(frames, window, t, options.window, options.toneMap, size);
      if (writer) writer->write(frame.data, frame.step);
      if (!pngDirectory.empty()) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%05d.png", t);
        detail::savePng(pngDirectory / name, frame);
      }
    }
    if (writer) {
      writer->close();
      std::filesystem::rename(temp, mp4Path);
    }
  } catch (...) {
    writer.reset();
    std::error_code ec;
    if (!mp4Path.empty()) std::filesystem::remove(temp, ec);
    throw;
  }
}

}  // namespace tofsim::imaging
