#pragma once
// Light in flight as a video: one frame per time bin (or every `stride`-th
// bin) of a transient volume, tone-mapped with ONE scale for the whole video
// so that brightness is comparable between frames, each frame stamped with
// its time ("t = 5.433 ns (1.629 m)": the bin centre, and the optical path
// c·t). MP4 (MPEG-4 part 2, fourcc 'mp4v') through OpenCV's VideoWriter.
//
// Tone maps (the scale is the 99.5th percentile `white` of all positive
// values of all frames):
//   Global: v / white, clamped to [0, 1], then sRGB-encoded.
//   Log:    1 + log10(v / white) / 4: four decades below white fill the
//           range (dim indirect light stays visible), then sRGB-encoded.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "tofsim/imaging/Pictures.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::imaging {

struct VideoOptions {
  ToneMap toneMap = ToneMap::Global;
  int32_t stride = 1;  ///< one frame every `stride` bins, >= 1
  /// Exposure of a frame in bins, >= 1: frame t sums bins
  /// [t - (window - 1) / 2, t + window / 2], like a gated camera's shutter,
  /// so a wavefront shows with the width of the window instead of one bin.
  int32_t window = 1;
  double fps = 30.0;
};

/// Frames are the image scaled up by an integer factor k = ceil(256 / min(W, H))
/// (nearest neighbour, so pixels stay visible), plus a 24-pixel band at the
/// bottom for the time stamp, rounded up to even sizes (the encoder needs them).
struct FrameSize {
  int32_t width = 0;
  int32_t height = 0;
};
FrameSize videoFrameSize(int32_t imageWidth, int32_t imageHeight);

/// Number of frames for `bins` time bins: ceil(bins / stride).
int32_t videoFrameCount(int32_t bins, int32_t stride);

/// A volume as the video reads it: one time bin of every pixel at a time
/// (from memory, or from a bin-major file when the volume is not held).
struct BinFrames {
  int32_t width = 0, height = 0, channels = 0;
  TimeAxis axis;
  /// The tone maps' white: WhiteLevelSampler's over the volume's values in
  /// (y, x, t, c) order (WhiteLevel.h).
  double white = 1.0;
  /// Fills `out` with bin t: width * height * channels floats, (y, x, c) order.
  std::function<void(int32_t t, float* out)> readBin;
  /// The stamp of the frame of bin t; unset: its time and optical path
  /// (a sequence's frames say their scene time instead).
  std::function<std::string(int32_t t)> stamp;
};

/// The frames of a volume in memory.
BinFrames binFramesOf(const TransientVolume& volume);

/// Loads the MP4 encoder (a module of its own, loaded on first use); throws
/// InputError when it cannot be: a run that will write a video asks first.
void requireVideoEncoder();

/// Writes the video atomically (an empty mp4Path: only the PNGs) (to "<stem>.tmp.mp4", renamed when
/// complete). With `pngDirectory` not empty, also writes each frame as pngDirectory/frame_NNNNN.png
/// (NNNNN = the time bin). Holds the bins of one frame's window. Throws InputError when OpenCV
/// cannot encode MP4.
void writeTransientVideo(const std::filesystem::path& mp4Path, const BinFrames& frames,
                         const VideoOptions& options,
                         const std::filesystem::path& pngDirectory = {});

}  // namespace tofsim::imaging
