// The declared config keys (ConfigKeys.h). The README tables are checked
// against these rows by tests/config/ConfigKeysTest.cpp: change both together.
// The rows of a section with a parameter table come from it (RunFields.h,
// TimeFields.h, LightFields.h, OutputFields.h, NlosFields.h,
// SequenceFields.h; sensors: sensors/SensorFields.h); the literal rows below
// are the top level's and `camera`'s.
#include "tofsim/config/ConfigKeys.h"

#include <iterator>

#include "FieldDoc.h"
#include "LightFields.h"
#include "NlosFields.h"
#include "OutputFields.h"
#include "RunFields.h"
#include "SequenceFields.h"
#include "TimeFields.h"
#include "tofsim/sensors/SensorFields.h"

namespace tofsim::config {

namespace {
// clang-format off
const ConfigKey kRunConfigKeys[] = {
    {"scene", "string", "", "required", "-",
     "glTF file, relative to the config's folder"},
    {"camera", "mapping", "", "required", "-",
     "see below (`{}` for all defaults); not with `nlos`"},
    {"light", "mapping", "", "required", "-",
     "see below; not with `nlos`"},
    {"rays", "mapping", "", "none", "-",
     "a capture whose pixels are the rays of a file (a fibre bundle, a scanning pattern, a custom lens) instead of `camera`, see below; not with `camera`, `nlos` or `sequence`"},
    {"rays.file", "path", "", "required", "-",
     "the rays, one a row: a .npy (N, 6) float32 or float64, or a CSV of six columns ox, oy, oz, dx, dy, dz (m, world frame; a header row and `#` lines allowed), relative to the config; directions are normalised (a zero one is an error); read without following links"},
    {"rays.resolution", "[int, int]", "", "[N, 1]", "pixel",
     "width, height of the image the rays fill row by row; their product is N"},
    {"rays.last_leg_counts", "bool", "", "true", "-",
     "false: the leg from a ray's hit back to its origin takes no time (the arrival is timed at the hit)"},
    {"nlos", "mapping", "", "none", "-",
     "a non-line-of-sight relay-wall scan instead of `camera` and `light`, see below"},
    {"sequence", "mapping", "", "none", "-",
     "a capture sequence of the scene's glTF animations (frames at their own scene times) instead of one capture at the rest pose, see below; not with `nlos`"},
    {"time", "mapping", "", "required", "-",
     "see below"},
    {"render", "mapping", "", "defaults", "-",
     "see below"},
    {"output", "mapping", "", "defaults", "-",
     "see below"},
    {"sensors", "list", "", "none", "-",
     "sensor models run on the volume, see below"},
    {"materials", "mapping", "", "none", "-",
     "per glTF material name, its settings (a scattering delay), see below"},
    {"camera.gltf_camera", "string", "", "\"\"", "-",
     "name or index of a glTF camera; its position, orientation and fov replace the keys below (resolution still applies)"},
    {"camera.position", "vec3", "", "[0, 0, 0]", "m",
     "pinhole position"},
    {"camera.look_at", "vec3", "", "[0, 0, -1]", "m",
     "point on the optical axis; must differ from `position`"},
    {"camera.up", "vec3", "", "[0, 1, 0]", "-",
     "up direction; not parallel to the view direction"},
    {"camera.fov_y", "angle", "in (0, 180)", "40", "deg",
     "full vertical field of view"},
    {"camera.resolution", "[int, int]", "", "[64, 64]", "pixel",
     "width, height, each in [1, 16384]; with a lens calibration file, its image size"},
    {"camera.vignetting", "string", "", "none", "-",
     "`none`; `cos4`, a thin lens's fall-off: each pixel's light times cos^4 of its ray's angle to the optical axis; or a .npy (H, W) float32 map of gains in [0, 1000], not all 0 (a flat field, relative to the config). Every output and sensor sees it"},
    {"camera.lens", "mapping", "", "none", "-",
     "a calibrated lens (OpenCV's model) in place of `fov_y`, see below"},
    {"camera.aperture", "length", ">= 0", "0", "m",
     "thin-lens defocus: the aperture's diameter (`0`: a pinhole, sharp at every depth). Each pixel sample traces `aperture_samples` rays from points of the aperture disk through its point on the plane in focus, so a surface at depth z blurs over the circle of confusion aperture abs(z - focus_distance) / (z focus_distance) (at unit distance; over the pixel's angle: pixels), and its camera leg is timed through its aperture point and the lens (an in-focus surface's light arrives as through the pinhole). `render.renderer: ir` with `render.backend: cpu` only (`auto` picks it); cost: `bench/defocus`"},
    {"camera.focus_distance", "length", "> 0", "1", "m",
     "with `aperture`: the depth (along the optical axis) of the plane in focus; required then, an error without an aperture"},
    {"camera.aperture_samples", "int", "in [2, 4096]", "16", "-",
     "with `aperture`: the aperture points each pixel sample traces (Vogel's sunflower spiral: equal areas, the same for every pixel, so the bytes do not depend on threads or budgets); the render costs about this many times the pinhole's first-surface and gather work"},
    {"camera.lens.camera_matrix", "[9 numbers]", "", "required", "pixel",
     "OpenCV's camera matrix row by row, [fx, 0, cx, 0, fy, cy, 0, 0, 1], pixel centres at integers (a list, nested rows or a cv::FileStorage matrix)"},
    {"camera.lens.distortion", "list", "of 4, 5, 8, 12 or 14", "[0, 0, 0, 0]", "-",
     "OpenCV's distortion coefficients in its order: k1 k2 p1 p2 [k3 [k4 k5 k6 [s1 s2 s3 s4 [tau_x tau_y]]]]"},
    {"camera.lens.calibration", "path", "", "none", "-",
     "an OpenCV calibration YAML (cv::FileStorage's: camera_matrix, distortion_coefficients, image_width, image_height) in place of the two keys above; relative to the config"},
    {"camera.psf", "mapping", "", "none", "-",
     "the lens's point spread function (stray light) on every time bin, or equivalently on the CW-ToF raws, see below"},
    {"camera.psf.core_sigma", "number", ">= 0", "0", "pixel",
     "the core's Gaussian sigma, integrated over each pixel; 0: a delta (the pixel keeps its light)"},
    {"camera.psf.halo_weight", "number", "in [0, 1)", "0", "-",
     "s: the halo's share of the light, K = (1 - s) core + s halo"},
    {"camera.psf.halo_profile", "string", "", "gaussian", "-",
     "`gaussian` (sigma `halo_radius`) or `exponential` (exp(-r / `halo_radius`), the long tail measured stray light has)"},
    {"camera.psf.halo_radius", "number", "> 0", "0", "pixel",
     "the halo's sigma or decay length; required with `halo_weight` > 0"},
    {"camera.psf.file", "path", "", "none", "-",
     "a measured kernel in place of the four keys above: a 2-D float32 .npy (H, W), odd sizes, centre at (H/2, W/2), values finite and >= 0, normalised on load; relative to the config"},
    {"materials.<name>", "mapping", "", "none", "-",
     "the settings of the scene's materials of this name (an unknown name is an error that lists the scene's); they replace what the glTF material's `extras` say"},
    {"materials.<name>.scattering_delay", "mapping or none", "", "required", "-",
     "the material's temporal response: (1 - `fraction`) of the light it scatters leaves at once, `fraction` after the model's delay, energy kept (the albedo is unchanged); `none`: instant, whatever its extras say"},
    {"materials.<name>.scattering_delay.model", "string", "", "required", "-",
     "`exponential` (a fluorescence lifetime: exp(-t / `lifetime`) / `lifetime`), `gaussian` (a subsurface-like delay, truncated to t >= 0) or `table` (a measured kernel)"},
    {"materials.<name>.scattering_delay.fraction", "number", "in [0, 1]", "1", "-",
     "the share of the scattered light that is delayed; the rest is prompt"},
    {"materials.<name>.scattering_delay.lifetime", "duration", "> 0", "required", "s",
     "`exponential`: the lifetime tau"},
    {"materials.<name>.scattering_delay.mean", "duration", ">= 0", "required", "s",
     "`gaussian`: the mean delay"},
    {"materials.<name>.scattering_delay.sigma", "duration", "> 0", "required", "s",
     "`gaussian`: its standard deviation (the filter spans 16 sigma: at most 8192 bins)"},
    {"materials.<name>.scattering_delay.file", "path", "", "required", "-",
     "`table`: the kernel, rows (delay, weight): a float32 or float64 .npy (n, 2) or a two-column .csv (`#` comments, a header line allowed), >= 2 rows, delays >= 0 and increasing from the light's arrival, weights >= 0 of any scale (a piecewise-linear density, normalised; at most 8192 bins long); relative to the config, read without following links"},
    {"materials.<name>.scattering_delay.delay_unit", "string", "", "s", "-",
     "`table`: the unit of the file's delays: `s`, `ms`, `us`, `ns` or `ps`"},
    {"materials.<name>.scattering_delay.reemission", "3x3 matrix", "", "identity", "-",
     "the delayed light's change of channel (fluorescence's Stokes shift): rows the re-emitted channel, columns the absorbed one (R, G, B), out = M in, e.g. [[1, 1, 0], [0, 0, 0], [0, 0, 1]] re-emits in R what G absorbs; entries >= 0, each column summing to at most 1 (the rest is absorbed)"},
};
// The keys of a sensor entry itself, and the one-of-two channel keys; every
// other sensor key's row comes from its parameter table (SensorFields.h).
const ConfigKey kSensorEntryKeys[] = {
    {"common.type", "string", "", "required", "-",
     "`streak`, `spad` or `cwtof`"},
    {"common.name", "string", "", "the type", "-",
     "label of this sensor"},
    {"common.channel", "int", "", "0", "-",
     "volume channel used when `channel_weights` is absent"},
    {"common.channel_weights", "list of numbers", "", "none", "-",
     "weighted sum of the channels instead (one weight per channel)"},
};
// clang-format on
}  // namespace

std::span<const ConfigKey> runConfigKeys() {
  static const DocRows rows = [] {
    DocRows r;
    r.keys.assign(std::begin(kRunConfigKeys), std::end(kRunConfigKeys));
    addDocRows<LightConfig>(r, "light", kLightFields);
    addDocRows(r, "time", kTimeFields, RunConfig{}.render.time);
    addDocRows<RunConfig>(r, "render", kRenderFields);
    addDocRows<capture::IndirectSettings>(r, "render.indirect", kIndirectFields);
    addDocRows<ReferenceConfig>(r, "render.reference", kReferenceFields);
    addDocRows<NlosConfig>(r, "nlos", kNlosFields);
    addDocRows<SequenceConfig>(r, "sequence", kSequenceFields);
    addDocRows<OutputConfig>(r, "output", kOutputFields);
    return r;
  }();
  return rows.keys;
}
std::span<const ConfigKey> sensorConfigKeys() {
  static const DocRows rows = [] {
    DocRows r;
    r.keys.assign(std::begin(kSensorEntryKeys), std::end(kSensorEntryKeys));
    addDocRows<sensors::Radiometry>(r, "common", sensors::kRadiometryFields);
    addDocRows<sensors::InstrumentBins>(r, "bins", sensors::kBinsFields);
    addDocRows<sensors::StreakParams>(r, "streak", sensors::kStreakFields);
    addDocRows<sensors::SpadParams>(r, "spad", sensors::kSpadFields);
    addDocRows<sensors::CwTofParams>(r, "cwtof", sensors::kCwTofFields);
    return r;
  }();
  return rows.keys;
}

}  // namespace tofsim::config
