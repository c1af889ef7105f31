#pragma once
// The one contract between the GL backend's C++ and its shaders: binding
// points, attribute and output locations, the work-group size and the channel
// count. Each number is written here only; shaders see it as a #define
// (TOFSIM_...) that makeProgram hands to the existing shader assembly, so a
// shader that uses a binding without going through makeProgram fails to
// compile instead of silently using another number.
//
// Each enumeration counts up from 0, so no binding point serves two buffers
// (or two textures) in any pass.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "tofsim/capture/RenderJob.h"
#include "tofsim/capture/RenderSettings.h"
#include "tofsim/capture/SegmentSink.h"
#include "tofsim/gl/Program.h"

namespace tofsim::render::gpu {

/// local_size_x of every compute shader (TOFSIM_WORK_GROUP_SIZE).
inline constexpr uint32_t kWorkGroupSize = 64;
/// Channels per bin of the volumes (TOFSIM_CHANNELS).
inline constexpr int kChannels = capture::kChannels;

/// Shader storage buffer bindings (TOFSIM_SSBO_...).
enum StorageBinding : uint32_t {
  kDirectVolume,      ///< segment's direct light, written by direct_gather.comp
  kIndirectVolume,    ///< segment's indirect light, indirect_gather.comp
  kOutsideAxis,       ///< two floats per pixel: light before / after the axis
  kVpls,              ///< struct Vpl[] (vpl.glsl)
  kCorners,           ///< triangle corners in BVH order (scene_geometry.glsl)
  kAreaCdf,           ///< cumulative triangle areas
  kBvh,               ///< BVH nodes
  kIsm,               ///< imperfect shadow maps of the resident batch
  kLoopGuard,         ///< flag raised near llvmpipe's loop-trip limit
  kFootprint,         ///< segment's footprint difference buffer: bins x 3 doubles per pixel
  kFootprintWritten,  ///< one uint per pixel: its difference buffer holds entries
  kFootprintVolume,   ///< the volume footprint_integrate.comp adds the buffer to
  kSampledPixels,     ///< one uint per pixel: 1 = N x N samples, 0 = its centre (ADAPTIVE_SAMPLES)
  kPixelRaySteps,  ///< two vec4 per pixel: a lens camera's ray steps along x, y (PIXEL_RAY_STEPS)
  kResponseState,  ///< 16 doubles per pixel: response_integrate.comp's sums between chunks
  kResponseTaps,   ///< the delayed response classes' filters (PixelFootprint)
  kScatterVertices,  ///< the G-buffers' vertices by index: the materials', then given samples'
  kSampleCameraEnds,  ///< vec4 per given sample: its camera end, lens path (SAMPLE_CAMERA_ENDS)
  kResponseCompose,   ///< the response classes' compose table, uint (GatherResponseClasses)
  kMediumRays,        ///< vec4 per sample: its ray direction (medium_direct.comp, issue 42)
  kMediumVplVolume,   ///< segment's VPL light scattered into the camera rays (medium_vpls.comp)
  kMediumVplOutside,  ///< its two floats per pixel off the axis
  kRegions,           ///< per-region media: struct Region[] (medium_regions.glsl, issue 42)
  kRegionCorners,     ///< their triangles' corners, vec4, 3 per triangle
  kRegionLegs,        ///< two vec4 per sample: its camera and light legs' passage (region_legs.comp)
};

/// Texture units (TOFSIM_UNIT_...).
enum TextureUnit : uint32_t {
  kGPosition,                 ///< camera G-buffer: world position
  kGNormal,                   ///< camera G-buffer: normal
  kGAlbedo,                   ///< camera G-buffer: base-colour texel, vertex index
  kShadowMap,                 ///< the light's distance cube (light.glsl)
  kAlbedoTexture,             ///< a material's base-colour texture (gbuffer.frag)
  kGMetallicRoughness,        ///< camera G-buffer: metallic-roughness texel (render.materials: gltf)
  kMetallicRoughnessTexture,  ///< a material's metallic-roughness texture (gbuffer.frag)
  // The pixel-centre G-buffer of the one-sample pixels (ADAPTIVE_SAMPLES).
  kCentrePosition,           ///< world position
  kCentreNormal,             ///< normal
  kCentreAlbedo,             ///< base-colour texel, vertex index
  kCentreMetallicRoughness,  ///< metallic-roughness texel (render.materials: gltf)
};

/// Vertex attribute locations of gbuffer.vert (TOFSIM_ATTRIB_...).
enum VertexAttribute : uint32_t { kPositionAttribute, kNormalAttribute, kUvAttribute };

/// Fragment outputs of gbuffer.frag (TOFSIM_OUT_...); distance.frag writes
/// kOutPosition's location, its only output.
enum FragmentOutput : int { kOutPosition, kOutNormal, kOutAlbedo, kOutMetallicRoughness };

/// The contract as (TOFSIM_NAME, value) defines.
std::vector<std::pair<std::string, std::string>> shaderDefines();

/// The gathers' variant of the job (direct_gather.comp, indirect_gather.comp):
/// PIXEL_SAMPLES (render.pixel_samples), PIXEL_FOOTPRINT, VPL_FOOTPRINT,
/// GLTF_MATERIALS (render.materials: gltf), VPL_VERTICES (whole VPL records:
/// ir::vplsCarryVertex), MEDIUM_VPLS (a scattering medium: medium VPLs,
/// tested exactly whatever the visibility), ADAPTIVE_SAMPLES
/// (render.adaptive_pixel_samples with pixel_samples > 1), SURFACE_STEPS (a
/// footprint over an imager whose steps are the surface's: a point set). As
/// defines, so that render.pixel_footprint: false compiles the point-sampling
/// shader of before, render.materials: lambertian the Lambertian one, and a
/// render without adaptive samples the shader that reads no per-pixel mask.
/// MEDIUM_REGIONS (per-region media, `media:`: the legs through their
/// regions, medium_regions.glsl).
/// SCATTER_MODEL (the model every vertex has, render.materials') unless
/// !foldModel: vertices of other models (given medium samples) are read.
std::vector<std::pair<std::string, std::string>> gatherDefines(const capture::RenderJob& job,
                                                               bool foldModel = true);

/// render.adaptive_pixel_samples in effect: with pixel_samples > 1 only (one
/// sample per pixel has nothing to skip). The gathers' ADAPTIVE_SAMPLES.
inline bool adaptiveSamples(const capture::RenderSettings& settings) {
  return settings.adaptive_pixel_samples && settings.pixel_samples > 1;
}

/// A program from embedded shaders with the contract's defines, then `extra`.
gl::Program makeProgram(const std::vector<gl::ShaderStage>& stages,
                        const std::vector<std::pair<std::string, std::string>>& extra = {});

}  // namespace tofsim::render::gpu
