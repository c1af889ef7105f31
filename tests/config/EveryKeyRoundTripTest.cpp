// The effective config round-trips a config in which EVERY declared run key
// has a non-default value: a key that the writer dropped, or wrote back as
// its default, would show here. Which keys there are comes from the
// declared table (ConfigKeys.h), so a new key without a value in kEveryKey
// fails the coverage check below.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <sstream>
#include <string>

#include "support/TempDir.h"
#include "tofsim/config/ConfigKeys.h"
#include "tofsim/config/RunConfig.h"

namespace tofsim::config {
namespace {

// Required sections, empty: every key at its default.
const char* kMinimal = "scene: scene.gltf\ncamera: {}\nlight: {}\ntime: {}\n";

const char* kEveryKey = R"(scene: scene.gltf
sequence: {start: 0.5 s, rate: 30 Hz, count: 3, exposure_samples: 2, video: false}
camera:
  gltf_camera: cam
  position: [0.5, 0.25, 2]
  look_at: [0.1, 0.2, 0.3]
  up: [0, 0, 1]
  fov_y: 33 deg
  resolution: [40, 30]
  vignetting: cos4
  psf: {core_sigma: 0.7, halo_weight: 0.05, halo_profile: exponential, halo_radius: 6}
  aperture: 4 mm
  focus_distance: 2.5
  aperture_samples: 9
light:
  type: spot
  attach_to_camera: true
  offset: [0.01, 0.02, 0.03]
  position: [1, 2, 3]
  direction: [0, -1, 0]
  cone_angle: 25 deg
  cone_falloff: 3 deg
  intensity: [2, 3, 4]
time:
  start: 1 ns
  bin_width: 20 ps
  bins: 300
  index_of_refraction: 1.33
  camera_unwarp: true
medium:
  sigma_a: [0.3, 0.05, 0.02]
  sigma_s: 0.1
  phase: {model: henyey_greenstein, g: 0.3}
  index_of_refraction: 1.33
render:
  renderer: reference
  backend: cpu
  threads: 3
  seed: 7
  shadow_map_resolution: 256
  memory_budget: 100 MiB
  strict: true
  pixel_footprint: false
  pixel_samples: 3
  adaptive_pixel_samples: true
  materials: gltf
  indirect:
    enabled: false
    rsm_resolution: 8
    medium_vpls: 300
    medium_camera_rays: false
    gather_pairs: 500
    rsm_edge_samples: 3
    merge_pixel_samples: true
    ism_resolution: 16
    points_per_vpl: 200
    ism_pull_push: false
    visibility: exact
    geometry_clamp: 50
    vpl_brdf_clamp: 8
    vpl_footprint: false
    bounces: 3
    vpls_per_bounce: 500
    russian_roulette: true
  reference:
    bounces: 3
    samples_per_pixel: 16
    threads: 2
    pixel_filter: point
    sampling: cosine
output:
  directory: elsewhere
  format: hdf5
  transient: false
  steady: false
  depth: false
  frames: true
  components: [direct, indirect]
  video: true
  video_tone_map: log
  video_stride: 2
  video_window: 4
  video_fps: 24
  max_bytes: 3 GiB
  frame_pngs: true
  plot_ranges: {depth: [0.5, 3], sensors/spad/spad_depth_peak: [-0.25, 2]}
sensors:
  - type: spad
)";

// The nlos keys (instead of camera and light); laser_point is single's.
const char* kMinimalNlos =
    "scene: scene.gltf\nnlos: {relay_wall: w, sensor_origin: [0, 0, 1], laser_origin: [0, 0, 1]}\n"
    "time: {}\n";
const char* kEveryNlosKey = R"(scene: scene.gltf
nlos:
  relay_wall: wall
  scan: exhaustive
  sensor_grid: [8, 4]
  laser_grid: [2, 3]
  laser_aperture: [[0.25, 0.125], [0.75, 0.5]]
  sensor_origin: [0.5, 0.25, 1]
  laser_origin: [-0.5, 0.25, 1]
  laser_power: [2, 3, 4]
  laser_falloff: projector
  account_first_and_last_bounces: true
  hdf5: false
time: {bins: 64}
)";
const char* kSingleNlos =
    "scene: scene.gltf\nnlos: {relay_wall: w, scan: single, laser_point: [0.25, 0.75], "
    "sensor_origin: [0, 0, 1], laser_origin: [0, 0, 1]}\ntime: {}\n";

