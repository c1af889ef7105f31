#pragma once
// The sequence tests' scene (SequenceRunTest.cpp, SequenceSensorsTest.cpp,
// hardening/SequenceSwapTest.cpp):
// a plane at d(t) = d0 + v t along the axis of an 8 x 8 camera with a 10
// degree field of view (a glTF translation channel, LINEAR, over [0, 1] s),
// lit by a point light at the camera, rendered on the CPU backend at pixel
// centres, direct light only.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>

#include "scene/AnimatedGltfFiles.h"
#include "support/TempDir.h"
#include "tofsim/pipeline/RenderRun.h"
#include "tofsim/util/Error.h"

namespace tofsim::pipeline::test_sequence {

namespace fs = std::filesystem;
constexpr double kC = 299792458.0;
constexpr double kD0 = 2.0;  // m, the plane's distance at t = 0

inline std::string bytesOf(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

class MovingPlaneTest : public test::TempDirTest {
 protected:
  // The plane z = -(d0 + v t): a large triangle (scaled, offset so that it
  // covers the view) below a node translated by the animation over [0, 1] s.
  void writeScene(double v_m_per_s) {
    test::AnimatedGltf f;
    const float z0 = static_cast<float>(-kD0), z1 = static_cast<float>(-kD0 - v_m_per_s);
    f.addChannel(0, "translation", {0.0f, 1.0f}, {0, 0, z0, 0, 0, z1}, "LINEAR");
    const std::string nodes =
        R"([{"children": [1], "translation": [0, 0, )" + std::to_string(z0) +
        R"(]}, {"mesh": 0, "scale": [40, 40, 1], "translation": [-5, -5, 0]}])";
    test::writeText(dir_ / "plane.gltf", f.json(nodes, "[0]"));
  }
  // The config's text (the CLI tests write it to a file).
  static std::string configYaml(const std::string& sequence, const std::string& time,
                                const std::string& sensor = "") {
    return "scene: plane.gltf\n"
           "camera: {position: [0, 0, 0], look_at: [0, 0, -1], fov_y: 10 deg, resolution: [8, 8]}\n"
           "light: {attach_to_camera: true, intensity: 5}\n"
           "time: " +
           time +
           "\n"
           "render: {backend: cpu, threads: 2, pixel_footprint: false, indirect: {enabled: "
           "false}}\n"
           "output: {steady: false, depth: true}\n" +
           sequence + (sensor.empty() ? "" : "sensors:\n  - " + sensor + "\n");
  }
  config::RunConfig config(const std::string& sequence, const std::string& time,
                           const std::string& sensor = "") {
    return config::loadRunConfigText(configYaml(sequence, time, sensor), dir_ / "c.yaml");
  }
  fs::path run(const config::RunConfig& c, const std::string& name) {
    RunOptions options;
    options.outputDirectory = dir_ / name;
    options.quiet = std::getenv("SEQ_DEBUG") == nullptr;
    runRender(c, options);
    return dir_ / name;
  }
  std::string errorOf(const std::string& sequence) {
    try {
      run(config(sequence, kTime), "bad");
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }
  static constexpr const char* kTime = "{start: 13 ns, bin_width: 10 ps, bins: 800}";
};

// Pixel (4, 4) of the 8 x 8 image, whose centre is half a pixel off the
// axis in x and y: its ray meets the plane at kOffAxis times the plane's
// distance.
// Pixel (x, y)'s ray meets the plane at offAxis(x, y) times its distance.
inline double offAxis(int x, int y) {
  const double step =
      std::tan(5.0 * std::numbers::pi / 180.0) / 4.0;  // per pixel, at unit distance
  return std::sqrt(1.0 + std::pow((x - 3.5) * step, 2) + std::pow((y - 3.5) * step, 2));
}
constexpr std::size_t kCentre = 4 * 8 + 4;
const double kOffAxis = offAxis(4, 4);

}  // namespace tofsim::pipeline::test_sequence
