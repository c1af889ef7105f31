#pragma once
// Private to the config module: `camera.lens`, a calibrated camera's OpenCV
// intrinsics (capture::Lens), given in the config (camera_matrix, distortion)
// or as the calibration file OpenCV writes (calibration: a cv::FileStorage
// YAML, e.g. calibrateCamera's or the camera_calibration sample's output), so
// that a camera's calibration plugs in unchanged. Every bad value is an
// InputError located in the file it came from.

#include <glm/glm.hpp>
#include <optional>
#include <cstdint>
#include <string>

#include "ConfigNode.h"
#include "tofsim/capture/Lens.h"

namespace tofsim::config {

struct ParsedLens {
  capture::Lens lens;
  /// The calibration file (absolute), empty when the values were inline.
  std::string calibration_file;
  /// image_width, image_height from the calibration file (required there).
  std::optional<glm::ivec2> image_size;
  /// Where the camera matrix was given (its file, line and key path).
  FileLoc matrix_at;
  std::string matrix_key;
};

/// fx, fy, cx, cy in pixels must be sane for a width x height image: focal
/// lengths within [1/1000, 1000] x the larger side (fields of view between
/// about 0.06 and 179.9 degrees), the principal point at most one image size
/// outside the image. Checked before the distortion's inversion, whose
/// errors such values would only obscure. A located error at the matrix.
void checkIntrinsics(const ParsedLens& lens, int32_t width, int32_t height);

/// The `lens` mapping of the camera node `camera`.
ParsedLens parseLens(const ConfigNode& camera);

/// How many of the 14 coefficients to write: the shortest of OpenCV's
/// lengths (4, 5, 8, 12, 14) that holds every non-zero one.
std::size_t distortionCount(const capture::Lens& lens);

}  // namespace tofsim::config
