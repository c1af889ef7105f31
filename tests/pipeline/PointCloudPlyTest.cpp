// Depth images as point clouds (apps/pipeline PointCloudPly): the binary
// little-endian PLY read back here, header and every value, against the
// camera's rays; and the sensor writer making one per depth output.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "tofsim/pipeline/PlotRanges.h"
#include "tofsim/pipeline/PointCloudPly.h"
#include "tofsim/pipeline/SensorWriter.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::pipeline {
namespace {

struct Ply {
  std::vector<std::string> header;  // lines up to end_header
  std::size_t vertices = 0;
  std::vector<std::string> properties;
  std::vector<float> values;  // vertices x properties
};

// A minimal reader of what PLY readers require: magic, format, one vertex
// element of float properties, then the little-endian body.
Ply readPly(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t end = bytes.find("end_header\n");
  EXPECT_NE(end, std::string::npos);
  Ply ply;
  std::istringstream header(bytes.substr(0, end + 11));
  for (std::string line; std::getline(header, line);) {
    ply.header.push_back(line);
    std::istringstream words(line);
    std::string word, type, name;
    words >> word;
    if (word == "element") words >> name >> ply.vertices;
    if (word == "property") {
      words >> type >> name;
      EXPECT_EQ(type, "float");
      ply.properties.push_back(name);
    }
  }
  const std::size_t body = end + 11;
  EXPECT_EQ(bytes.size() - body, ply.vertices * ply.properties.size() * 4);
  for (std::size_t k = body; k + 4 <= bytes.size(); k += 4) {
    uint32_t bits = 0;
    for (int b = 0; b < 4; ++b)
      bits |= static_cast<uint32_t>(static_cast<unsigned char>(bytes[k + b])) << (8 * b);
    float v = 0.0f;
    std::memcpy(&v, &bits, 4);
    ply.values.push_back(v);
  }
  return ply;
}

capture::Camera testCamera() {
  capture::Camera camera;
  camera.position_world = {0.5f, 1.0f, 2.0f};
  camera.look_at_world = {0.5f, 0.8f, -1.0f};
  camera.fov_y_deg = 50.0f;
  camera.width = 4;
  camera.height = 3;
  return camera;
}

TEST(PointCloudPlyTest, HeaderAndValuesReadBack) {
  const capture::Camera camera = testCamera();
  Image depth(4, 3, 1), intensity(4, 3, 1), confidence(4, 3, 1);
  for (int32_t y = 0; y < 3; ++y) {
    for (int32_t x = 0; x < 4; ++x) {
      depth.at(y, x, 0) = 1.0f + 0.25f * x + 0.5f * y;
      intensity.at(y, x, 0) = static_cast<float>(10 * y + x);
      confidence.at(y, x, 0) = 0.1f * static_cast<float>(x);
    }
  }
  depth.at(1, 2, 0) = std::nanf("");  // no depth: no point
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "tofsim_point_cloud_test.ply";
  EXPECT_EQ(writePointCloudPly(path, {&depth, &intensity, &confidence, "test cloud"}, camera), 11u);
  const Ply ply = readPly(path);
  ASSERT_GE(ply.header.size(), 3u);
  EXPECT_EQ(ply.header[0], "ply");
  EXPECT_EQ(ply.header[1], "format binary_little_endian 1.0");
  EXPECT_EQ(ply.header.back(), "end_header");
  EXPECT_EQ(ply.vertices, 11u);
  EXPECT_EQ(ply.properties, (std::vector<std::string>{"x", "y", "z", "cam_x", "cam_y", "cam_z",
                                                      "intensity", "confidence"}));
  const glm::dvec3 right(camera.right()), up(camera.up()), forward(camera.forward());
  std::size_t v = 0;
  double worst = 0.0;
  for (int32_t y = 0; y < 3; ++y) {
    for (int32_t x = 0; x < 4; ++x) {
      if (std::isnan(depth.at(y, x, 0))) continue;
      const float* p = ply.values.data() + 8 * v++;
      const double d = depth.at(y, x, 0);
      const glm::dvec3 dir(camera.pixelDirection(x, y));
      const glm::dvec3 world = glm::dvec3(camera.position_world) + d * dir;
      const double expected[6] = {world.x,
                                  world.y,
                                  world.z,
                                  d * glm::dot(dir, right),
                                  -d * glm::dot(dir, up),
                                  d * glm::dot(dir, forward)};
      for (int k = 0; k < 6; ++k) worst = std::max(worst, std::fabs(p[k] - expected[k]));
      EXPECT_EQ(p[6], intensity.at(y, x, 0));
      EXPECT_EQ(p[7], confidence.at(y, x, 0));
      // The camera frame is OpenCV's: z forward along the depth, y down.
      EXPECT_NEAR(std::sqrt(p[3] * p[3] + p[4] * p[4] + p[5] * p[5]), d, 1e-6);
      EXPECT_GT(p[5], 0.0f);
      if (y == 1) {  // row 1 of 3 is the optical axis's
        EXPECT_NEAR(p[4], 0.0f, 1e-6);
      } else {
        EXPECT_EQ(p[4] < 0.0f, y == 0);
      }
    }
  }
  std::printf("largest coordinate difference %.3g m\n", worst);
  EXPECT_LT(worst, 1e-6);
  std::filesystem::remove(path);
}

// A SPAD's run on 10 bins of 10 ps, seen through `camera`.
SensorRunInfo spadRun(const sensors::SensorSpec& spec, const capture::Camera& camera) {
  TimeAxis axis;
  axis.bin_width_s = 1e-11;
  axis.bins = 10;
  return SensorRunInfo{&spec, axis, 1, {}, &camera};
}

sensors::SensorSpec spadSpec() {
  sensors::SensorSpec spec;
  spec.name = "spad";
  spec.params = sensors::SpadParams{};
  return spec;
}

// A 4 x 3 depth image of 2 m everywhere, drawn as the point cloud `cloud`.
sensors::SensorOutput depthImage(const std::string& name,
                                 const sensors::SensorOutput::PointCloud& cloud) {
  sensors::SensorOutput depth;
  depth.name = name;
  depth.kind = sensors::SensorOutput::Kind::Image;
  depth.shape = {3, 4};
  depth.axes = {"y", "x"};
  depth.unit = "m";
  depth.data.assign(12, 2.0f);
  depth.point_cloud = cloud;
  return depth;
}

TEST(PointCloudPlyTest, SensorWriterMakesOnePerDepthOutput) {
  const capture::Camera camera = testCamera();
  const sensors::SensorSpec spec = spadSpec();
  SensorRunInfo run = spadRun(spec, camera);
  const sensors::SensorOutput depth = depthImage(
      "spad_depth_matched", sensors::SensorOutput::PointCloud{"spad_intensity", "spad_confidence"});
  sensors::SensorOutput intensity = depth;
  intensity.name = "spad_intensity";
  intensity.point_cloud.reset();
  intensity.data.assign(12, 7.0f);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tofsim_ply_writer";
  std::filesystem::remove_all(dir);
  PlotRanges ranges({});
  const std::vector<std::string> files = writeSensorOutputs(dir, {depth, intensity}, run, ranges);
  EXPECT_NE(std::find(files.begin(), files.end(), "spad_depth_matched.ply"), files.end());
  EXPECT_EQ(std::find(files.begin(), files.end(), "spad_intensity.ply"), files.end());
  const Ply ply = readPly(dir / "spad_depth_matched.ply");
  ASSERT_EQ(ply.vertices, 12u);
  EXPECT_EQ(ply.values[6], 7.0f);  // intensity from spad_intensity
  EXPECT_EQ(ply.values[7], 1.0f);  // no spad_confidence output: 1
  std::ifstream json(dir / "spad_depth_matched.json");
  const std::string text((std::istreambuf_iterator<char>(json)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"point_cloud\": \"spad_depth_matched.ply\""), std::string::npos);
  // Without a camera (a point-set imager), no cloud.
  run.camera = nullptr;
  std::filesystem::remove_all(dir);
  const std::vector<std::string> none = writeSensorOutputs(dir, {depth, intensity}, run, ranges);
  EXPECT_EQ(std::find(none.begin(), none.end(), "spad_depth_matched.ply"), none.end());
  std::filesystem::remove_all(dir);
}

// A pixel without a detected return (spad_returns 0, the cloud's mask) is no
// point, though the estimators gave it a finite depth; the others keep theirs.
TEST(PointCloudPlyTest, NoPointWhereNoReturnWasDetected) {
  const capture::Camera camera = testCamera();
  const sensors::SensorSpec spec = spadSpec();
  const SensorRunInfo run = spadRun(spec, camera);
  const sensors::SensorOutput depth =
      depthImage("spad_depth_peak", sensors::SensorOutput::PointCloud{
                                        "spad_intensity", "spad_confidence", "spad_returns"});
  sensors::SensorOutput returns = depth;
  returns.name = "spad_returns";
  returns.point_cloud.reset();
  returns.data.assign(12, 1.0f);
  returns.data[5] = 0.0f;  // (y 1, x 1): noise alone
  returns.data[11] = 0.0f;
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tofsim_ply_mask";
  std::filesystem::remove_all(dir);
  PlotRanges ranges({});
  writeSensorOutputs(dir, {depth, returns}, run, ranges);
  const Ply ply = readPly(dir / "spad_depth_peak.ply");
  EXPECT_EQ(ply.vertices, 10u);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tofsim::pipeline
