#include "tofsim/pipeline/Metadata.h"

#include <nlohmann/json.hpp>

#include "TimeAxisJson.h"
#include "tofsim/pipeline/AxisReport.h"
#include "tofsim/pipeline/OutputProducts.h"
#include "tofsim/pipeline/Version.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::pipeline {

namespace {
nlohmann::json vec(const glm::vec3& v) { return {v.x, v.y, v.z}; }
}  // namespace

std::string transientMetadataJson(const config::RunConfig& config, const capture::RenderJob& job,
                                  const capture::RenderResult& result, const std::string& backend,
                                  const std::string& device) {
  const TimeAxis& axis = job.settings.time;
  const capture::Camera& cam = job.camera();
  const capture::Light& light = job.light;
  nlohmann::json j;
  j["format"] = "tofsim transient volume";
  j["tofsim_version"] = kVersion;
  j["files"] = nlohmann::json::object();
  for (const auto& [role, file] : metadataFiles()) j["files"][role] = file;
  j["shape"] = {cam.height, cam.width, axis.bins, 3};
  j["axes"] = {"y", "x", "t", "c"};
  j["axes_doc"] =
      "value[y][x][t][c]: row y (0 = top), column x (0 = left), time bin t, channel c; "
      "float32, C order";
  j["channels"] = {"R", "G", "B"};
  j["value_unit"] = "W m^-2 sr^-1";
  j["value_doc"] =
      "radiance arriving within the bin for an impulse of the light at t = 0 (the scene's "
      "impulse response); summing over t gives the steady-state radiance under a continuous "
      "light of the same intensity";
  nlohmann::ordered_json time = timeAxisJson(axis);
  time["time_origin"] =
      axis.camera_unwarp
          ? "emission at the light; the surface -> camera delay is removed (time at the surface)"
          : "emission at the light; arrival at the camera";
  j["time"] = time;
  j["camera"] = {{"position_m", vec(cam.position_world)},
                 {"look_at_m", vec(cam.look_at_world)},
                 {"up", vec(cam.up_world)},
                 {"fov_y_deg", cam.fov_y_deg},
                 {"width", cam.width},
                 {"height", cam.height},
                 {"model", "pinhole, one ray through each pixel centre"}};
  j["light"] = {{"type", light.type == capture::Light::Type::Spot ? "spot" : "point"},
                {"position_m", vec(light.position_world)},
                {"direction", vec(light.direction_world)},
                {"cone_half_angle_deg", light.cone_half_angle_deg},
                {"cone_falloff_deg", light.cone_falloff_deg},
                {"intensity_W_per_sr", vec(light.intensity_W_per_sr)},
                {"attached_to_camera", config.light.attach_to_camera}};
  j["renderer"] = config.renderer == config::RendererKind::Reference ? "reference" : "ir";
  j["backend"] = backend;
  j["device"] = device;
  j["seed"] = job.settings.seed;
  // What bounce<k>.npy can hold, and what `tofsim sense` takes as the
  // light's bounce orders (cwtof multipath_by_order).
  j["indirect_bounces"] = surfaceVertices(config) - 1;
  j["scene"] = config.scene_file.filename().string();
  const AxisLossFractions lost = axisLossFractions(result);
  j["stats"] = {{"seconds", result.seconds},
                {"segments", result.segments},
                {"vpls", result.vpls},
                {"vpl_batches", result.vplBatches},
                {"sampled_pixels", result.sampledPixels},
                {"peak_gpu_bytes", result.peakGpuBytes},
                {"energy_outside_time_axis", result.offAxis.total()},
                {"energy_before_axis", result.offAxis.before},
                {"energy_after_axis", result.offAxis.after},
                {"energy_on_axis", result.onAxisEnergy},
                {"fraction_before_axis", lost.before},
                {"fraction_after_axis", lost.after},
                {"rejected_non_finite_values", result.nonFiniteRejected}};
  const capture::PassSeconds& pass = result.passSeconds;
  j["stats"]["pass_seconds"] = {
      {"surfaces", pass.surfaces}, {"vpls", pass.vpls},         {"visibility", pass.visibility},
      {"direct", pass.direct},     {"indirect", pass.indirect}, {"read_back", pass.readBack},
      {"other", pass.other}};
  return j.dump(2) + "\n";
}

}  // namespace tofsim::pipeline
