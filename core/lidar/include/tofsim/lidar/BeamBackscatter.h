#pragma once
// The medium's single scattering along a lidar's beams (issue 43 with issue
// 42's media): the fog's backscatter in each beam's waveform, and which
// returns are fog's (false returns, not on a surface).
//
// The laser's cone and the receiver's coincide, so a receiver ray of share
// a (BeamPattern.h) carries a of the laser's power P along its own
// direction until its surface at D. The medium in the shell [s, s + ds]
// of that part of the cone scatters a P exp(-sigma_t s) sigma_s p(pi) ds
// back toward the lidar per steradian, and the receiver's aperture, s away,
// gets it attenuated again: per unit receiver area
//
//   dE = a P sigma_s p(pi) exp(-2 sigma_t s) / s^2 ds,
//
// in the waveform's unit (W m^-2 per pulse, DirectWaveforms.h), at optical
// path eta x 2 s (eta s with time.camera_unwarp). Summed over the rays this
// is the lidar equation's backscatter, P sigma_s p(pi) exp(-2 sigma_t s) /
// s^2 ds for a beam that sees no surface, whatever its profile: the profile
// matters only where part of the beam stops at a surface. Each bin holds
// the exact integral over its range interval (from the overlap on, up to
// the ray's surface): with x = 2 sigma_t s,
//
//   int exp(-2 sigma_t s) / s^2 ds = -exp(-x) / s + 2 sigma_t E1(x),
//
// per channel, then the mean of the channels (a lidar sees one wavelength,
// as DirectWaveforms' BRDF). The medium's camera single scattering
// (core/physics/medium_single_scattering.md) integrates the same light by
// quadrature for any light position; a lidar's co-located cone has this
// closed form.
//
// A zone scan's flood (ScanGrid.h) is the same light: the flood's intensity
// is P / Omega_fov in every direction of the field, and a zone's receiver
// ray of solid angle Omega_ray (share a = Omega_ray / Omega_fov) collects the
// medium's radiance sigma_s p(pi) P / Omega_fov exp(-2 sigma_t s) / s^2 ds
// over Omega_ray: a P sigma_s p(pi) exp(-2 sigma_t s) / s^2 ds, the beam's
// form with the zone ray's share (emitter and receiver co-located). A zone's
// rays are its own (zoneRays), each beam's are the divergence cone's.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tofsim/lidar/BeamPattern.h"
#include "tofsim/lidar/DirectWaveforms.h"
#include "tofsim/lidar/LidarSpec.h"

namespace tofsim::lidar {

/// Each beam's receiver rays' surface bins (ring-major, then azimuth, then
/// ray): the bin their surface's light lands in (DirectWaveforms'), or -1
/// for none on the axis.
struct BeamSurfaces {
  int32_t raysPerBeam = 0;
  std::vector<int32_t> bins;
};

/// int_a^b exp(-2 sigmaT s) / s^2 ds for 0 < a <= b (b infinite allowed).
double backscatterIntegral(double sigmaT, double a, double b);

/// Beams added per task by addBackscatter (their losses summed per block,
/// then the blocks in order): a rolling scan sums its losses the same way.
constexpr std::size_t kBackscatterBlock = 256;

/// The medium's backscatter on a frame's time axis, worked out once (the
/// medium per channel, each bin's range interval from the overlap on, a
/// whole bin's light), and each beam's receiver rays (a zone's own).
class BackscatterLight {
 public:
  BackscatterLight(const LidarSpec& spec, const capture::Medium& medium, const TimeAxis& axis);
  /// Receiver rays per beam: BeamSurfaces::raysPerBeam.
  int32_t raysPerBeam() const;
  /// Adds beam (ring, azimuth)'s backscatter to `waveform` (axis bins), its
  /// rays traced against `scene`: their surface bins into `surfaceBins`
  /// (raysPerBeam values, -1 for none on the axis); returns what fell off
  /// the axis.
  WaveformLoss addBeam(const rays::RayScene& scene, int32_t ring, int32_t azimuth,
                       float* waveform, int32_t* surfaceBins) const;

 private:
  double light(double a, double b) const;  // the light of range [a, b], all rays' shares 1
  double binOf(double r) const;            // DirectWaveforms' bin of a surface at range r

  const LidarSpec& spec_;
  std::vector<BeamRay> beamRays_;  // a beam's; empty for a zone scan (zoneRays per zone)
  double field_sr_ = 0.0;          // a zone scan's field of view
  glm::dvec3 sigmaT_{0.0}, weight_{0.0};  // weight = power x sigma_s p(pi) / channels
  bool grey_ = false;  // every channel alike (fog): one integral for the three
  std::vector<double> edges_m_;  // bins + 1 range edges, each >= the overlap
  std::vector<double> whole_;    // a whole bin's light
  double legsEta_ = 2.0, start_m_ = 0.0, width_m_ = 1.0;
};

/// Adds the medium's backscatter to every beam's waveform (when the medium
/// scatters; nothing else changes) on `threads` threads over fixed blocks
/// (the same bytes for any thread count), its light off the axis to
/// `waveforms.lost`; returns the beams' surface bins.
BeamSurfaces addBackscatter(const LidarSpec& spec, const WaveformScene& scene,
                            const TimeAxis& axis, int threads, LidarWaveforms& waveforms);

/// Which of lidarReturns' points (in its order) are fog's: returns whose
/// bins [first, last] hold no receiver ray's surface bin. 1: fog's.
std::vector<uint8_t> fogReturnFlags(const LidarSpec& spec, const TransientVolume& waveforms,
                                    const BeamSurfaces& surfaces);

}  // namespace tofsim::lidar
