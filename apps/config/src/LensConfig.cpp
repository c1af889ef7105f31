#include "LensConfig.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

#include "ConfigPath.h"
#include "ShortestNumber.h"
#include "YamlText.h"

namespace tofsim::config {

namespace {

// OpenCV's lengths of the distortion vector (cv::projectPoints).
constexpr std::array<std::size_t, 5> kDistortionLengths = {4, 5, 8, 12, 14};

// The numbers of `key`: a list (nested lists, as a 3 x 3 matrix, flattened)
// or a cv::FileStorage matrix ({rows, cols, dt, data}).
std::vector<double> numbersOf(const ConfigNode& node, const std::string& key) {
  const ConfigNode c = node.child(key);
  std::vector<double> out;
  if (c.isMap()) {
    const long long rows = c.getInt("rows", -1), cols = c.getInt("cols", -1);
    c.markUsed("dt");
    const ConfigNode data = c.child("data");
    if (!data.isSequence()) data.fail("expected a list of numbers");
    for (const ConfigNode& e : data.elements()) out.push_back(e.asDouble());
    if (rows < 0 || cols < 0 || static_cast<std::size_t>(rows * cols) != out.size()) {
      c.fail("rows x cols (" + std::to_string(rows) + " x " + std::to_string(cols) +
             ") must equal the number of values in data (" + std::to_string(out.size()) + ")");
    }
    return out;
  }
  if (!c.isSequence()) c.fail("expected a list of numbers or an OpenCV matrix");
  for (const ConfigNode& e : c.elements()) {
    if (e.isSequence()) {
      for (const ConfigNode& v : e.elements()) out.push_back(v.asDouble());
    } else {
      out.push_back(e.asDouble());
    }
  }
  return out;
}

// The first of `names` the node has, or "" when none.
std::string firstKey(const ConfigNode& node, std::initializer_list<const char*> names) {
  for (const char* name : names) {
    if (node.has(name)) return name;
  }
  return "";
}

void setCameraMatrix(const ConfigNode& node, const std::string& key, ParsedLens& out) {
  capture::Lens& lens = out.lens;
  out.matrix_at = node.locationOf(key);
  out.matrix_key = node.pathOf(key);
  const std::vector<double> m = numbersOf(node, key);
  if (m.size() != 9) {
    node.failKey(key, "expected the 3 x 3 camera matrix (9 numbers, row by row), got " +
                          std::to_string(m.size()));
  }
  for (const double v : m) {
    if (!std::isfinite(v)) node.failKey(key, "must be finite");
  }
  // OpenCV's projection reads fx, fy, cx, cy only: a skew or another last row
  // would be silently dropped there, so it is refused here.
  if (m[1] != 0.0 || m[3] != 0.0 || m[6] != 0.0 || m[7] != 0.0 || m[8] != 1.0) {
    node.failKey(key, "must be [fx, 0, cx, 0, fy, cy, 0, 0, 1] (OpenCV's model has no skew)");
  }
  if (!(m[0] > 0.0 && m[4] > 0.0)) node.failKey(key, "fx and fy must be > 0 pixels");
  lens.fx = m[0];
  lens.cx = m[2];
  lens.fy = m[4];
  lens.cy = m[5];
}

void setDistortion(const ConfigNode& node, const std::string& key, capture::Lens& lens) {
  const std::vector<double> d = numbersOf(node, key);
  bool known = false;
  for (const std::size_t n : kDistortionLengths) known = known || d.size() == n;
  if (!known) {
    node.failKey(key,
                 "expected 4, 5, 8, 12 or 14 coefficients (k1 k2 p1 p2 [k3 [k4 k5 k6 [s1 s2 "
                 "s3 s4 [tau_x tau_y]]]]), got " +
                     std::to_string(d.size()));
  }
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (!std::isfinite(d[i]))
      node.failKey(key, "coefficient " + std::to_string(i) + " is not finite");
    lens.distortion[i] = d[i];
  }
}

// The text of an OpenCV YAML file as yaml-cpp reads it: cv::FileStorage
// writes a first line "%YAML:1.0", which is no YAML directive; it becomes a
// comment, so the lines keep their numbers.
std::string openCvYamlText(const ConfigNode& lensNode, const std::string& path) {
  std::ifstream in(path);
  if (!in) lensNode.failKey("calibration", "cannot read the calibration file " + path);
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  if (s.rfind("%YAML:", 0) == 0) s.insert(0, "#");
  return s;
}

ParsedLens fromCalibration(const ConfigNode& lensNode) {
  ParsedLens out;
  out.calibration_file =
      existingDataFile(lensNode, "calibration", "calibration file").string();
  YAML::Node root;
  try {
    root = parseYaml(openCvYamlText(lensNode, out.calibration_file));
  } catch (const YAML::Exception& e) {
    lensNode.failKey("calibration", out.calibration_file + ":" + std::to_string(e.mark.line + 1) +
                                        ":" + std::to_string(e.mark.column + 1) + ": " + e.msg);
  }
  // Its keys are located in the calibration file; the other keys OpenCV
  // writes there (calibration_time, avg_reprojection_error, ...) are not read.
  const ConfigNode file(root, out.calibration_file);
  if (!file.isMap()) file.fail("expected a mapping (an OpenCV calibration YAML)");
  const std::string matrix = firstKey(file, {"camera_matrix", "cameraMatrix", "K"});
  const std::string dist =
      firstKey(file, {"distortion_coefficients", "dist_coeffs", "distCoeffs", "D"});
  if (matrix.empty()) file.fail("has no camera_matrix (nor cameraMatrix, K)");
  if (dist.empty()) file.fail("has no distortion_coefficients (nor dist_coeffs, distCoeffs, D)");
  setCameraMatrix(file, matrix, out);
  setDistortion(file, dist, out.lens);
  // A camera matrix is in pixels of the image it was calibrated on: without
  // that size nothing says which resolution it fits (OpenCV's calibration
  // writes both keys).
  for (const char* key : {"image_width", "image_height"}) {
    if (!file.has(key)) {
      file.fail(std::string("has no ") + key +
                ": a calibration's camera matrix holds at the image size it was made at; add "
                "image_width and image_height (pixels) to the file");
    }
  }
  const long long w = file.getInt("image_width", 0), h = file.getInt("image_height", 0);
  if (w < 1 || h < 1 || w > 16384 || h > 16384) {
    file.fail("image_width and image_height must both be in [1, 16384]");
  }
  out.image_size = glm::ivec2(static_cast<int>(w), static_cast<int>(h));
  return out;
}

}  // namespace

