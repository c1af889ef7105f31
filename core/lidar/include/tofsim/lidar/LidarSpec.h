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

/// How the beams are laid out. Spinning: channels (elevations) x azimuths
/// about the spin axis. Raster: a grid of beams over a rectangular field of
/// view (a MEMS or flash-like raster), each beam its own divergence cone.
/// Zones (multizone direct-ToF, VL53L5CX / TMF8828 class): the emitter
/// floods the field of view and each zone's receiver integrates its whole
/// rectangular solid angle (ScanGrid.h).
enum class ScanPattern { Spinning, Raster, Zones };

/// The grid of a raster or zone scan: rows x columns cells tiling the field
/// of view on the image plane at unit distance (a pinhole's pixels: cell
/// (row, column) spans equal steps of tan), row 0 the lowest, column 0 the
/// leftmost seen from the device. The device looks along `forward_world`
/// (towards look_at, not projected) with `up_world` orthogonalised to it.
struct ScanGrid {
  int32_t rows = 0, columns = 0;
  double fov_horizontal_deg = 0.0, fov_vertical_deg = 0.0;  ///< full angles, in (0, 180)
  /// Zones: zone_rays x zone_rays receiver rays per zone, at the centres of
  /// its sub-cells (as a camera's pixel_samples).
  int32_t zone_rays = 4;
};

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
  /// Unit. Spinning: normal to up, azimuth 0; raster and zones: the look
  /// direction itself (ScanGrid's frame orthogonalises up to it).
  glm::vec3 forward_world{1.0f, 0.0f, 0.0f};
  glm::vec3 up_world{0.0f, 0.0f, 1.0f};  ///< unit: the spin axis (a grid scan's up)
  std::vector<double> elevations_deg;         ///< one per channel (ring)
  double azimuth_start_deg = 0.0;
  double azimuth_end_deg = 360.0;  ///< exclusive
  double azimuth_step_deg = 0.2;   ///< > 0
  ScanPattern scan = ScanPattern::Spinning;
  ScanGrid grid;  ///< raster and zones only
  double divergence_rad = 3e-3;  ///< full angle, > 0
  BeamProfile profile = BeamProfile::Gaussian;
  /// Receiver rays over the divergence cone per beam (BeamPattern.h's
  /// layout: rings x sectors of equal power).
  int32_t beam_rays = 16;
  double power_W = 1.0;  ///< the laser's power per beam, per unit pulse
  ReturnSettings returns;
  BackscatterSettings backscatter;

  bool gridScan() const { return scan != ScanPattern::Spinning; }
  /// The waveforms' rows: channels (spinning) or the grid's rows.
  int32_t channels() const {
    return gridScan() ? grid.rows : static_cast<int32_t>(elevations_deg.size());
  }
  /// The waveforms' columns: azimuths start, start + step, ... below end (a
  /// small tolerance, so that 0..360 by 0.2 is 1800 azimuths, not 1801); the
  /// grid's columns for raster and zones.
  int32_t azimuths() const {
    if (gridScan()) return grid.columns;
    if (!(azimuth_step_deg > 0.0) || !(azimuth_end_deg > azimuth_start_deg)) return 0;
    return static_cast<int32_t>(
        std::ceil((azimuth_end_deg - azimuth_start_deg) / azimuth_step_deg - 1e-9));
  }
  double azimuthOf_deg(int32_t a) const { return azimuth_start_deg + azimuth_step_deg * a; }
};

}  // namespace tofsim::lidar
