#pragma once
// Private to the config module: the `camera:` section's parameter tables
// (see RunFields.h): `camera`, `camera.lens` and `camera.psf`. Keys whose
// values depend on each other are read as plain values and checked over the
// parsed struct by the section (CameraConfigParser.cpp, PsfConfig.cpp):
// fov_y or a lens, the aperture's three keys, a kernel file or the
// parametric PSF. A table's order is the order the keys are read and written.

#include <array>
#include <cstdint>
#include <limits>
#include <tuple>

#include "RunFields.h"
#include "tofsim/optics/PsfKernel.h"

namespace tofsim::config {

// clang-format off
inline constexpr auto kCameraFields = std::tuple{
    Field{"gltf_camera", &CameraConfig::gltf_camera, Text{},
          {.doc = "name or index of a glTF camera; its position, orientation and fov replace the keys below (resolution still applies)", .unset = "\"\""}},
    In{"position", &CameraConfig::camera, &capture::Camera::position_world, Vec3{},
       {.unit = "m", .doc = "pinhole position"}},
    In{"look_at", &CameraConfig::camera, &capture::Camera::look_at_world, Vec3{},
       {.unit = "m", .doc = "point on the optical axis; must differ from `position`"}},
    In{"up", &CameraConfig::camera, &capture::Camera::up_world, Vec3{},
       {.doc = "up direction; not parallel to the view direction"}},
    Custom{"lens", "mapping", "", "none", "-",
           "a calibrated lens (OpenCV's model) in place of `fov_y`, see below"},
    In{"fov_y", &CameraConfig::camera, &capture::Camera::fov_y_deg, Angle{.rangeDoc = "in (0, 180)"},
       {.doc = "full vertical field of view"}},
    Custom{"resolution", "[int, int]", "", "[64, 64]", "pixel",
           "width, height, each in [1, 16384]; with a lens calibration file, its image size"},
    Custom{"vignetting", "string", "", "none", "-",
           "`none`; `cos4`, a thin lens's fall-off: each pixel's light times cos^4 of its ray's angle to the optical axis; or a .npy (H, W) float32 map of gains in [0, 1000], not all 0 (a flat field, relative to the config). Every output and sensor sees it"},
    Custom{"psf", "mapping", "", "none", "-",
           "the lens's point spread function (stray light) on every time bin, or equivalently on the CW-ToF raws, see below"},
    In{"aperture", &CameraConfig::camera, &capture::Camera::aperture_m, Checked{sensors::Length{}, ">= 0"},
       {.doc = "thin-lens defocus: the aperture's diameter (`0`: a pinhole, sharp at every depth). Each pixel sample traces `aperture_samples` rays from points of the aperture disk through its point on the plane in focus, so a surface at depth z blurs over the circle of confusion aperture abs(z - focus_distance) / (z focus_distance) (at unit distance; over the pixel's angle: pixels), and its camera leg is timed through its aperture point and the lens (an in-focus surface's light arrives as through the pinhole). `render.renderer: ir` with `render.backend: cpu` only (`auto` picks it); cost: `bench/defocus`"}},
    In{"focus_distance", &CameraConfig::camera, &capture::Camera::focus_distance_m, Checked{sensors::Length{}, "> 0"},
       {.doc = "with `aperture`: the depth (along the optical axis) of the plane in focus; required then, an error without an aperture"}},
    In{"aperture_samples", &CameraConfig::camera, &capture::Camera::aperture_samples,
       Checked{IntegerIn{std::numeric_limits<int32_t>::min(), std::numeric_limits<int32_t>::max()}, "in [2, 4096]"},
       {.doc = "with `aperture`: the aperture points each pixel sample traces (Vogel's sunflower spiral: equal areas, the same for every pixel, so the bytes do not depend on threads or budgets); the render costs about this many times the pinhole's first-surface and gather work"}},
};

// The keys of `camera.lens`: their forms (a list, nested rows, a
// cv::FileStorage matrix, a calibration file) are read by LensConfig.cpp.
inline constexpr auto kLensFields = std::tuple{
    Custom{"camera_matrix", "[9 numbers]", "", "required", "pixel",
           "OpenCV's camera matrix row by row, [fx, 0, cx, 0, fy, cy, 0, 0, 1], pixel centres at integers (a list, nested rows or a cv::FileStorage matrix)"},
    Custom{"distortion", "list", "of 4, 5, 8, 12 or 14", "[0, 0, 0, 0]", "-",
           "OpenCV's distortion coefficients in its order: k1 k2 p1 p2 [k3 [k4 k5 k6 [s1 s2 s3 s4 [tau_x tau_y]]]]"},
    Custom{"calibration", "path", "", "none", "-",
           "an OpenCV calibration YAML (cv::FileStorage's: camera_matrix, distortion_coefficients, image_width, image_height) in place of the two keys above; relative to the config"},
};

inline constexpr std::array<Name<optics::HaloProfile>, 2> kHaloProfileNames{
    {{"gaussian", optics::HaloProfile::Gaussian}, {"exponential", optics::HaloProfile::Exponential}}};

// The keys of `camera.psf`: the parametric kernel's, or `file` in their place.
inline constexpr auto kPsfFields = std::tuple{
    In{"core_sigma", &PsfConfig::params, &optics::PsfParams::core_sigma_px, Checked{Number{}, ">= 0"},
       {.unit = "pixel", .doc = "the core's Gaussian sigma, integrated over each pixel; 0: a delta (the pixel keeps its light)"}},
    In{"halo_weight", &PsfConfig::params, &optics::PsfParams::halo_weight, Checked{Number{}, "in [0, 1)"},
       {.doc = "s: the halo's share of the light, K = (1 - s) core + s halo"}},
    In{"halo_profile", &PsfConfig::params, &optics::PsfParams::halo_profile, Choice<optics::HaloProfile>{kHaloProfileNames},
       {.doc = "`gaussian` (sigma `halo_radius`) or `exponential` (exp(-r / `halo_radius`), the long tail measured stray light has)"}},
    In{"halo_radius", &PsfConfig::params, &optics::PsfParams::halo_radius_px, Checked{Number{}, "> 0"},
       {.unit = "pixel", .doc = "the halo's sigma or decay length; required with `halo_weight` > 0"}},
    Custom{"file", "path", "", "none", "-",
           "a measured kernel in place of the four keys above: a 2-D float32 .npy (H, W), odd sizes, centre at (H/2, W/2), values finite and >= 0, normalised on load; relative to the config"},
};
// clang-format on

}  // namespace tofsim::config
