#pragma once
// A lidar beam's multipath (issue 43, `lidar.multipath`): the laser light
// that bounces off other surfaces before it returns, added to the beam's
// waveform (DirectWaveforms.h holds the direct echo) in the bin of its full
// optical path, laser -> spot -> ... -> receiver point -> lidar.
//
// Each beam is an instant-radiosity capture of its own:
//  - the laser's `spot_rays` rays over the divergence cone (BeamPattern.h's
//    layout and profile) hit the spot's points; each becomes a VPL of the
//    power its ray carries, power x share x T(r) (ir::Vpl: albedo Phi / pi,
//    W/sr, on a Lambertian surface; Phi, W, with its BRDF otherwise);
//  - bounces > 1: the spot VPLs' light continues by core/ir's bounce
//    machinery (ir::traceBounce: `vpls_per_bounce` child VPLs per later
//    bounce, seeded per beam), so every later VPL carries its path too;
//  - the receiver's `receiver_rays` rays, uniform over its field of view
//    (`receiver_fov`, full angle, the divergence by default: a receiver that
//    sees just the spot; wider, it sees what the spot lights around it),
//    find the receiver points y; each stands for the solid angle
//    Omega_r / rays of the receiver, Omega_r = 2 pi (1 - cos(fov / 2));
//  - every VPL lights every receiver point it sees (an Embree shadow ray:
//    exact visibility), the radiance y returns to the lidar times y's solid
//    angle landing in the bin of the VPL's path + eta |x - y| + eta r_y (no
//    r_y with time.camera_unwarp):
//
//      E += Omega_r / rays x f_y x f_vpl x flux x G x T
//
//    with IR's gather physics (physics::vplScatter, vplRadiance and
//    geometryTerm with render.indirect.geometry_term_clamp, the BRDFs at
//    both ends, render.indirect.vpl_brdf_clamp for glossy VPLs) and T the
//    medium's transmittance over the legs. A receiver point on the spot's
//    own plane gets nothing from it (cos = 0): on a plane the multipath is 0.
// The unit is the direct echo's (W m^-2 per pulse at the receiver's
// aperture). The direct echo itself stays DirectWaveforms' (the receiver
// sees the whole spot); the receiver field of view is what widens what the
// multipath collects.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tofsim/lidar/BeamPattern.h"
#include "tofsim/lidar/DirectWaveforms.h"
#include "tofsim/lidar/LidarSpec.h"
#include "tofsim/lidar/MultipathSettings.h"

namespace tofsim::lidar {

/// What every beam's multipath shares: the two ray layouts and the solid
/// angle each receiver ray stands for (sr).
struct MultipathRays {
  std::vector<BeamRay> spot;      ///< the laser's, by the beam's profile
  std::vector<BeamRay> receiver;  ///< uniform (tophat) over receiver_fov
  double receiverRaySolidAngle_sr = 0.0;
};
MultipathRays multipathRays(const LidarSpec& spec, const MultipathSettings& settings);

/// Adds the multipath of a beam along unit `axis` into `waveform`
/// (axis.bins floats); `beam`: its index, which seeds its later bounces.
/// Returns what fell off the time axis.
WaveformLoss addBeamMultipath(const LidarSpec& spec, const MultipathSettings& settings,
                              const MultipathRays& rays, const WaveformScene& scene,
                              const TimeAxis& axis, const glm::vec3& beamAxis, uint64_t beam,
                              float* waveform);

/// Beams added per task by addMultipathWaveforms (their losses summed per
/// block, then the blocks in order): a rolling scan sums its losses the same way.
constexpr std::size_t kMultipathBlock = 64;

/// Adds every beam's multipath to `waveforms` (renderDirectWaveforms'
/// volume and losses), on `threads` threads over fixed blocks of beams:
/// the same bytes for any thread count. Nothing when settings are off.
void addMultipathWaveforms(const LidarSpec& spec, const MultipathSettings& settings,
                           const WaveformScene& scene, const TimeAxis& axis, int threads,
                           LidarWaveforms& waveforms);

}  // namespace tofsim::lidar
