// The declared config keys (ConfigKeys.h). The README tables are checked
// against these rows by tests/config/ConfigKeysTest.cpp: change both together.
// The rows of a section with a parameter table come from it (RunFields.h,
// CameraFields.h, RaysFields.h, TimeFields.h, LightFields.h, OutputFields.h,
// NlosFields.h, SequenceFields.h; sensors: sensors/SensorFields.h); the
// literal rows below are the top level's.
#include "tofsim/config/ConfigKeys.h"

#include <iterator>

#include "CameraFields.h"
#include "FieldDoc.h"
#include "LightFields.h"
#include "NlosFields.h"
#include "OutputFields.h"
#include "RaysFields.h"
#include "RunFields.h"
#include "SequenceFields.h"
#include "TimeFields.h"
#include "tofsim/sensors/SensorFields.h"

namespace tofsim::config {

namespace {
// clang-format off
const ConfigKey kRunConfigKeys[] = {
    {"scene", "string", "", "required", "-",
     "glTF file, relative to the config's folder (`output.directory` is relative to the folder the command runs in)"},
    {"camera", "mapping", "", "required", "-",
     "see below (`{}` for all defaults); not with `nlos`"},
    {"light", "mapping", "", "required", "-",
     "see below; not with `nlos`"},
    {"rays", "mapping", "", "none", "-",
     "a capture whose pixels are the rays of a file (a fibre bundle, a scanning pattern, a custom lens) instead of `camera`, see below; not with `camera`, `nlos` or `sequence`"},
    {"nlos", "mapping", "", "none", "-",
     "a non-line-of-sight relay-wall scan instead of `camera` and `light`, see below"},
    {"lidar", "mapping", "", "none", "-",
     "a lidar (spinning, a raster or a multizone sensor) instead of `camera` and `light` (its beams or zones are its captures), see below; not with `camera`, `light`, `rays` or `nlos`; with `sequence`: rolling scans (spinning and raster)"},
    {"lidar.position", "vec3", "", "required", "m",
     "where the lidar's beams start"},
    {"lidar.orientation", "mapping", "", "required", "-",
     "`{look_at, up}`"},
    {"lidar.orientation.look_at", "vec3", "", "required", "m",
     "azimuth 0 looks toward it (projected onto the plane normal to `up`); not on the spin axis"},
    {"lidar.orientation.up", "vec3", "", "[0, 0, 1]", "-",
     "the spin axis (normalised)"},
    {"lidar.channels", "mapping or list", "", "required", "deg",
     "`{count, min, max}`, or the elevations listed (ring r = the r-th); each in [-90, 90]; at least one, at most 1024"},
    {"lidar.channels.count", "int in [1, 1024]", "", "required", "-",
     "elevations evenly from `min` to `max`, ring 0 = `min`"},
    {"lidar.channels.min", "angle", "", "0", "deg",
     "the lowest elevation"},
    {"lidar.channels.max", "angle >= min", "", "min", "deg",
     "the highest elevation (> min with more than one channel)"},
    {"lidar.azimuth", "mapping", "", "defaults", "-",
     "`{start, end, step}`: azimuths start, start + step, ... below end"},
    {"lidar.azimuth.start", "angle", "", "0", "deg",
     "the first azimuth"},
    {"lidar.azimuth.end", "angle > start", "", "360", "deg",
     "exclusive; end - start at most 360"},
    {"lidar.azimuth.step", "angle > 0", "", "0.2", "deg",
     "between azimuths"},
    {"lidar.beam_divergence", "angle with a unit", "", "3 mrad", "rad",
     "full angle, > 0 (`3 mrad`, `0.003 rad`, `0.2 deg`; a bare number is an error); Gaussian: the 1/e^2 full width (untruncated)"},
    {"lidar.beam_profile", "string", "", "gaussian", "-",
     "`gaussian` or `tophat`: the power's spread over the cone"},
    {"lidar.beam_rays", "int in [1, 4096]", "", "16", "-",
     "receiver rays per beam: max(1, round(sqrt(n) / 2)) rings of n / rings sectors; 1: the beam's axis alone"},
    {"lidar.power", "number > 0", "", "1", "W",
     "the laser's power per beam, per unit pulse"},
    {"lidar.rotation_rate", "frequency > 0", "", "10 Hz", "Hz",
     "turns per second: the points' `time_offset`, and with `sequence` each column's firing time (rolling scans above)"},
    {"lidar.frame_rate", "frequency > 0", "", "10 Hz", "Hz",
     "raster only: frames per second; the cells fire line by line from the top, evenly over the frame: the points' `time_offset`, and with `sequence` each cell's firing time (rolling scans above)"},
    {"lidar.returns", "mapping", "", "defaults", "-",
     "`{mode, max, threshold, separation}`: see Echoes above"},
    {"lidar.returns.mode", "string", "", "strongest", "-",
     "`first`, `strongest`, `last`, `dual` or `all`"},
    {"lidar.returns.max", "int in [1, 255]", "", "2", "-",
     "the most returns kept per beam"},
    {"lidar.returns.threshold", "number >= 0", "", "0", "W m^-2",
     "a bin is part of an echo above it (0: any light)"},
    {"lidar.returns.separation", "length >= 0", "", "0.3 m", "m",
     "runs of bins closer than this (in range) are one echo"},
    {"lidar.backscatter", "mapping", "", "defaults", "-",
     "`{overlap, phase_at_pi}`: a scattering medium's light along each beam (the fog's false returns), see Backscatter above"},
    {"lidar.backscatter.overlap", "length > 0", "", "1 m", "m",
     "the receiver sees the laser's cone whole from this range on; nearer scattering does not reach it"},
    {"lidar.backscatter.phase_at_pi", "number >= 0", "", "0", "1/sr",
     "the medium's phase function at pi as the lidar sees it (fog's Mie backscatter: 0.052); 0: the medium's own"},
    {"lidar.plot_beams", "list of [ring, azimuth]", "", "[]", "-",
     "beams (ring, azimuth in degrees: the nearest) whose waveforms `waveforms.png` draws"},
    {"lidar.scan", "string", "", "spinning", "-",
     "`spinning`, `raster` (a grid of beams over a field of view) or `zones` (a multizone direct-ToF sensor): see Grid scans below"},
    {"lidar.preset", "string", "", "none", "-",
     "a device preset (`spinning-16`, `spinning-64`, `multizone-8x8`; `tofsim presets` lists each value and its source): its values are the defaults of the lidar's keys (and of `time.bin_width` and `time.bins` for `multizone-8x8`), each explicit key wins"},
    {"lidar.grid", "mapping", "", "required", "-",
     "raster and zones: `{rows, columns}`, row 0 the lowest, column 0 the leftmost"},
    {"lidar.grid.rows", "int in [1, 1024]", "", "required", "-",
     "the grid's rows (the waveforms' first axis)"},
    {"lidar.grid.columns", "int in [1, 1024]", "", "required", "-",
     "the grid's columns (the waveforms' second axis)"},
    {"lidar.field_of_view", "mapping", "", "required", "-",
     "raster and zones: `{horizontal, vertical}`, full angles through a pinhole's image plane"},
    {"lidar.field_of_view.horizontal", "angle in (0, 170)", "", "required", "deg",
     "the full horizontal angle the columns tile (equal steps of tan)"},
    {"lidar.field_of_view.vertical", "angle in (0, 170)", "", "required", "deg",
     "the full vertical angle the rows tile (equal steps of tan)"},
    {"lidar.zone_rays", "int in [1, 64]", "", "4", "-",
     "zones: rays a side of a zone (N x N through its sub-cells' centres, each weighted by its solid angle)"},
    {"lidar.multipath", "mapping", "", "none (off)", "-",
     "each beam's light that bounces before it returns (IR per beam: the spot's VPLs light the receiver's points), see below"},
    {"lidar.multipath.bounces", "int in [0, 8]", "", "0", "-",
     "0: off; 1: the spot lights the receiver points (one-bounce multipath); n: n - 1 more bounces by VPLs from the spot"},
    {"lidar.multipath.spot_rays", "int in [1, 1024]", "", "4", "-",
     "laser rays over the divergence cone (by `beam_profile`): the spot's VPLs"},
    {"lidar.multipath.receiver_rays", "int in [1, 4096]", "", "16", "-",
     "receiver rays, uniform over `receiver_fov`: the points the multipath reaches the lidar from"},
    {"lidar.multipath.receiver_fov", "angle with a unit", "", "beam_divergence", "rad",
     "the receiver's full field of view, >= `beam_divergence`, < 180 deg"},
    {"lidar.multipath.vpls_per_bounce", "int in [1, 4096]", "", "16", "-",
     "VPLs per beam for each bounce after the first (core/ir's bounce tracing)"},
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
    {"medium", "mapping", "", "none", "-",
     "a homogeneous participating medium filling the scene (fog, smoke, turbid water), see below; not with `nlos` or `rays`"},
    {"medium.sigma_a", "number or list of 3", ">= 0", "0", "1/m",
     "absorption coefficient: one number for every channel or [R, G, B]; a unit reads too (`0.01 /m`, `10 1/km`, `0.3 /cm`)"},
    {"medium.sigma_s", "number or list of 3", ">= 0", "0", "1/m",
     "scattering coefficient, as `sigma_a`; the medium is there when sigma_a + sigma_s > 0 in a channel"},
    {"medium.visibility", "length", "> 0", "none", "m",
     "fog by its meteorological visibility V: sigma_t = 3.912 / V (Koschmieder, 2 % contrast), sigma_s = `albedo` x sigma_t, sigma_a the rest, and fog's phase function (see below); not with `sigma_a` or `sigma_s`"},
    {"medium.albedo", "number or list of 3", "in [0, 1]", "0.99996", "-",
     "with `visibility`: the fog's single-scattering albedo, one number or [R, G, B]"},
    {"medium.phase", "mapping or string", "", "isotropic", "-",
     "the phase function, `{model: ..., g: ...}` or the model's name alone; with `visibility`: `{model: henyey_greenstein, g: 0.845}`"},
    {"medium.phase.model", "string", "", "required", "-",
     "`isotropic`, `henyey_greenstein` or `rayleigh`"},
    {"medium.phase.g", "number", "in (-1, 1)", "required", "-",
     "`henyey_greenstein` only: the asymmetry, the mean cosine of the scattering angle (> 0: forward)"},
    {"medium.index_of_refraction", "number", ">= 1", "time's", "-",
     "sets `time.index_of_refraction` (light covers c / eta per second on every leg); given in both, they must agree"},
    {"media", "list", "", "none", "-",
     "per-region media: each a homogeneous medium inside a closed glTF mesh, see `media` below; not with `medium`, `nlos`, `rays`, `lidar` or `sequence`"},
    {"materials", "mapping", "", "none", "-",
     "per glTF material name, its settings (a scattering delay), see below"},
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
     "`streak`, `spad`, `cwtof` or `apd`"},
    {"common.name", "string", "", "the type", "-",
     "label of this sensor"},
    {"common.channel", "int", ">= 0", "none", "-",
     "the one volume channel seen; with neither this nor `channel_weights` the sensor sees the sum of the channels (as `[1, 1, 1]`)"},
    {"common.channel_weights", "list of numbers", "", "none", "-",
     "weighted sum of the channels instead (one weight per channel)"},
};
// clang-format on
}  // namespace

std::span<const ConfigKey> runConfigKeys() {
  static const DocRows rows = [] {
    DocRows r;
    r.keys.assign(std::begin(kRunConfigKeys), std::end(kRunConfigKeys));
    addDocRows<CameraConfig>(r, "camera", kCameraFields);
    addDocRows<capture::Lens>(r, "camera.lens", kLensFields);
    addDocRows<PsfConfig>(r, "camera.psf", kPsfFields);
    addDocRows<RaysConfig>(r, "rays", kRaysFields);
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
    addDocRows<sensors::ApdParams>(r, "apd", sensors::kApdFields);
    return r;
  }();
  return rows.keys;
}

}  // namespace tofsim::config
