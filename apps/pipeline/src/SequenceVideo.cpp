#include "SequenceVideo.h"

#include <algorithm>
#include <cstdio>

#include "tofsim/imaging/WhiteLevel.h"
#include "tofsim/io/Exr.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline {

imaging::VideoOptions videoOptions(const config::OutputConfig& out) {
  imaging::VideoOptions options;
  options.toneMap = out.video_tone_map == config::VideoToneMap::Log ? imaging::ToneMap::Log
                                                                    : imaging::ToneMap::Global;
  options.stride = out.video_stride;
  options.window = out.video_window;
  options.fps = out.video_fps;
  return options;
}

void writeSequenceVideo(const std::filesystem::path& mp4, const config::OutputConfig& out,
                        const std::vector<std::filesystem::path>& steadyFiles,
                        const std::vector<double>& times_s, const Progress& progress) {
  TOFSIM_CHECK(!steadyFiles.empty() && steadyFiles.size() == times_s.size());
  std::vector<Image> images;
  for (const std::filesystem::path& f : steadyFiles) {
    images.push_back(io::readExr(f));
    TOFSIM_CHECK(images.back().width == images.front().width &&
                 images.back().height == images.front().height &&
                 images.back().channels == images.front().channels);
  }
  const Image& first = images.front();
  imaging::WhiteLevelSampler white(first.data.size() * images.size());
  for (const Image& i : images) white.add(i.data.data(), i.data.size());

  // A "volume" whose bins are the frames.
  imaging::BinFrames frames;
  frames.width = first.width;
  frames.height = first.height;
  frames.channels = first.channels;
  frames.axis.bins = static_cast<int32_t>(images.size());
  frames.white = white.white();
  frames.readBin = [&](int32_t k, float* dst) {
    std::copy(images[k].data.begin(), images[k].data.end(), dst);
  };
  frames.stamp = [&](int32_t k) {
    char text[64];
    std::snprintf(text, sizeof text, "frame %d: t = %.4f s", k, times_s[k]);
    return std::string(text);
  };
  // One frame per frame, each alone: the tone map is the output keys'.
  imaging::VideoOptions options;
  options.toneMap = videoOptions(out).toneMap;
  // The scene's own pace: frames as far apart in the video as in scene time.
  const double span = times_s.back() - times_s.front();
  options.fps = times_s.size() > 1 && span > 0.0 ? (times_s.size() - 1) / span : 1.0;
  progress.message("sequence video: " + std::to_string(images.size()) + " frame(s)");
  imaging::writeTransientVideo(mp4, frames, options);
}

}  // namespace tofsim::pipeline
