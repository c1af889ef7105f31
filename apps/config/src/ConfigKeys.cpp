// The declared config keys (ConfigKeys.h). The README tables are checked
// against these rows by tests/config/ConfigKeysTest.cpp: change both together.
// Sensor parameters are declared in their tables (sensors/SensorFields.h).
#include "tofsim/config/ConfigKeys.h"

#include <iterator>

#include "FieldDoc.h"
#include "NlosFields.h"
#include "RunFields.h"
#include "SequenceFields.h"
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
    {"light.type", "string", "", "point", "-",
     "`point` or `spot`"},
    {"light.attach_to_camera", "bool", "", "false", "-",
     "put the light at the camera (plus `offset`) aimed along the view, as ToF illuminators are mounted; then `position`/`direction` are ignored"},
    {"light.offset", "vec3", "", "[0, 0, 0]", "m",
     "with `attach_to_camera`: right, up, forward of the pinhole"},
    {"light.position", "vec3", "", "[0, 0, 0]", "m",
     "light position"},
    {"light.direction", "vec3", "", "[0, 0, -1]", "-",
     "spot axis (normalised; not zero)"},
    {"light.cone_angle", "angle", "in (0, 180]", "30", "deg",
     "spot half angle"},
    {"light.cone_falloff", "angle", "in [0, cone_angle]", "0", "deg",
     "spot edge softening"},
    {"light.intensity", "number or vec3", ">= 0", "1", "W/sr",
     "radiant intensity per channel (R, G, B)"},
    {"time.start", "duration", "", "0", "s",
     "leading edge of bin 0 (time from the light's impulse to arrival at the camera)"},
    {"time.bin_width", "duration", "> 0", "10 ps", "s",
     "bin width"},
    {"time.bins", "int", "in [1, 2^20]", "512", "-",
     "number of bins"},
    {"time.index_of_refraction", "number", ">= 1", "1", "-",
     "of the medium filling the scene (slows light)"},
    {"time.camera_unwarp", "bool", "", "false", "-",
     "drop the surface -> camera delay (time at the surface)"},
    {"render.renderer", "string", "", "ir", "-",
     "`ir` (instant radiosity) or `reference`"},
    {"render.backend", "string", "", "auto", "-",
     "device of `ir`: `gl` (OpenGL 4.5 through EGL: a GPU, or Mesa's llvmpipe), `cpu` (the "
     "native CPU backend, all cores, needs no EGL), or `auto`: `gl` when the EGL device platform "
     "offers a hardware GPU (llvmpipe/softpipe do not count), `cpu` otherwise. The choice is "
     "printed (`device: ...`) and recorded in `transient.json` (`backend`, `device`); "
     "`--backend` on `render` sets it. Both give the same volume within float rounding "
     "(tests/cpu)"},
    {"render.threads", "int", "in [0, 4096]", "0", "-",
     "worker threads of the `cpu` backend, and of the later bounces' ray tracing on both backends (0 = every core this process may run on: its CPU affinity, e.g. a Slurm task's `--cpus-per-task`, taskset or a container's cpuset); the bytes do not depend on it (tests/cpu, tests/ir BounceVplsTest)"},
    {"render.seed", "int", "in [0, 2^62]", "1", "-",
     "seed of every random choice: the renderer's and the sensors'"},
    {"render.shadow_map_resolution", "int", "in [16, 16384]", "1024", "pixel",
     "per cube face of the light's shadow map"},
    {"render.memory_budget", "bytes", "in [1 MiB, 1 PiB]", "512 MiB", "B",
     "device memory (GPU, or RAM for `backend: cpu`) for volume segments and ISM batches; for `tofsim sense`, the host memory of the runs of pixels it reads from the saved files"},
    {"render.strict", "bool", "", "false", "-",
     "light cut off by the time axis or a sensor window (more than 0.1 %) is an error, not a warning; `--strict` on `render` / `validate` sets it (see \"Time windows\")"},
    {"render.pixel_footprint", "bool", "", "true", "-",
     "a pixel integrates its area: every contribution is spread over the distribution of its optical path across the pixel (a trapezoid in time, first order; see README.md, \"Pixel footprints\"); `false`: all of a pixel's light in the bin of its centre's path (closed-form tests). `ir` only: the reference integrates by `reference.pixel_filter`"},
    {"render.pixel_samples", "int", "in [1, 16]", "1", "-",
     "N x N stratified surface samples per pixel, averaged (silhouettes, pixels that see two surfaces); each sample's footprint is its sub-pixel; costs N^2 gathers"},
    {"render.adaptive_pixel_samples", "bool", "", "false", "-",
     "with `pixel_samples` N > 1: the N x N samples only in pixels at an edge of the pixel-centre G-buffer (a 3 x 3 neighbour off the pixel's tangent plane by more than 5 degrees, a normal turned by more than 5 degrees, or surface next to background), or where the light reaches one of two neighbouring pixel centres and not the other (a shadow's edge or a hard spot's rim inside a flat pixel: a ray from each centre to the light, traced by the driver on either backend); every other pixel takes one sample at its centre with the whole pixel's footprint, exactly what `pixel_samples: 1` computes there (README.md, \"Pixel footprints\"). Silhouettes, creases and shadow edges at a fraction of N^2 the cost; texture edges inside a flat pixel are not detected. `ir` only"},
    {"render.materials", "string", "", "lambertian", "-",
     "`lambertian`: every material reflects albedo / pi (base colour only; metallic and roughness ignored), the output of before, byte for byte. `gltf`: the glTF metallic-roughness BRDF (GGX, height-correlated Smith, Schlick; `metallicFactor`, `roughnessFactor`, `metallicRoughnessTexture`; README.md, \"Materials\") in the direct light seen by the camera, on both `ir` backends and in the reference, and in IR's indirect light: glossy VPLs (each records the direction its light came from and its material, and lights a point with its BRDF, clamped at `indirect.vpl_brdf_clamp`) and the BRDF on the camera side of every VPL contribution. The default stays `lambertian` because glTF's metallic 0, roughness 1 is not Lambertian: the shipped scenes would change"},
    {"render.indirect", "mapping", "", "defaults", "-",
     "indirect light (instant radiosity: VPLs), below"},
    {"render.reference", "mapping", "", "defaults", "-",
     "the CPU path tracer's settings (`renderer: reference`), below"},
};
// render.indirect.* and render.reference.* come from their tables (RunFields.h),
// spliced in here.
const ConfigKey kRunConfigKeysAfterRender[] = {
    {"output.directory", "string", "", "out", "-",
     "output folder (`-o` overrides)"},
    {"output.transient", "bool", "", "true", "-",
     "`transient.npy` (H, W, T, 3) + `transient.json` (axes, units, time axis)"},
    {"output.steady", "bool", "", "true", "-",
     "`steady.exr` + `steady.png` (sum over time)"},
    {"output.depth", "bool", "", "true", "-",
     "`depth.exr` (channels Y and Z, the same metres; 0 = no surface), `depth.npy` (float32 (H, W), "
     "metres) + `depth.png`"},
    {"output.frames", "bool", "", "false", "-",
     "`frames/frame_NNNNN.exr`, one per time bin"},
    {"output.components", "list", "", "[]", "-",
     "also write `direct` (`direct.npy`), `indirect` (`indirect.npy`) and/or `bounce1` .. `bounceN` (`bounce<k>.npy`, the light of exactly k indirect bounces, k <= `render.indirect.bounces`, `renderer: ir` only; `indirect` = their sum exactly)"},
    {"output.video", "bool", "", "false", "-",
     "`transient.mp4`: light in flight, one frame per `video_stride` bins, time stamp in each frame"},
    {"output.video_tone_map", "string", "", "global", "-",
     "`global`: linear, one scale for the whole video (the 99.5th percentile of all frames' values maps to white); `log`: `1 + log10(v / white) / 4`, four decades below that white"},
    {"output.video_stride", "int", "in [1, 2^20]", "1", "bins",
     "one frame every `video_stride` time bins"},
    {"output.video_window", "int", "", "1", "bins",
     "exposure of each video frame / frame PNG: frame t sums bins t-(w-1)/2 .. t+w/2, so a wavefront shows w bins wide"},
    {"output.video_fps", "number", "> 0", "30", "1/s",
     "frames per second of the video"},
    {"output.max_bytes", "bytes", "in [1 B, 1 EiB]", "64 GiB", "B",
     "before rendering, the outputs' size is estimated (`.npy` volumes, EXR frames and sensor arrays exactly, PNG and MP4 roughly); a run over this, or over the output folder's free space, fails at once naming the sizes and the keys that drive them"},
    {"output.frame_pngs", "bool", "", "false", "-",
     "`frames/frame_NNNNN.png` (NNNNN = time bin): the video's frames as PNG (needs no `video`)"},
    {"output.plot_ranges", "map of [lo, hi]", "lo < hi", "{}", "unit of the picture",
     "fixed colour ranges, so pictures compare across runs: key = the PNG's path without `.png` (`depth`, `steady`, `sensors/<sensor>/<output>`), e.g. `{depth: [0.5, 3], sensors/cwtof/cwtof_mpi_error: [-0.05, 0.05]}`; `steady` maps lo..hi to black..white; a key that names no picture of the run is warned about; a sensor picture's JSON records the range it was drawn with, fixed or automatic (`picture.range`, `sensors/README.md`)"},
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
    addDocRows<capture::IndirectSettings>(r, "render.indirect", kIndirectFields);
    addDocRows<ReferenceConfig>(r, "render.reference", kReferenceFields);
    addDocRows<NlosConfig>(r, "nlos", kNlosFields);
    addDocRows<SequenceConfig>(r, "sequence", kSequenceFields);
    r.keys.insert(r.keys.end(), std::begin(kRunConfigKeysAfterRender),
                  std::end(kRunConfigKeysAfterRender));
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
