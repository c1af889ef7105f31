#pragma once
// A lidar as the capture sees it (issue 43, `lidar:` in place of `camera:`):
// where it stands, its spin axis, its channels (elevations) and azimuths, the
// beam's divergence and profile, its laser power and how echoes become
// returns. Plain data: apps/config fills it from the YAML
// (configs/README.md, `lidar`), core/lidar renders it.
//
// Frame: `up_world` is the spin axis; azimuth 0 looks along `forward_world`
// (the look_at direction with its component along up removed) and azimuths
// grow counter-clockwise seen from above (from forward towards up x
// forward, the lidar's left); an elevation is the angle above the plane
// normal to up. Ring r is channel r in the order the channels are listed
// (count/min/max: ring 0 is the lowest).

#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tofsim::lidar {

/// How the laser's power spreads over the divergence cone. Gaussian: the
/// divergence is the 1/e^2 full angle (power density exp(-2 theta^2 / w^2),
/// w the half divergence), untruncated; tophat: uniform over the cone.
enum class BeamProfile { Gaussian, Tophat };

/// Which echoes of a beam's waveform become returns (Echoes.h).
enum class ReturnMode { First, Strongest, Last, Dual, All };

/// How the beams are laid out in time and space. Only `spinning` is built;
/// raster and zones (multizone direct-ToF) are later slices.
enum class ScanPattern { Spinning };

struct ReturnSettings {
  ReturnMode mode = ReturnMode::Strongest;
  /// The most returns kept per beam (first, strongest, last keep one at
  /// most, dual two, all up to this), >= 1.
  int32_t max = 2;
  /// A waveform bin belongs to an echo when its value is above this, in the
  /// waveform's unit (W m^-2 per pulse, DirectWaveforms.h); 0: any light.
  double threshold = 0.0;
  /// Runs of bins above the threshold closer than this (range, m) are one
  /// echo: the receiver's pulse-pair resolution.
  double separation_m = 0.3;
};

/// The medium's single scattering along each beam (BeamBackscatter.h).
struct BackscatterSettings {
  /// The range from which the receiver sees the laser's cone whole (a
  /// coaxial receiver's overlap; [HAH]'s ramps to 1 over 0.9 - 1.0 m):
  /// nothing nearer reaches the detector. > 0 (the 1 / r^2 diverges at 0).
  double overlap_m = 1.0;
  /// The medium's phase function at pi as the lidar sees it, 1/sr (fog's
  /// Mie backscatter, which Henyey-Greenstein underestimates 15x:
  /// shared/research/media-delays-lidar.md 2.2); 0: the medium's own.
  double phase_at_pi_per_sr = 0.0;
};

struct LidarSpec {
  glm::vec3 position_world{0.0f};
  glm::vec3 forward_world{1.0f, 0.0f, 0.0f};  ///< unit, normal to up: azimuth 0
  glm::vec3 up_world{0.0f, 0.0f, 1.0f};       ///< unit: the spin axis
  std::vector<double> elevations_deg;         ///< one per channel (ring)
  double azimuth_start_deg = 0.0;
  double azimuth_end_deg = 360.0;  ///< exclusive
  double azimuth_step_deg = 0.2;   ///< > 0
  ScanPattern scan = ScanPattern::Spinning;
  double divergence_rad = 3e-3;  ///< full angle, > 0
  BeamProfile profile = BeamProfile::Gaussian;
  /// Receiver rays over the divergence cone per beam (BeamPattern.h's
  /// layout: rings x sectors of equal power).
  int32_t beam_rays = 16;
  double power_W = 1.0;  ///< the laser's power per beam, per unit pulse
  ReturnSettings returns;
  BackscatterSettings backscatter;

  int32_t channels() const { return static_cast<int32_t>(elevations_deg.size()); }
  /// Azimuths start, start + step, ... below end (a small tolerance, so
  /// that 0..360 by 0.2 is 1800 azimuths, not 1801).
  int32_t azimuths() const {
    if (!(azimuth_step_deg > 0.0) || !(azimuth_end_deg > azimuth_start_deg)) return 0;
    return static_cast<int32_t>(
        std::ceil((azimuth_end_deg - azimuth_start_deg) / azimuth_step_deg - 1e-9));
  }
  double azimuthOf_deg(int32_t a) const { return azimuth_start_deg + azimuth_step_deg * a; }
};

}  // namespace tofsim::lidar
