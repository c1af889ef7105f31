#pragma once
// A lidar's waveforms from direct light (issue 43's first slice): each
// receiver ray of each beam (BeamPattern.h) finds its surface with the
// driver's Embree RayScene, and the laser light that surface returns along
// the ray lands in the bin of its optical path eta x 2 r (eta x r with
// time.camera_unwarp). A ray's value is the irradiance it brings to the
// receiver's aperture, in W m^-2 per unit pulse:
//
//   E = power x share x f(wi = wo) x cos(theta) / r^2 x T(2 r)
//
// f the hit's BRDF toward the lidar (albedo / pi for a Lambertian surface,
// the glTF BRDF with render.materials: gltf; the mean of R, G and B: a lidar
// sees one wavelength), theta the incidence, T the medium's transmittance
// over both legs (capture::Medium; 1 without one). A beam fully on a
// Lambertian plane gives power rho cos / (pi r^2), the lidar equation of an
// extended target per unit receiver area: a sensor's `etendue` is then the
// receiver's aperture area in m^2.
//
// Light that bounces more than once (multipath, IR's indirect light per
// beam, `lidar.multipath`) is MultipathWaveforms.h's, added to the same
// waveforms.

#include <cstdint>
#include <vector>

#include "tofsim/capture/Medium.h"
#include "tofsim/lidar/BeamPattern.h"
#include "tofsim/lidar/LidarSpec.h"
#include "tofsim/lidar/SparseWaveforms.h"
#include "tofsim/physics/ScatterVertex.h"
#include "tofsim/rays/RayScene.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::lidar {

/// What every beam's receiver rays are traced against.
struct WaveformScene {
  const rays::RayScene* rays = nullptr;
  /// ir::materialVertices of the scene, in Scene::materials order.
  std::vector<physics::ScatterVertex> materials;
  capture::Medium medium;
};

/// Light that fell off the time axis (before its start or after its end),
/// summed over the beams, in the waveform's unit.
struct WaveformLoss {
  double before = 0.0, after = 0.0;
};

/// A beam's receiver rays (BeamPattern.h) with their tilts, worked out once
/// for every beam of a frame.
struct ReceiverRays {
  explicit ReceiverRays(std::vector<BeamRay> beamRays);
  std::vector<BeamRay> rays;
  std::vector<RayTilt> tilts;
};

/// Beam (ring, azimuth)'s rays' direct light, each ray's (bin, value) in
/// ray order appended to `out` (its rays traced as one packet from the
/// lidar's position: RayScene::intersectPacket's bundle); what fell off the
/// axis added to `lost`.
void beamRayBins(const LidarSpec& spec, const ReceiverRays& rays,
                 const WaveformScene& scene, const TimeAxis& axis, int32_t ring, int32_t azimuth,
                 std::vector<WaveformBin>& out, WaveformLoss& lost);

/// Adds beam (ring, azimuth)'s direct light into `waveform` (axis.bins
/// floats); returns what fell off the axis.
WaveformLoss addBeamWaveform(const LidarSpec& spec, const std::vector<BeamRay>& rays,
                             const WaveformScene& scene, const TimeAxis& axis, int32_t ring,
                             int32_t azimuth, float* waveform);

struct LidarWaveforms {
  /// Height channels, width azimuths, one channel "intensity": pixels are
  /// beams. Empty (size() 0) unless asked for (keepVolume).
  TransientVolume volume;
  /// Every beam's nonzero bins: the same waveforms (the volume, where kept,
  /// is these expanded).
  SparseWaveforms sparse;
  TimeAxis axis;
  WaveformLoss lost;
  /// Beam b's waveform (axis bins floats) into `out`: the volume's where
  /// kept (what was added to it after the render included), else the
  /// sparse bins expanded.
  void beamWaveform(std::size_t beam, float* out) const;
};

/// Every beam's waveform, on `threads` threads (0: all) over fixed blocks of
/// beams: the same bytes for any thread count. The dense volume is made
/// (and written in blocks, each by the thread that rendered it) only with
/// keepVolume; the returns need the sparse bins alone.
LidarWaveforms renderDirectWaveforms(const LidarSpec& spec, const WaveformScene& scene,
                                     const TimeAxis& axis, int threads, bool keepVolume = true);

}  // namespace tofsim::lidar
