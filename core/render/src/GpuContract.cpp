#include "GpuContract.h"

#include "tofsim/ir/IrBackend.h"
#include "tofsim/ir/MediumVpl.h"
#include "tofsim/render/GlRegionLimits.h"

namespace tofsim::render::gpu {

std::vector<std::pair<std::string, std::string>> shaderDefines() {
  const auto n = [](auto value) { return std::to_string(static_cast<long long>(value)); };
  return {
      {"TOFSIM_WORK_GROUP_SIZE", n(kWorkGroupSize)},
      {"TOFSIM_CHANNELS", n(kChannels)},
      {"TOFSIM_SSBO_DIRECT_VOLUME", n(kDirectVolume)},
      {"TOFSIM_SSBO_INDIRECT_VOLUME", n(kIndirectVolume)},
      {"TOFSIM_SSBO_OUTSIDE_AXIS", n(kOutsideAxis)},
      {"TOFSIM_SSBO_VPLS", n(kVpls)},
      {"TOFSIM_SSBO_CORNERS", n(kCorners)},
      {"TOFSIM_SSBO_AREA_CDF", n(kAreaCdf)},
      {"TOFSIM_SSBO_BVH", n(kBvh)},
      {"TOFSIM_SSBO_ISM", n(kIsm)},
      {"TOFSIM_SSBO_LOOP_GUARD", n(kLoopGuard)},
      {"TOFSIM_SSBO_FOOTPRINT", n(kFootprint)},
      {"TOFSIM_SSBO_FOOTPRINT_WRITTEN", n(kFootprintWritten)},
      {"TOFSIM_SSBO_FOOTPRINT_VOLUME", n(kFootprintVolume)},
      {"TOFSIM_SSBO_SAMPLED_PIXELS", n(kSampledPixels)},
      {"TOFSIM_SSBO_PIXEL_RAY_STEPS", n(kPixelRaySteps)},
      {"TOFSIM_SSBO_RESPONSE_STATE", n(kResponseState)},
      {"TOFSIM_SSBO_RESPONSE_TAPS", n(kResponseTaps)},
      {"TOFSIM_SSBO_SCATTER_VERTICES", n(kScatterVertices)},
      {"TOFSIM_SSBO_SAMPLE_CAMERA_ENDS", n(kSampleCameraEnds)},
      {"TOFSIM_SSBO_RESPONSE_COMPOSE", n(kResponseCompose)},
      {"TOFSIM_SSBO_MEDIUM_RAYS", n(kMediumRays)},
      {"TOFSIM_SSBO_MEDIUM_VPL_VOLUME", n(kMediumVplVolume)},
      {"TOFSIM_SSBO_MEDIUM_VPL_OUTSIDE", n(kMediumVplOutside)},
      {"TOFSIM_SSBO_REGIONS", n(kRegions)},
      {"TOFSIM_SSBO_REGION_CORNERS", n(kRegionCorners)},
      {"TOFSIM_SSBO_REGION_LEGS", n(kRegionLegs)},
      {"TOFSIM_REGION_CROSSINGS", n(kGlRegionCrossings)},
      {"TOFSIM_UNIT_G_POSITION", n(kGPosition)},
      {"TOFSIM_UNIT_G_NORMAL", n(kGNormal)},
      {"TOFSIM_UNIT_G_ALBEDO", n(kGAlbedo)},
      {"TOFSIM_UNIT_SHADOW_MAP", n(kShadowMap)},
      {"TOFSIM_UNIT_ALBEDO_TEXTURE", n(kAlbedoTexture)},
      {"TOFSIM_UNIT_G_METALLIC_ROUGHNESS", n(kGMetallicRoughness)},
      {"TOFSIM_UNIT_METALLIC_ROUGHNESS_TEXTURE", n(kMetallicRoughnessTexture)},
      {"TOFSIM_UNIT_CENTRE_POSITION", n(kCentrePosition)},
      {"TOFSIM_UNIT_CENTRE_NORMAL", n(kCentreNormal)},
      {"TOFSIM_UNIT_CENTRE_ALBEDO", n(kCentreAlbedo)},
      {"TOFSIM_UNIT_CENTRE_METALLIC_ROUGHNESS", n(kCentreMetallicRoughness)},
      {"TOFSIM_ATTRIB_POSITION", n(kPositionAttribute)},
      {"TOFSIM_ATTRIB_NORMAL", n(kNormalAttribute)},
      {"TOFSIM_ATTRIB_UV", n(kUvAttribute)},
      {"TOFSIM_OUT_POSITION", n(kOutPosition)},
      {"TOFSIM_OUT_NORMAL", n(kOutNormal)},
      {"TOFSIM_OUT_ALBEDO", n(kOutAlbedo)},
      {"TOFSIM_OUT_METALLIC_ROUGHNESS", n(kOutMetallicRoughness)},
  };
}

std::vector<std::pair<std::string, std::string>> gatherDefines(const capture::RenderJob& job,
                                                               bool foldModel) {
  const capture::RenderSettings& s = job.settings;
  std::vector<std::pair<std::string, std::string>> defines = {
      {"PIXEL_SAMPLES", std::to_string(s.pixel_samples)}};
  if (s.pixel_footprint) defines.emplace_back("PIXEL_FOOTPRINT", "1");
  if (s.pixel_footprint && s.indirect.vpl_footprint) defines.emplace_back("VPL_FOOTPRINT", "1");
  // The G-buffer's and the VPL records' layout (their glTF parameters), and
  // the one model of every vertex (scatter_vertex.glsl folds on it).
  if (s.materials == capture::MaterialModel::Gltf) defines.emplace_back("GLTF_MATERIALS", "1");
  if (ir::vplsCarryVertex(s)) defines.emplace_back("VPL_VERTICES", "1");
  // Medium VPLs among the VPLs (a scattering medium): their exact visibility.
  if (s.medium.scatters()) defines.emplace_back("MEDIUM_VPLS", "1");
  if (foldModel) {
    defines.emplace_back("SCATTER_MODEL", std::to_string(ir::vertexModelOf(s.materials)));
  }
  // Only with sub-samples to skip: every other render compiles the gathers
  // of before, which read no mask.
  if (adaptiveSamples(s)) defines.emplace_back("ADAPTIVE_SAMPLES", "1");
  // Rays with their own origins: each sample's camera end from a buffer
  // (camera_end.glsl); every other imager compiles the gathers of before.
  if (!capture::raysShareOrigin(job.imager)) defines.emplace_back("SAMPLE_CAMERA_ENDS", "1");
  const capture::Camera* camera = capture::cameraOf(job.imager);
  if (s.pixel_footprint && camera == nullptr) defines.emplace_back("SURFACE_STEPS", "1");
  if (s.pixel_footprint && camera != nullptr && camera->lens) {
    defines.emplace_back("PIXEL_RAY_STEPS", "1");
  }
  // A medium filling the scene (medium_uniforms.glsl); without one the
  // gathers of before.
  if (s.medium.present()) defines.emplace_back("MEDIUM", "1");
  // Per-region media (medium_regions.glsl); without them the gathers of before.
  if (!s.media.empty()) defines.emplace_back("MEDIUM_REGIONS", "1");
  return defines;
}

gl::Program makeProgram(const std::vector<gl::ShaderStage>& stages,
                        const std::vector<std::pair<std::string, std::string>>& extra) {
  std::vector<std::pair<std::string, std::string>> defines = shaderDefines();
  defines.insert(defines.end(), extra.begin(), extra.end());
  return gl::Program(stages, defines);
}

}  // namespace tofsim::render::gpu
