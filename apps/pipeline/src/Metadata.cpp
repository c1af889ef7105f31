#include "tofsim/pipeline/Metadata.h"

#include <nlohmann/json.hpp>

#include "RenderStatsJson.h"
#include "TimeAxisJson.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/pipeline/AxisReport.h"
#include "tofsim/pipeline/OutputProducts.h"
#include "tofsim/pipeline/Version.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::pipeline {

namespace {

nlohmann::json vec(const glm::vec3& v) { return {v.x, v.y, v.z}; }

/// How transient.npy is laid out and what its values are.
void addVolumeLayout(nlohmann::json& j, const capture::Imager& imager, const TimeAxis& axis) {
  j["shape"] = {capture::imageHeight(imager), capture::imageWidth(imager), axis.bins, 3};
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
}

/// The time axis, with where its zero is and which path its times measure.
nlohmann::ordered_json timeJson(const TimeAxis& axis) {
  nlohmann::ordered_json time = timeAxisJson(axis);
  time["time_origin"] =
      axis.camera_unwarp
          ? "emission at the light; the surface -> camera delay is removed (time at the surface)"
          : "emission at the light; arrival at the camera";
  return time;
}

nlohmann::json cameraJson(const capture::Camera& cam) {
  nlohmann::json j = {{"position_m", vec(cam.position_world)},
                      {"look_at_m", vec(cam.look_at_world)},
                      {"up", vec(cam.up_world)},
                      {"width", cam.width},
                      {"height", cam.height}};
  if (const auto& lens = cam.lens) {
    j["lens"] = {{"fx_px", lens->fx},
                 {"fy_px", lens->fy},
                 {"cx_px", lens->cx},
                 {"cy_px", lens->cy},
                 {"distortion", lens->distortion},
                 {"distortion_order", "k1 k2 p1 p2 k3 k4 k5 k6 s1 s2 s3 s4 tau_x tau_y (OpenCV)"},
                 {"pixel_convention", "OpenCV: pixel (x, y)'s centre at (x, y), +y down"}};
    j["model"] = "calibrated lens (OpenCV's model): one ray through each pixel centre, undistorted";
  } else {
    j["fov_y_deg"] = cam.fov_y_deg;
    j["model"] = "pinhole, one ray through each pixel centre";
  }
  // Only with an aperture: a pinhole's metadata keeps its bytes.
  if (cam.defocused()) {
    j["thin_lens"] = {
        {"aperture_m", cam.aperture_m},
        {"focus_distance_m", cam.focus_distance_m},
        {"aperture_samples", cam.aperture_samples},
        {"pattern", "Vogel's sunflower spiral on the aperture disk, the same for every pixel"},
        {"timing",
         "camera leg to each aperture point plus the lens's path to the pixel less the "
         "chief ray's (a surface in focus arrives as through the pinhole)"}};
  }
  return j;
}

nlohmann::json vignettingJson(const capture::Vignetting& v) {
  switch (v.kind) {
    case capture::Vignetting::Kind::Cos4:
      return "cos4: each pixel's light times cos^4 of its ray's angle to the optical axis";
    case capture::Vignetting::Kind::Map:
      return "map: each pixel's light times its gain in " + v.file;
    case capture::Vignetting::Kind::None:
      break;
  }
  return "none";
}

// What the lens's scattering was: its parameters or its kernel file.
nlohmann::json psfJson(const config::PsfConfig& psf) {
  nlohmann::json j;
  j["model"] =
      "each time bin convolved with the kernel, the scattered light keeping its delay; light "
      "thrown past the sensor's edge lost";
  if (!psf.file.empty()) {
    j["kernel_file"] = psf.file;
  } else {
    j["core_sigma_px"] = psf.params.core_sigma_px;
    j["halo_weight"] = psf.params.halo_weight;
    j["halo_profile"] = optics::haloProfileName(psf.params.halo_profile);
    j["halo_radius_px"] = psf.params.halo_radius_px;
  }
  j["kernel_radius_px"] = {psf.kernel.radiusX(), psf.kernel.radiusY()};
  return j;
}

nlohmann::json lightJson(const capture::Light& light, bool attachedToCamera) {
  return {{"type", light.type == capture::Light::Type::Spot ? "spot" : "point"},
          {"position_m", vec(light.position_world)},
          {"direction", vec(light.direction_world)},
          {"cone_half_angle_deg", light.cone_half_angle_deg},
          {"cone_falloff_deg", light.cone_falloff_deg},
          {"intensity_W_per_sr", vec(light.intensity_W_per_sr)},
          {"attached_to_camera", attachedToCamera}};
}

// The medium that filled the scene: its coefficients as the renderers took
// them, and the visibility they came from (fog).
nlohmann::json mediumJson(const capture::Medium& m, const config::MediumConfig& form,
                          const TimeAxis& axis) {
  nlohmann::json j = {
      {"model",
       "homogeneous, filling the scene: each leg of geometric length x attenuated by "
       "exp(-sigma_t x); light scattered once in it is direct light (bounce 1)"},
      {"sigma_a_per_m", vec(m.sigma_a_per_m)},
      {"sigma_s_per_m", vec(m.sigma_s_per_m)},
      {"sigma_t_per_m", vec(m.sigmaT())},
      {"albedo", vec(m.albedo())},
      {"phase", config::phaseModelName(m.phase)},
      {"index_of_refraction", axis.index_of_refraction}};
  if (m.phase == physics::PHASE_HENYEY_GREENSTEIN) j["g"] = m.g;
  if (form.visibility_m > 0.0) {
    j["visibility_m"] = form.visibility_m;
    j["visibility_doc"] = "fog: sigma_t = 3.912 / visibility (Koschmieder)";
  }
  return j;
}

// Per-region media (`media:`): each region's medium and index.
nlohmann::json mediaJson(const std::vector<capture::RegionMedium>& media) {
  nlohmann::json list = nlohmann::json::array();
  for (const capture::RegionMedium& r : media) {
    nlohmann::json j = {
        {"region", r.region},
        {"model",
         "homogeneous inside the closed mesh `region` (an interface, not a surface): each leg "
         "attenuated by exp(-sigma_t x its length inside), slowed to c / index_of_refraction "
         "there"},
        {"sigma_a_per_m", vec(r.medium.sigma_a_per_m)},
        {"sigma_s_per_m", vec(r.medium.sigma_s_per_m)},
        {"sigma_t_per_m", vec(r.medium.sigmaT())},
        {"albedo", vec(r.medium.albedo())},
        {"phase", config::phaseModelName(r.medium.phase)},
        {"index_of_refraction", r.index_of_refraction}};
    if (r.medium.phase == physics::PHASE_HENYEY_GREENSTEIN) j["g"] = r.medium.g;
    list.push_back(j);
  }
  return list;
}

}  // namespace

