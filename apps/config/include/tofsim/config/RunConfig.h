#pragma once
// A render config as typed structs, every default filled in. Produced by
// loadRunConfig (the only code that reads YAML); consumed by the pipeline.
// Key names, units and defaults are documented in configs/README.md.

#include <array>
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tofsim/capture/Camera.h"
#include "tofsim/capture/Imager.h"
#include "tofsim/capture/Light.h"
#include "tofsim/capture/RenderSettings.h"
#include "tofsim/capture/Vignetting.h"
#include "tofsim/config/NlosConfig.h"
#include "tofsim/config/SequenceConfig.h"
#include "tofsim/optics/PsfKernel.h"
#include "tofsim/physics/TemporalResponse.h"
#include "tofsim/sensors/SensorSpec.h"

namespace tofsim::config {

/// `lidar:` in place of `camera:` (LidarConfig.h); declared here only, so
/// that the lidar's header stays out of every file that includes this one.
struct LidarConfig;

/// camera.psf: the lens's point spread function, applied to every time bin
/// of the transient before any output or sensor (pipeline::PsfSegments), or
/// equivalently on the CW-ToF raws and the steady image when nothing else
/// written needs the blurred transient (pipeline/PsfPath.h).
struct PsfConfig {
  /// The parametric form (1 - s) core + s halo; unused with a kernel file.
  optics::PsfParams params;
  /// camera.psf.file: the measured kernel (absolute) in place of params;
  /// empty for the parametric form.
  std::string file;
  /// The kernel itself: params' cropped to the image (PsfKernel::parametric's
  /// crop_px = max(W, H) - 1, which changes no pixel), or the file's normalised.
  optics::PsfKernel kernel;
  /// Where camera.psf is, for the errors found later (render.memory_budget).
  FileLoc at;
};

struct CameraConfig {
  /// Name or index of a camera in the scene; empty: use the values below.
  std::string gltf_camera;
  capture::Camera camera;  ///< position, look-at, up, fov or lens, resolution
  /// camera.lens.calibration: the OpenCV calibration file the lens came from
  /// (absolute); empty when the lens was given inline or there is none.
  std::string lens_calibration;
  /// camera.vignetting: none, cos4 or a map of gains.
  capture::Vignetting vignetting;
  /// camera.psf; none: a perfectly sharp lens.
  std::optional<PsfConfig> psf;
};

/// rays: in place of camera: a capture whose pixels are the rays of a file
/// (RayFile.h): the user's own sensor geometry.
struct RaysConfig {
  std::string file;  ///< the ray file, absolute
  capture::RayListImager imager;
};

struct LightConfig {
  capture::Light light;
  /// Place the light at the camera (plus offset, in the camera frame:
  /// right, up, forward metres) and aim it along the view direction, as ToF
  /// illuminators are mounted.
  bool attach_to_camera = false;
  glm::vec3 offset_camera_m{0.0f};
};

enum class RendererKind { InstantRadiosity, Reference };

/// render.backend: the device instant radiosity runs on. Auto: the GL backend
/// when the EGL device platform offers a hardware GPU, the CPU backend
/// (core/cpu, needs no EGL) otherwise.
enum class IrBackendKind { Auto, Gl, Cpu };
/// "auto", "gl" or "cpu".
const char* irBackendName(IrBackendKind kind);

/// render.reference.pixel_filter: a pixel's area (box) or its centre (point).
enum class ReferencePixelFilter { Box, Point };

/// render.reference.sampling: how paths continue at glTF surfaces: the cosine
/// + GGX visible-normal mixture (brdf) or cosine sampling alone (cosine).
enum class ReferenceSampling { Brdf, Cosine };

/// render.reference: the CPU path tracer's settings (core/reference).
struct ReferenceConfig {
  int32_t bounces = 2;             ///< 1 direct only, 2 direct + one indirect, n
  int32_t samples_per_pixel = 64;  ///< indirect paths per pixel
  int32_t threads = 0;             ///< 0: all hardware threads
  ReferencePixelFilter pixel_filter = ReferencePixelFilter::Box;
  ReferenceSampling sampling = ReferenceSampling::Brdf;

