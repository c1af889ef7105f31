#pragma once
// `lidar.multipath` (configs/README.md, `lidar`): how a beam's multipath is
// rendered (MultipathWaveforms.h). Plain data, header only, so the config
// module fills it without the renderer.

#include <cstdint>

namespace tofsim::lidar {

/// `lidar.multipath` (configs/README.md, `lidar`).
struct MultipathSettings {
  /// Light's bounces after the spot: 0 = off (direct light only), 1 = the
  /// spot lights the receiver points (one-bounce multipath), n = n - 1 more
  /// bounces by VPLs traced from the spot.
  int32_t bounces = 0;
  int32_t spot_rays = 4;          ///< laser rays (spot VPLs) per beam, >= 1
  int32_t receiver_rays = 16;     ///< receiver rays per beam, >= 1
  double receiver_fov_rad = 0.0;  ///< full angle; 0: the beam's divergence
  int32_t vpls_per_bounce = 16;   ///< per beam, for each bounce after the first
  /// From render: indirect.geometry_term_clamp (1/m^2, <= 0 none),
  /// indirect.vpl_brdf_clamp (1/sr, <= 0 none), materials (the later
  /// bounces' vertex model, physics::VERTEX_*) and seed.
  double geometry_clamp_per_m2 = 100.0;
  double brdf_clamp_per_sr = 0.0;
  int vertex_model = 0;
  uint64_t seed = 0;

  bool enabled() const { return bounces > 0; }
};

}  // namespace tofsim::lidar
