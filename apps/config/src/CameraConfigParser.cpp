#include "CameraConfigParser.h"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "CameraFields.h"
#include "FieldParse.h"
#include "LensConfig.h"
#include "PsfConfig.h"
#include "ShortestNumber.h"
#include "SpadTableFile.h"

namespace tofsim::config {

namespace {

// The largest gain a vignetting map may hold (configs/README.md).
constexpr double kMaxVignettingGain = 1000.0;

// camera.vignetting: none, cos4 or a .npy map of the camera's size.
capture::Vignetting parseVignetting(const ConfigNode& node, const capture::Camera& camera) {
  capture::Vignetting v;
  const std::string text = node.getString("vignetting", "none");
  if (text == "none") return v;
  if (text == "cos4") {
    v.kind = capture::Vignetting::Kind::Cos4;
    return v;
  }
  if (text.size() < 4 || text.substr(text.size() - 4) != ".npy") {
    node.failKey("vignetting", "must be none, cos4 or a .npy map of gains (got '" + text + "')");
  }
  PixelMap map = readPixelMap(node, "vignetting", "vignetting map", "gain");
  if (map.width != camera.width || map.height != camera.height) {
    node.failKey("vignetting", map.file + ": a " + std::to_string(map.height) + " x " +
                                   std::to_string(map.width) + " map for a " +
                                   std::to_string(camera.height) + " x " +
                                   std::to_string(camera.width) + " (H x W) image");
  }
  // A flat field's gains are near 1. Far larger ones would overflow float
  // in radiance x gain (3e38 turned most values infinite, written as 0), and
  // a map of zeros makes every pixel black.
  std::size_t largest = 0;
  for (std::size_t k = 1; k < map.values.size(); ++k) {
    if (map.values[k] > map.values[largest]) largest = k;
  }
  if (map.values[largest] > kMaxVignettingGain) {
    node.failKey("vignetting", map.file + ": gain " +
                                   shortest(static_cast<float>(map.values[largest])) +
                                   " at (y, x) = (" + std::to_string(largest / map.width) + ", " +
                                   std::to_string(largest % map.width) + ") is over " +
                                   std::to_string(static_cast<int>(kMaxVignettingGain)) +
                                   " (a flat field's gains are near 1)");
  }
  if (map.values[largest] == 0.0) {
    node.failKey("vignetting", map.file + ": every gain is 0, which makes every pixel black");
  }
  v.kind = capture::Vignetting::Kind::Map;
  v.width = map.width;
  v.height = map.height;
  v.file = map.file;
  v.map.assign(map.values.begin(), map.values.end());
  return v;
}

// camera.aperture, focus_distance, aperture_samples (read by the table):
// thin-lens defocus (capture/ThinLens.h). The last two mean nothing without
// an aperture, so giving them alone is an error rather than silently ignored.
void checkAperture(const ConfigNode& node, const capture::Camera& c) {
  if (!(c.aperture_m >= 0.0f && std::isfinite(c.aperture_m))) {
    node.failKey("aperture", "must be a diameter >= 0 m (0: a pinhole; got " +
                                 std::to_string(c.aperture_m) + ")");
  }
  if (!c.defocused()) {
    for (const char* key : {"focus_distance", "aperture_samples"}) {
      if (node.has(key)) {
        node.failKey(key, "needs camera.aperture > 0 (a pinhole is in focus at every depth)");
      }
    }
    return;
  }
  if (!node.has("focus_distance")) {
    node.failKey("aperture", "an aperture needs camera.focus_distance, the depth in focus (m)");
  }
  if (!(c.focus_distance_m > 0.0f && std::isfinite(c.focus_distance_m))) {
    node.failKey("focus_distance", "must be > 0 m with an aperture (got " +
                                       std::to_string(c.focus_distance_m) + ")");
  }
  if (c.aperture_samples < 2 || c.aperture_samples > 4096) {
    node.failKey("aperture_samples", "must be in [2, 4096] with an aperture (got " +
                                         std::to_string(c.aperture_samples) +
                                         "; one point is a pinhole moved off the axis)");
  }
}

// camera.resolution: two integers, by default the calibration's image size;
// a lens's intrinsics are checked against the image it is for.
void parseResolution(const ConfigNode& node, const std::optional<ParsedLens>& lens,
                     CameraConfig& out) {
  capture::Camera& c = out.camera;
  std::vector<double> defaultResolution = {64.0, 64.0};
  if (lens && lens->image_size)
    defaultResolution = {double(lens->image_size->x), double(lens->image_size->y)};
  const std::vector<double> res = node.getDoubles("resolution", 2, defaultResolution);
  for (double r : res) {
    if (r < 1 || r > 16384 || r != std::floor(r)) {
      node.failKey("resolution", "must be two integers in [1, 16384] (width, height)");
    }
  }
  c.width = static_cast<int32_t>(res[0]);
  c.height = static_cast<int32_t>(res[1]);
  if (!lens) return;
  // A calibration holds for the image it was made at: another resolution
  // would need the camera matrix scaled, which is the user's to state.
  if (lens->image_size && *lens->image_size != glm::ivec2(c.width, c.height)) {
    node.failKey("resolution", "differs from the calibration's image size " +
                                   std::to_string(lens->image_size->x) + " x " +
                                   std::to_string(lens->image_size->y) + " (" +
                                   lens->calibration_file + ")");
  }
  checkIntrinsics(*lens, c.width, c.height);
  try {
    capture::checkLensInvertible(lens->lens, c.width, c.height);
  } catch (const InputError& e) {
    node.failKey("lens", e.what());
  }
  c.lens = lens->lens;
  out.lens_calibration = lens->calibration_file;
}

}  // namespace

void parseCamera(const ConfigNode& node, CameraConfig& out) {
  capture::Camera& c = out.camera;
  std::optional<ParsedLens> lens;
  parseFields(node, kCameraFields, out, [&](const std::string& key) {
    if (key == "lens" && node.has("lens")) {
      if (node.has("fov_y")) {
        node.failKey("fov_y", "a lens's camera matrix sets the field of view: give fov_y or lens");
      }
      lens = parseLens(node);
    } else if (key == "resolution") {
      // fov_y, read between the lens and here, is checked before the image.
      if (!(c.fov_y_deg > 0.0f && c.fov_y_deg < 180.0f)) {
        node.failKey("fov_y", "must be in (0, 180) degrees");
      }
      parseResolution(node, lens, out);
    } else if (key == "vignetting") {
      out.vignetting = parseVignetting(node, c);
    } else if (key == "psf" && node.has("psf")) {
      out.psf = parsePsf(node, c.width, c.height);
    }
  });
  checkAperture(node, c);
  if (out.gltf_camera.empty()) {
    const glm::vec3 forward = c.look_at_world - c.position_world;
    if (glm::length(forward) <= 0.0f) node.failKey("look_at", "must differ from position");
    if (glm::length(glm::cross(forward, c.up_world)) <= 1e-6f * glm::length(forward)) {
      node.failKey("up", "must not be parallel to the view direction");
    }
  }
}

}  // namespace tofsim::config
