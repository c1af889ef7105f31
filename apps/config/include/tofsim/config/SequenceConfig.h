#pragma once
// The `sequence:` section of a run config: a capture sequence of an animated
// scene (glTF animations, tofsim/scene/AnimatedScene.h). Each frame is
// rendered at its own time of scene time, the scene prepared once and
// updated per frame; a CW-ToF sensor takes each of its raw frames at that
// raw's own time within the frame (capture_order, integration_time,
// readout_gap), so what moves between raws gives the device's motion
// artifacts. Outputs: configs/README.md, `sequence`.

#include <cstdint>
#include <vector>

#include "tofsim/util/Error.h"

namespace tofsim::config {

struct SequenceConfig {
  /// Scene time of frame 0, s (with rate and count).
  double start_s = 0.0;
  /// Frames per second of scene time (with count); 0: the list `times`.
  double rate_Hz = 0.0;
  int32_t count = 0;  ///< frames (with rate)
  /// The frames' times, s, increasing: start + k / rate, or the list given.
  std::vector<double> times_s;
  /// Samples of an exposure that moves (a CW-ToF raw's integration_time, a
  /// SPAD's exposure_time), at the midpoints of equal parts of it (1: its middle).
  int32_t exposure_samples = 1;
  /// sequence.mp4 of the frames' steady images.
  bool video = true;
  /// Where `sequence:` is, for the errors found with the scene (frame times
  /// outside its animations).
  FileLoc at;
};

}  // namespace tofsim::config
