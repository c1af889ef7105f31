#pragma once
// The rolling-scan tests' scene (core/lidar RollingScan.h): a plate moving
// along the lidar's beams at 30 m/s, z = 5 m + 30 m/s t (a triangle 60 m on
// its sides normal to +z, LINEAR from 5 m at t = 0 to 35 m at t = 1 s), and
// optionally a still wall at x = 6 m (the plane x = 6, a concave corner
// with the plate: multipath). The lidar at the origin looks along +z with
// up +y: one channel at elevation 0, azimuths -20 .. 20 degrees by 1
// (positive azimuths towards +x).

#include <filesystem>
#include <string>

#include "scene/AnimatedGltfFiles.h"
#include "tofsim/ir/MaterialVertex.h"
#include "tofsim/lidar/RollingScan.h"
#include "tofsim/scene/AnimatedScene.h"

namespace tofsim::test {

constexpr double kPlateSpeed_m_per_s = 30.0;
constexpr double kPlateZ0_m = 5.0;
constexpr double kRollStart_s = 0.2;  // the turn starts with the plate at 11 m
constexpr double kRollRate_Hz = 10.0;

/// The plate's z at scene time t_s.
inline double plateZ_m(double t_s) { return kPlateZ0_m + kPlateSpeed_m_per_s * t_s; }

/// The scene's glTF file in `dir` (plate.gltf).
inline std::filesystem::path writeMovingPlate(const std::filesystem::path& dir, bool wall = false) {
  AnimatedGltf f;
  f.addChannel(0, "translation", {0, 1}, {-20, -20, 5, -20, -20, 35}, "LINEAR");
  // The wall: the triangle turned -90 degrees about y into the plane x = 0
  // (x -> -z, z -> x), 60 m on its sides, moved to x = 6.
  const std::string nodes =
      wall ? R"([{"mesh": 0, "scale": [60, 60, 1], "translation": [-20, -20, 5]},
                 {"mesh": 0, "scale": [60, 60, 1], "rotation": [0, -0.70710678, 0, 0.70710678],
                  "translation": [6, -20, -20]}])"
           : R"([{"mesh": 0, "scale": [60, 60, 1], "translation": [-20, -20, 5]}])";
  return writeText(dir / "plate.gltf", f.json(nodes, wall ? "[0, 1]" : "[0]"));
}

inline scene::AnimatedScene movingPlate(const std::filesystem::path& dir, bool wall = false) {
  return scene::AnimatedScene::load(writeMovingPlate(dir, wall));
}

/// The scene at any time, as the pipeline traces it (Lambertian, in `medium`).
struct PlateAtTime : lidar::AnimatedWaveformScene {
  explicit PlateAtTime(const scene::AnimatedScene& animated, const capture::Medium& medium = {})
      : AnimatedWaveformScene(
            animated, animated.restScene(),
            ir::materialVertices(animated.restScene(), physics::VERTEX_LAMBERTIAN), medium, 1) {}
};

inline lidar::LidarSpec rollingLidar() {
  lidar::LidarSpec s;
  s.up_world = {0.0f, 1.0f, 0.0f};
  s.forward_world = {0.0f, 0.0f, 1.0f};
  s.elevations_deg = {0.0};
  s.azimuth_start_deg = -20.0;
  s.azimuth_end_deg = 20.0;
  s.azimuth_step_deg = 1.0;
  s.returns.mode = lidar::ReturnMode::First;
  s.returns.max = 1;
  return s;
}

inline TimeAxis rollingAxis() {  // 1.5 mm of range per bin, to 15 m
  TimeAxis a;
  a.bin_width_s = 10e-12;
  a.bins = 10000;
  return a;
}

}  // namespace tofsim::test
