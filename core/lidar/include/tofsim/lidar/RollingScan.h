#pragma once
// A rolling scan (issue 43): a spinning lidar's azimuth columns fire one
// after another as it turns, so a scene that moves during the turn is seen
// by each column where it is at that column's own time (the rolling
// distortion of a moving scene). Column a fires at
//
//   start + (azimuth_a - azimuth_start) / 360 / rotation_rate
//
// (the channels of a column at once), and is traced against the scene at
// that time: the caller moves the scene there (glTF animations,
// scene::AnimatedScene; AnimatedWaveformScene below), a scene update per
// column.

#include <cstdint>
#include <functional>
#include <optional>

#include "tofsim/lidar/DirectWaveforms.h"
#include "tofsim/lidar/LidarSpec.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/scene/AnimatedScene.h"

namespace tofsim::lidar {

/// When azimuth column `azimuth` fires after the turn's start, s.
double firingOffset_s(const LidarSpec& spec, int32_t azimuth, double rotation_rate_Hz);

/// The scene at scene time t_s, ready to trace (valid until the next call).
using SceneAtTime = std::function<const WaveformScene&(double t_s)>;

/// An animated scene to trace at any time: the moving meshes re-baked there
/// (AnimatedScene::updateScene) and their vertices updated in the rays' BVH
/// on one Embree device (a new RayScene only where a mesh's counts change).
class AnimatedWaveformScene {
 public:
  /// `scene`: animated.restScene(), configured (materials' delays);
  /// `materials`: ir::materialVertices of it (materials do not move).
  AnimatedWaveformScene(const scene::AnimatedScene& animated, scene::Scene scene,
                        std::vector<physics::ScatterVertex> materials,
                        const capture::Medium& medium, int threads);
  /// The scene at t_s, ready to trace (until the next call).
  const WaveformScene& at(double t_s);

 private:
  const scene::AnimatedScene& animated_;
  scene::Scene scene_;
  int threads_;
  std::optional<rays::RayScene> rays_;
  WaveformScene traced_;
  std::optional<double> time_s_;
};

/// Every beam's direct-light waveform, column a traced against
/// sceneAt(start_s + firingOffset_s(a)); the columns in order, a column's
/// beams on `threads` threads: the same bytes for any thread count, and
/// renderDirectWaveforms' bytes for a scene that does not move.
LidarWaveforms renderRollingWaveforms(const LidarSpec& spec, const SceneAtTime& sceneAt,
                                      const TimeAxis& axis, double start_s,
                                      double rotation_rate_Hz, int threads, bool keepVolume);

}  // namespace tofsim::lidar