// The lidar's keys (instead of camera and light), each off its default
// (`scan` has one value today).
const char* kMinimalLidar =
    "scene: scene.gltf\nlidar: {position: [0, 0, 1], orientation: {look_at: [1, 0, 1]}, "
    "channels: {count: 1}}\ntime: {}\n";
const char* kEveryLidarKey = R"(scene: scene.gltf
lidar:
  position: [0, 0, 1]
  orientation: {look_at: [1, 0, 1], up: [0, 0.5, 2]}
  channels: {count: 3, min: -5, max: 5}
  azimuth: {start: 10, end: 100, step: 1.5}
  beam_divergence: 0.2 deg
  beam_profile: tophat
  beam_rays: 7
  power: 2
  rotation_rate: 20 Hz
  returns: {mode: all, max: 4, threshold: 1e-6, separation: 5 cm}
  plot_beams: [[1, 40]]
  multipath: {bounces: 2, spot_rays: 5, receiver_rays: 9, receiver_fov: 10 deg, vpls_per_bounce: 3}
  backscatter: {overlap: 0.5 m, phase_at_pi: 0.05}
time: {bins: 64}
)";

// The node at a dotted key path, or an undefined node.
YAML::Node at(const YAML::Node& root, const std::string& path) {
  YAML::Node node = YAML::Clone(root);
  std::stringstream parts(path);
  std::string part;
  while (std::getline(parts, part, '.')) {
    if (!node.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
    node = node[part];
  }
  return node;
}

std::string text(const YAML::Node& node) {
  YAML::Emitter out;
  out << node;
  return out.c_str();
}

class EveryKeyRoundTripTest : public test::TempDirTest {
 protected:
  RunConfig load(const std::string& yaml, const std::string& name) {
    std::ofstream(dir_ / "scene.gltf") << "{}";
    std::ofstream(dir_ / name) << yaml;
    return loadRunConfig(dir_ / name);
  }
};

TEST_F(EveryKeyRoundTripTest, EveryDeclaredKeyIsNonDefaultAndSurvivesTheRoundTrip) {
  const YAML::Node defaults = YAML::Load(effectiveConfigYaml(load(kMinimal, "minimal.yaml")));
  const RunConfig every = load(kEveryKey, "every.yaml");
  const std::string written = effectiveConfigYaml(every);
  const YAML::Node effective = YAML::Load(written);
  for (const ConfigKey& key : runConfigKeys()) {
    const std::string type = key.type;
    if (type == "mapping" || std::string(key.path) == "sensors") continue;
    // Refused on the default GL backend and with `medium:` (in every.yaml):
    // MediaCliTest.ARegionRendersAndItsEffectiveConfigRendersAgain.
    if (std::string(key.path) == "media") continue;
    if (std::string(key.path).rfind("nlos.", 0) == 0) continue;  // NlosKeysSurviveTheRoundTrip
    if (std::string(key.path).rfind("lidar.", 0) == 0) continue;  // LidarKeysSurvive...
    // Instead of camera: RayListConfigTest.TheEffectiveConfigRoundTrips.
    if (std::string(key.path).rfind("rays.", 0) == 0) continue;
    // Keyed by a material's name, each model's own keys:
    // MaterialsConfigTest.TheEffectiveConfigReloadsToTheSameKernels.
    if (std::string(key.path).rfind("materials", 0) == 0) continue;
    // Fog's keys exclude sigma_a and sigma_s:
    // MediumConfigTest.EffectiveConfigReloadsToTheSameMedium.
    if (std::string(key.path) == "medium.visibility" || std::string(key.path) == "medium.albedo") {
      continue;
    }
    // Excludes fov_y: LensConfigTest.EffectiveConfigReloadsToTheSameLens.
    if (std::string(key.path).rfind("camera.lens.", 0) == 0) continue;
    // Excludes the parametric keys: PsfConfigTest.KernelFileRoundTrips.
    if (std::string(key.path) == "camera.psf.file") continue;
    // The list form excludes rate and count: ConfigKeysWriterTest writes it.
    if (std::string(key.path) == "sequence.times") continue;
    if (std::string(key.defaultValue) == "required") continue;  // no default to differ from
    const YAML::Node value = at(effective, key.path);
    ASSERT_TRUE(value.IsDefined()) << key.path << " is not in the effective config";
    EXPECT_NE(text(value), text(at(defaults, key.path)))
        << key.path << " has its default value in the test config (give it another)";
  }
  const RunConfig again = load(written, "again.yaml");
  EXPECT_EQ(effectiveConfigYaml(again), written);
}

TEST_F(EveryKeyRoundTripTest, NlosKeysAreNonDefaultAndSurviveTheRoundTrip) {
  const YAML::Node defaults =
      YAML::Load(effectiveConfigYaml(load(kMinimalNlos, "minimal_nlos.yaml")));
  for (const char* yaml : {kEveryNlosKey, kSingleNlos}) {
    const std::string written = effectiveConfigYaml(load(yaml, "nlos.yaml"));
    const YAML::Node effective = YAML::Load(written);
    EXPECT_FALSE(effective["camera"].IsDefined());
    EXPECT_FALSE(effective["light"].IsDefined());
    const RunConfig again = load(written, "again.yaml");
    EXPECT_EQ(effectiveConfigYaml(again), written);
  }
  const YAML::Node every = YAML::Load(effectiveConfigYaml(load(kEveryNlosKey, "every.yaml")));
  const YAML::Node single = YAML::Load(effectiveConfigYaml(load(kSingleNlos, "single.yaml")));
  for (const ConfigKey& key : runConfigKeys()) {
    const std::string path = key.path;
    if (path.rfind("nlos.", 0) != 0) continue;
    const YAML::Node value = at(path == "nlos.laser_point" ? single : every, path);
    ASSERT_TRUE(value.IsDefined()) << path << " is not in the effective config";
    if (std::string(key.defaultValue) == "required") continue;
    const YAML::Node fallback = at(defaults, path);
    if (fallback.IsDefined()) {
      EXPECT_NE(text(value), text(fallback)) << path << " has its default value in the test config";
    }
  }
}

TEST_F(EveryKeyRoundTripTest, LidarKeysAreNonDefaultAndSurviveTheRoundTrip) {
  const YAML::Node defaults =
      YAML::Load(effectiveConfigYaml(load(kMinimalLidar, "minimal_lidar.yaml")));
  const std::string written = effectiveConfigYaml(load(kEveryLidarKey, "lidar.yaml"));
  const YAML::Node every = YAML::Load(written);
  EXPECT_FALSE(every["camera"].IsDefined());
  EXPECT_FALSE(every["light"].IsDefined());
  EXPECT_EQ(effectiveConfigYaml(load(written, "again.yaml")), written);
  for (const ConfigKey& key : runConfigKeys()) {
    const std::string path = key.path;
    if (path.rfind("lidar.", 0) != 0) continue;
    // A grid scan's keys (a raster's frame_rate) and the preset:
    // LidarPresetTest.GridScansAndPresetsRoundTrip.
    if (path.rfind("lidar.grid", 0) == 0 || path.rfind("lidar.field_of_view", 0) == 0 ||
        path == "lidar.zone_rays" || path == "lidar.preset" || path == "lidar.frame_rate") {
      continue;
    }
    const YAML::Node value = at(every, path);
    ASSERT_TRUE(value.IsDefined()) << path << " is not in the effective config";
    if (std::string(key.defaultValue) == "required" || path == "lidar.scan") continue;
    EXPECT_NE(text(value), text(at(defaults, path))) << path << " has its default value";
  }
}

}  // namespace
}  // namespace tofsim::config
