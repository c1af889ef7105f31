#pragma once
// Everything that controls one transient render besides the scene, camera and
// light. Field names carry their units.

#include <cstddef>
#include <cstdint>

#include "tofsim/capture/Medium.h"
#include "tofsim/capture/MediumRegions.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::capture {

enum class Visibility { Ism, Exact };

/// How surfaces reflect (render.materials). Lambertian: albedo / pi for every
/// material, the renderer of before. Gltf: the glTF metallic-roughness BRDF
/// (shaders/gltf_brdf.glsl) in the direct light and at both ends of every VPL
/// contribution: the VPL's BRDF toward x (for the direction its light came
/// from) and x's toward the camera.
enum class MaterialModel { Lambertian, Gltf };

struct IndirectSettings {
  bool enabled = true;
  int32_t rsm_resolution = 32;    ///< RSM side; VPL count = rsm_resolution^2
  /// With a scattering medium (RenderSettings::medium, sigma_s > 0): rays
  /// from the light that leave a medium VPL each where they scatter before
  /// any surface (ir::lightMediumVpls), bounce 1 after the RSM's; 0 = none.
  /// 1024: the default RSM's count (32^2).
  int32_t medium_vpls = 1024;
  /// With a scattering medium: every VPL's light scattered once more into
  /// the pixels' camera rays (core/physics/medium_vpl_scattering.md),
  /// sampled: a roulette keeps ~4096 (ray, VPL) pairs a ray, 2 points each
  /// (fog_lidar: 2.0 CPU-s without, 3.9 with); off, the camera rays see the
  /// light source's single scattering only.
  bool medium_camera_rays = true;
  /// N > 0: the CPU surface gather keeps about N (pixel sample, VPL) pairs a
  /// sample, each with probability min(1, e / threshold) and its light
  /// weighed by the inverse (cpu GatherRoulette.h; core/physics/
  /// medium_vpl_scattering.md, "The surface gather sampled"); 0 = every pair.
  int32_t gather_pairs = 0;
  /// N: a texel at an edge of the RSM is traced at N x N sub-texels, one
  /// VPL per flat surface among them (ir::rsmViewVpls); 1 = none.
  int32_t rsm_edge_samples = 4;
  /// With pixel_samples N > 1, the CPU backend gathers a pixel's indirect
  /// light once per flat surface among its samples (cpu MergedSamples.h).
  bool merge_pixel_samples = false;
  int32_t ism_resolution = 32;    ///< side of each VPL's paraboloid depth map
  /// ISM points splatted per VPL; 0 = two per texel of the finest map
  /// (ismPointsPerVpl).
  int32_t points_per_vpl = 0;
  bool ism_pull_push = true;      ///< fill ISM holes by pull-push
  Visibility visibility = Visibility::Ism;
  /// Upper bound of the geometry term cos*cos/d^2 (1/m^2); <= 0 disables clamping.
  double geometry_term_clamp_per_m2 = 100.0;
  /// render.materials: gltf: upper bound (1/sr, per channel) of a VPL's BRDF
  /// value toward x, and of its BRDF weight when a later bounce continues
  /// its path; <= 0 disables clamping.
  double vpl_brdf_clamp_per_sr = 0.0;
  /// Spread each VPL's light over the path variation across its RSM texel's
  /// patch (anti-banding); only with RenderSettings::pixel_footprint.
  bool vpl_footprint = true;
  /// Indirect bounces: 1 = the RSM's VPLs only; k > 1 adds VPLs of bounces
  /// 2..k, each traced from those of the bounce before (core/ir BounceVpls.h).
  int32_t bounces = 1;
  /// VPLs traced for each bounce after the first; 0 = as many as the first
  /// bounce has (rays that leave the scene make none).
  int32_t vpls_per_bounce = 0;
  /// Russian roulette on the later bounces: a child VPL survives with
  /// probability q = its hit's largest albedo channel, its flux divided by q,
  /// and each bounce after the second traces as many rays as the bounce
  /// before has VPLs. false: every bounce traces vpls_per_bounce rays.
  bool russian_roulette = false;
  /// Threads tracing the later bounces' rays (render.threads); 0 = all. The
  /// bytes do not depend on it.
  int32_t trace_threads = 0;
};

/// The ISM points splatted per VPL: points_per_vpl, or where 0, two per
/// texel of the map (2 ism_resolution^2). The ISM's verdicts depend on the
/// points per texel: sparser maps have holes whose pull-push fill lies
/// behind the occluders (light leaks), denser ones find each texel's nearest
/// surface where two meet (light hidden); about two per texel balances them
/// (bench/README.md, "The ISM's bias").
inline int32_t ismPointsPerVpl(const IndirectSettings& s) {
  if (s.points_per_vpl > 0) return s.points_per_vpl;
  const int64_t two = 2 * int64_t{s.ism_resolution} * s.ism_resolution;
  return static_cast<int32_t>(two < (int64_t{1} << 24) ? two : (int64_t{1} << 24));
}

struct RenderSettings {
  /// Arrival-time histogram bins, and how optical path becomes time: the
  /// medium's index of refraction and camera_unwarp (drop the surface ->
  /// camera delay) live there only, read by the renderers and the sensors.
  TimeAxis time;
  int32_t shadow_map_resolution = 1024;  ///< per cube face of the light's shadow map
  /// Bytes of GPU memory the volume segments and ISM batches may use.
  std::size_t memory_budget_bytes = std::size_t{512} << 20;
  uint64_t seed = 1;
  /// A pixel integrates its area: every contribution is spread over its
  /// optical path's distribution across the pixel (footprint_kernel.md).
  /// false: one point per (sub-)pixel, all of its light in one bin.
  bool pixel_footprint = true;
  /// N x N stratified G-buffer samples per pixel, averaged.
  int32_t pixel_samples = 1;
  /// With pixel_samples N > 1: the N x N samples only in pixels at an edge of
  /// the centre G-buffer (ir::sampledPixels); one sample at the centre, with
  /// weight 1 and the whole pixel's footprint, everywhere else.
  bool adaptive_pixel_samples = false;
  MaterialModel materials = MaterialModel::Lambertian;
  IndirectSettings indirect;
  /// The homogeneous medium filling the scene (issue 42); none by default.
  /// Its index of refraction is time.index_of_refraction.
  Medium medium;
  /// Media inside closed meshes (issue 42's `media:`; MediumRegions.h), in
  /// place of `medium`; their meshes are the scene's regions.
  std::vector<RegionMedium> media;

  /// Whether the VPLs' light scatters into the camera rays (a scattering
  /// medium and indirect.medium_camera_rays): the backends' medium VPL pass.
  bool vplsLightCameraRays() const { return medium.scatters() && indirect.medium_camera_rays; }
};

}  // namespace tofsim::capture