std::string transientMetadataJson(const config::RunConfig& config, const capture::RenderJob& job,
                                  const capture::RenderResult& result, const std::string& backend,
                                  const std::string& device) {
  const TimeAxis& axis = job.settings.time;
  nlohmann::json j;
  j["format"] = "tofsim transient volume";
  j["tofsim_version"] = kVersion;
  j["files"] = nlohmann::json::object();
  for (const auto& [role, file] : metadataFiles(config.output)) j["files"][role] = file;
  addVolumeLayout(j, job.imager, axis);
  j["time"] = timeJson(axis);
  // The camera, for an imager that is one; other kinds say which they are.
  if (!capture::cameraOf(job.imager)) j["imager"] = capture::imagerKind(job.imager);
  if (const capture::Camera* camera = capture::cameraOf(job.imager)) {
    j["camera"] = cameraJson(*camera);
    j["camera"]["vignetting"] = vignettingJson(config.camera.vignetting);
    // Only with a PSF: the files of a sharp lens keep their bytes.
    if (config.camera.psf) j["camera"]["psf"] = psfJson(*config.camera.psf);
  }
  j["light"] = lightJson(job.light, config.light.attach_to_camera);
  // Only with a medium: the files of a render in vacuum keep their bytes.
  if (job.settings.medium.present() && config.medium) {
    j["medium"] = mediumJson(job.settings.medium, *config.medium, axis);
  }
  if (!job.settings.media.empty()) j["media"] = mediaJson(job.settings.media);
  j["renderer"] = config.renderer == config::RendererKind::Reference ? "reference" : "ir";
  j["backend"] = backend;
  j["device"] = device;
  j["seed"] = job.settings.seed;
  // What bounce<k>.npy can hold, and what `tofsim sense` takes as the
  // light's bounce orders (cwtof multipath_by_order).
  j["indirect_bounces"] = surfaceVertices(config) - 1;
  j["scene"] = config.scene_file.filename().string();
  j["stats"] = renderStatsJson(result);
  return j.dump(2) + "\n";
}

}  // namespace tofsim::pipeline
