#pragma once
// Private to the config module: `camera.lens`, a calibrated camera's OpenCV
// intrinsics (capture::Lens), given in the config (camera_matrix, distortion)
// or as the calibration file OpenCV writes (calibration: a cv::FileStorage
// YAML, e.g. calibrateCamera's or the camera_calibration sample's output), so
// that a camera's calibration plugs in unchanged. Every bad value is an
// InputError located in the file it came from.

#include <glm/glm.hpp>
#include <optional>
#include <string>

#include "ConfigNode.h"
#include "tofsim/capture/Lens.h"

namespace tofsim::config {

struct ParsedLens {
  capture::Lens lens;
  /// The calibration file (absolute), empty when the values were inline.
  std::string calibration_file;
  /// image_width, image_height from the calibration file, where it has them.
  std::optional<glm::ivec2> image_size;
};

/// The `lens` mapping of the camera node `camera`.
ParsedLens parseLens(const ConfigNode& camera);

/// How many of the 14 coefficients to write: the shortest of OpenCV's
/// lengths (4, 5, 8, 12, 14) that holds every non-zero one.
std::size_t distortionCount(const capture::Lens& lens);

}  // namespace tofsim::config
