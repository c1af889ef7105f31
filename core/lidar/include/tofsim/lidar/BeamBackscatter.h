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
