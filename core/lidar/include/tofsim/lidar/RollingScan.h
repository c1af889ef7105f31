#pragma once
// A rolling scan (issue 43): a lidar's beams fire one after another, so a
// scene that moves during the scan is seen by each beam where it is at that
// beam's own time (the rolling distortion of a moving scene).
//  - Spinning: azimuth column a fires at
//      start + (azimuth_a - azimuth_start) / 360 / rotation_rate
//    (the channels of a column at once).
//  - Raster (a MEMS raster lidar): the cells fire one at a time, line by
//    line from the top row down, each line left to right, at a uniform cell
//    rate over the frame: cell (row, column) at
//      start + ((rows - 1 - row) columns + column) / (rows columns frame_rate).
//    An assumption (shared/research/media-delays-lidar.md sources no MEMS
//    timing): a resonant mirror's sinusoidal fast axis, bidirectional lines
//    and the flyback's dead time are left out; the frame's cells are evenly
//    spread over 1 / frame_rate.
//  - Zones: the flood is one exposure of every zone at once; it has no
//    rolling order (the pipeline refuses a zone scan's sequence).
// Each group of beams that fires together is traced against the scene at
// its time: the caller moves the scene there (glTF animations,
// scene::AnimatedScene; AnimatedWaveformScene below), a scene update per
// group. Everything a still frame adds to its beams does the same: the
// multipath (each beam's IR capture, MultipathWaveforms.h) and the medium's
// backscatter (BeamBackscatter.h), each beam's against the scene at its own
// firing time (addRollingLight).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "tofsim/lidar/BeamBackscatter.h"
#include "tofsim/lidar/DirectWaveforms.h"
#include "tofsim/lidar/LidarSpec.h"
#include "tofsim/lidar/MultipathSettings.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/scene/AnimatedScene.h"

namespace tofsim::lidar {

/// When azimuth column `azimuth` of a spinning lidar fires after the turn's start, s.
double firingOffset_s(const LidarSpec& spec, int32_t azimuth, double rotation_rate_Hz);

/// When beam (ring, azimuth) fires after the scan's start, s: a spinning
/// lidar's column at `rate_Hz` turns per second, a raster's cell at
/// `rate_Hz` frames per second; 0 for a zone scan (one flood).
double beamFiringOffset_s(const LidarSpec& spec, int32_t ring, int32_t azimuth, double rate_Hz);

/// Beams that fire at one time.
struct FiringGroup {
  double offset_s = 0.0;           ///< after the scan's start
  std::vector<std::size_t> beams;  ///< ring x azimuths + azimuth, rings ascending
};

/// A scan's beams grouped by firing time, in firing order: a spinning
/// lidar's azimuth columns, a raster's cells one by one, a zone scan's
/// zones in one group at 0.
std::vector<FiringGroup> firingGroups(const LidarSpec& spec, double rate_Hz);

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

/// Every beam's direct-light waveform, each group of firingGroups traced
/// against sceneAt(start_s + its offset); the groups in order, a group's
/// beams on `threads` threads: the same bytes for any thread count, and
/// renderDirectWaveforms' bytes for a scene that does not move. A spinning
/// or raster scan (a zone scan's flood throws std::invalid_argument).
LidarWaveforms renderRollingWaveforms(const LidarSpec& spec, const SceneAtTime& sceneAt,
                                      const TimeAxis& axis, double start_s, double rate_Hz,
                                      int threads, bool keepVolume);

/// Adds to a rolling frame's waveforms (keepVolume) what a still frame adds
/// after its direct echoes, each group against the scene at its firing
/// time: the multipath (`multipath` on: addBeamMultipath, seeded per beam as
/// addMultipathWaveforms) and the medium's backscatter (when it scatters:
/// BackscatterLight). The same bytes for any thread count, and
/// addMultipathWaveforms' then addBackscatter's for a scene that does not
/// move. Returns the beams' surface bins (empty without backscatter).
BeamSurfaces addRollingLight(const LidarSpec& spec, const MultipathSettings& multipath,
                             const SceneAtTime& sceneAt, const TimeAxis& axis, double start_s,
                             double rate_Hz, int threads, LidarWaveforms& waveforms);

}  // namespace tofsim::lidar