  bool operator==(const ReferenceConfig&) const = default;
};

/// Tone map of the transient video and frame PNGs (tofsim/imaging/Video.h).
enum class VideoToneMap { Global, Log };

/// Files of the arrays: one .npy each, or all in one capture.h5.
enum class OutputFormat { Npy, Hdf5 };

struct OutputConfig {
  std::filesystem::path directory = "out";
  /// Npy: transient.npy, direct.npy, ...; Hdf5: the volumes, the depth, the
  /// steady image and the sensors' arrays as datasets of capture.h5.
  OutputFormat format = OutputFormat::Npy;
  bool transient = true;  ///< transient.npy + transient.json
  bool steady = true;     ///< steady.exr
  bool depth = true;      ///< depth.exr
  bool frames = false;    ///< frames/frame_NNNN.exr, one per time bin
  bool direct = false;    ///< direct.npy (components: [direct, ...])
  bool indirect = false;  ///< indirect.npy
  /// bounce<k>.npy for each k listed (increasing, 1 <= k <= render.indirect.bounces):
  /// the light whose path has exactly k indirect bounces (IR renderer only).
  std::vector<int32_t> bounces;
  bool video = false;       ///< transient.mp4: light in flight, one frame per video_stride bins
  bool frame_pngs = false;  ///< frames/frame_NNNNN.png: the video's frames as PNG
  VideoToneMap video_tone_map = VideoToneMap::Global;
  int32_t video_stride = 1;  ///< bins per video frame, >= 1
  int32_t video_window = 1;  ///< bins summed into each frame (exposure), >= 1
  double video_fps = 30.0;   ///< frames per second of the video, > 0
  /// A run whose outputs would exceed this many bytes fails before rendering.
  std::uintmax_t max_bytes = std::uintmax_t(64) << 30;
  /// Fixed colour ranges [lo, hi] of pictures, keyed by the PNG's path in the
  /// output folder without ".png": "depth", "steady",
  /// "sensors/<sensor>/<output>". Pictures not named get an automatic range.
  std::map<std::string, std::array<double, 2>> plot_ranges;
};

/// The most bins time.bins may ask for (its range, TimeFields.h; the time
/// axis report's advice reads it too).
inline constexpr int32_t kMaxTimeBins = 1 << 20;

/// The time axis of a config's `time: {}`: time.*'s defaults (a TimeAxis
/// itself has none: 0 bins of 0 s).
inline constexpr TimeAxis kDefaultTimeAxis{.start_s = 0.0, .bin_width_s = 10e-12, .bins = 512};

/// materials.<name>.scattering_delay (MaterialDelays.h): a glTF material's
/// temporal response, which replaces its glTF extras' whole.
struct ScatteringDelayConfig {
  /// The kernel; none: `scattering_delay: none`, instant whatever the
  /// extras say.
  std::optional<physics::ResponseKernel> kernel;
  std::string table_file;        ///< model: table: the kernel's file (absolute)
  std::string delay_unit = "s";  ///< model: table: its delays' unit
};

/// One `materials:` entry, keyed by the glTF material's name.
struct MaterialConfig {
  std::string name;
  ScatteringDelayConfig scattering_delay;
  /// Where the entry is, for the errors found once the scene is read (a
  /// name the scene does not have).
  FileLoc at;
};

/// `medium:` (MediumSection.cpp): the homogeneous medium that fills the
/// scene is RunConfig::render.medium (and its index of refraction
/// render.time.index_of_refraction); this is the form it was written in,
/// for the effective config and the metadata.
struct MediumConfig {
  /// `visibility`: the meteorological visibility it was derived from (fog,
  /// Koschmieder: sigma_t = 3.912 / V), m; 0 when sigma_a and sigma_s were
  /// given.
  double visibility_m = 0.0;
  /// With `visibility`: the single-scattering albedo per channel.
  glm::vec3 albedo{0.0f};
  /// Where `medium:` is, for the errors found later.
  FileLoc at;
};
/// One `media:` entry as written (its medium is render.media's entry of the
/// same index): where it is, for the errors found once the scene is read.
struct RegionMediumConfig {
  FileLoc at;         ///< the entry
  FileLoc region_at;  ///< its `region` key
};
/// A medium's phase model (capture::Medium::phase) as `medium.phase.model`
/// writes it: "isotropic", "henyey_greenstein" or "rayleigh".
const char* phaseModelName(int32_t phase);

struct RunConfig {
  std::filesystem::path config_file;
  std::filesystem::path scene_file;  ///< resolved against the config's folder
  CameraConfig camera;
  /// rays: in place of camera:, the capture's imager (camera.camera then
  /// holds only its image size, for what sizes outputs and sensors).
  std::optional<RaysConfig> rays;
  LightConfig light;
  /// A non-line-of-sight relay-wall scan instead of a camera and a light
  /// (NlosConfig.h); `light` then holds the laser spot's emitter (a
  /// Lambertian light, placed per laser point by the pipeline).
  std::optional<NlosConfig> nlos;
  /// A lidar capture in place of a camera and a light (LidarConfig.h,
  /// core/lidar); null without `lidar:`. Shared, not copied: it is read only.
  std::shared_ptr<const LidarConfig> lidar;
  /// A capture sequence of the scene's animations (SequenceConfig.h); unset:
  /// one capture at the rest pose. Not with nlos.
  std::optional<SequenceConfig> sequence;
  capture::RenderSettings render{.time = kDefaultTimeAxis};
  RendererKind renderer = RendererKind::InstantRadiosity;
  IrBackendKind backend = IrBackendKind::Auto;  ///< render.backend (IR only)
  int32_t cpu_threads = 0;  ///< render.threads: the CPU IR backend's threads, 0 = all
  ReferenceConfig reference;
  /// render.strict (or --strict): light cut off by the time axis or a sensor
  /// window is an error, not a warning (apps/pipeline AxisReport.h).
  bool strict = false;
  OutputConfig output;
  /// The `sensors:` list (sensors/README.md). Run after a render on the kept
  /// volume, and by `tofsim sense` on a saved one, with seed render.seed.
  /// Names are unique and usable as folder names.
  std::vector<sensors::SensorSpec> sensors;
  /// The `materials:` entries, in file order (names unique); applied to the
  /// scene by config::loadConfiguredScene (MaterialDelays.h).
  std::vector<MaterialConfig> materials;
  /// Where `materials:` is (the config file when absent): errors about the
  /// materials' delays found once the scene is read are located there.
  FileLoc materials_at;
  /// `medium:` as written; unset without one (render.medium then has none).
  std::optional<MediumConfig> medium;
  /// `media:` entries, in order (render.media holds their media).
  std::vector<RegionMediumConfig> media;
};

/// One `--set key.path=value` override, applied before validation.
struct Override {
  std::string keyPath;  ///< e.g. "camera.resolution" or "sensors.0.bins"
  std::string value;    ///< YAML text, e.g. "[64, 64]" or "10 ps"
};

/// Parses "key.path=value"; throws InputError when there is no '='.
Override parseOverride(const std::string& text);

/// Loads, overrides and validates a config. Errors name the file, line,
/// column and key (or the --set that caused them).
RunConfig loadRunConfig(const std::filesystem::path& file,
                        const std::vector<Override>& overrides = {});

/// As loadRunConfig, on YAML (or JSON) text held in memory: `file` names it
/// in errors and anchors relative paths (the scene) at its folder.
RunConfig loadRunConfigText(const std::string& yamlText, const std::filesystem::path& file,
                            const std::vector<Override>& overrides = {});

/// The effective config as YAML: every key with its value, defaults included.
std::string effectiveConfigYaml(const RunConfig& config);

}  // namespace tofsim::config