ParsedLens parseLens(const ConfigNode& camera) {
  const ConfigNode lensNode = camera.child("lens");
  if (!lensNode.isMap())
    lensNode.fail("expected a mapping (camera_matrix and distortion, or calibration)");
  if (lensNode.has("calibration")) {
    for (const char* key : {"camera_matrix", "distortion"}) {
      if (lensNode.has(key)) {
        lensNode.failKey(key, "give the calibration file or the values, not both");
      }
    }
    return fromCalibration(lensNode);
  }
  ParsedLens out;
  setCameraMatrix(lensNode, "camera_matrix", out);
  if (lensNode.has("distortion")) setDistortion(lensNode, "distortion", out.lens);
  return out;
}

void checkIntrinsics(const ParsedLens& parsed, int32_t width, int32_t height) {
  const capture::Lens& lens = parsed.lens;
  const double side = std::max(width, height);
  const auto fail = [&](const std::string& message) {
    throw InputError(parsed.matrix_at, parsed.matrix_key,
                     message + " for a " + std::to_string(width) + " x " + std::to_string(height) +
                         " image");
  };
  const auto range = [](double lo, double hi) {
    return "[" + shortest(lo) + ", " + shortest(hi) + "] px";
  };
  for (const auto& [name, f] : {std::pair{"fx", lens.fx}, std::pair{"fy", lens.fy}}) {
    if (!(f >= side / 1000.0 && f <= side * 1000.0)) {
      fail(std::string(name) + " = " + shortest(f) + " px is outside " +
           range(side / 1000.0, side * 1000.0) +
           " (1/1000 to 1000 times the larger side: fields of view of 179.9 to 0.06 degrees)");
    }
  }
  for (const auto& [name, c, size] :
       {std::tuple{"cx", lens.cx, double(width)}, std::tuple{"cy", lens.cy, double(height)}}) {
    if (!(c >= -size && c <= 2.0 * size)) {
      fail(std::string(name) + " = " + shortest(c) + " px is outside " + range(-size, 2.0 * size) +
           " (the principal point at most an image size outside the image)");
    }
  }
}

std::size_t distortionCount(const capture::Lens& lens) {
  std::size_t last = 0;
  for (std::size_t i = 0; i < lens.distortion.size(); ++i) {
    if (lens.distortion[i] != 0.0) last = i + 1;
  }
  for (const std::size_t n : kDistortionLengths) {
    if (last <= n) return n;
  }
  return lens.distortion.size();
}

}  // namespace tofsim::config
