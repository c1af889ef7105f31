// Config loading: typed values with units, defaults, overrides, and errors
// that name the file, line, column and key.

#include <gtest/gtest.h>

#include <fstream>
#include <variant>

#include "support/TempDir.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/config/Units.h"
#include "tofsim/util/Error.h"
#include "tofsim/volume/PhysicalConstants.h"

namespace tofsim::config {
namespace {

class RunConfigTest : public test::TempDirTest {
 protected:
  std::filesystem::path write(const std::string& yaml) {
    std::ofstream(dir_ / "scene.gltf") << "{}";
    const auto path = dir_ / "test.yaml";
    std::ofstream(path) << yaml;
    return path;
  }
  // The message of the InputError loading `yaml` throws.
  std::string errorOf(const std::string& yaml, const std::vector<Override>& overrides = {}) {
    try {
      loadRunConfig(write(yaml), overrides);
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no error for:\n" << yaml;
    return "";
  }
};

const char* kValid = R"(scene: scene.gltf
camera:
  position: [0, 0, 2]
  look_at: [0, 0, 0]
  fov_y: 45 deg
  resolution: [32, 24]
light:
  type: spot
  position: [0, 1, 2]
  direction: [0, 0, -1]
  cone_angle: 0.5 rad
  intensity: [1, 2, 3]
time:
  start: 1 ns
  bin_width: "0.3 mm"
  bins: 100
)";

TEST_F(RunConfigTest, ValidConfigFillsTypedStructsWithUnitsConverted) {
  const RunConfig c = loadRunConfig(write(kValid));
  EXPECT_EQ(c.camera.camera.width, 32);
  EXPECT_EQ(c.camera.camera.height, 24);
  EXPECT_FLOAT_EQ(c.camera.camera.fov_y_deg, 45.0f);
  EXPECT_EQ(c.light.light.type, capture::Light::Type::Spot);
  EXPECT_NEAR(c.light.light.cone_half_angle_deg, 0.5 * 180.0 / M_PI, 1e-4);
  EXPECT_FLOAT_EQ(c.light.light.intensity_W_per_sr.z, 3.0f);
  EXPECT_DOUBLE_EQ(c.render.time.start_s, 1e-9);
  EXPECT_NEAR(c.render.time.bin_width_s, 0.3e-3 / kSpeedOfLight_m_per_s, 1e-24);
  EXPECT_EQ(c.render.time.bins, 100);
  EXPECT_EQ(c.output.directory, "out");  // default
  EXPECT_EQ(c.scene_file, dir_ / "scene.gltf");
}

TEST_F(RunConfigTest, UnitsParse) {
  EXPECT_DOUBLE_EQ(parseDuration_s("10 ps"), 10e-12);
  EXPECT_DOUBLE_EQ(parseDuration_s("3ns"), 3e-9);
  EXPECT_DOUBLE_EQ(parseDuration_s("0.5 m"), 0.5 / kSpeedOfLight_m_per_s);
  EXPECT_DOUBLE_EQ(parseLength_m("5 cm"), 0.05);
  EXPECT_DOUBLE_EQ(parseBytes("2 MiB"), 2.0 * 1024 * 1024);
  EXPECT_DOUBLE_EQ(parseFrequency_Hz("20 MHz"), 20e6);
  EXPECT_THROW(parseDuration_s("10 parsecs"), std::invalid_argument);
  EXPECT_THROW(parseDuration_s("fast"), std::invalid_argument);
}

// A bare time was seconds: "bin_width: 10" meant as 10 ps rendered one 10 s
// bin (issue 44). Only 0, the same in every unit, needs none.
TEST_F(RunConfigTest, ATimeWithoutAUnitIsAnErrorThatShowsTheForms) {
  EXPECT_DOUBLE_EQ(parseDuration_s("0"), 0.0);
  for (const char* bare : {"10", "1e-9", "-2"}) {
    try {
      parseDuration_s(bare);
      ADD_FAILURE() << bare << " accepted";
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("a time needs a unit"), std::string::npos) << what;
      EXPECT_NE(what.find(std::string(bare) + " ps"), std::string::npos) << what;
      EXPECT_NE(what.find("mm"), std::string::npos) << what;
    }
  }
  std::string yaml = kValid;
  yaml.replace(yaml.find("bin_width: \"0.3 mm\""), 19, "bin_width: 10");
  const std::string e = errorOf(yaml);
  EXPECT_NE(e.find("time.bin_width: a time needs a unit"), std::string::npos) << e;
  EXPECT_NE(e.find("test.yaml:"), std::string::npos) << e;
}

TEST_F(RunConfigTest, UnknownKeyNamesFileLineColumnAndKey) {
  const std::string e = errorOf(std::string(kValid) + "  bin_widht: 3 ps\n");
  EXPECT_NE(e.find("test.yaml:17:3"), std::string::npos) << e;
  EXPECT_NE(e.find("time.bin_widht"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown key"), std::string::npos) << e;
}

TEST_F(RunConfigTest, WrongTypeNamesLineAndKey) {
  std::string yaml = kValid;
  yaml.replace(yaml.find("bins: 100"), 9, "bins: lots");
  const std::string e = errorOf(yaml);
  EXPECT_NE(e.find("test.yaml:16:9"), std::string::npos) << e;
  EXPECT_NE(e.find("time.bins"), std::string::npos) << e;
  EXPECT_NE(e.find("integer"), std::string::npos) << e;
}

TEST_F(RunConfigTest, NegativeBinWidthIsRejected) {
  std::string yaml = kValid;
  yaml.replace(yaml.find("\"0.3 mm\""), 8, "-3 ps");
  const std::string e = errorOf(yaml);
  EXPECT_NE(e.find("test.yaml:15:14"), std::string::npos) << e;
  EXPECT_NE(e.find("time.bin_width: must be > 0"), std::string::npos) << e;
}

TEST_F(RunConfigTest, MissingSceneFileIsRejectedWithItsPath) {
  std::string yaml = kValid;
  yaml.replace(0, std::string("scene: scene.gltf").size(), "scene: nowhere.gltf");
  const std::string e = errorOf(yaml);
  EXPECT_NE(e.find("test.yaml:1:8"), std::string::npos) << e;
  EXPECT_NE(e.find("nowhere.gltf"), std::string::npos) << e;
}

TEST_F(RunConfigTest, YamlSyntaxErrorHasALocation) {
  const std::string e = errorOf("scene: [unclosed\n");
  EXPECT_NE(e.find("test.yaml:"), std::string::npos) << e;
}

TEST_F(RunConfigTest, OverridesApplyAndTheirErrorsNameTheOverride) {
  const RunConfig c = loadRunConfig(
      write(kValid), {parseOverride("time.bins=7"), parseOverride("camera.resolution=[8, 4]")});
  EXPECT_EQ(c.render.time.bins, 7);
  EXPECT_EQ(c.camera.camera.width, 8);
  const std::string e = errorOf(kValid, {parseOverride("time.bins=-1")});
  EXPECT_NE(e.find("--set time.bins=-1"), std::string::npos) << e;
  const std::string unknown = errorOf(kValid, {parseOverride("time.binz=1")});
  EXPECT_NE(unknown.find("time.binz: unknown key"), std::string::npos) << unknown;
  EXPECT_THROW(parseOverride("no-equals-sign"), InputError);
}

TEST_F(RunConfigTest, ReferencePixelFilterDefaultsToBoxAndRoundTrips) {
  const RunConfig c = loadRunConfig(write(kValid));
  EXPECT_EQ(c.reference.pixel_filter, ReferencePixelFilter::Box);
  EXPECT_NE(effectiveConfigYaml(c).find("pixel_filter: box"), std::string::npos);
  const RunConfig p =
      loadRunConfig(write(kValid), {parseOverride("render.reference.pixel_filter=point")});
  EXPECT_EQ(p.reference.pixel_filter, ReferencePixelFilter::Point);
  EXPECT_NE(effectiveConfigYaml(p).find("pixel_filter: point"), std::string::npos);
  const std::string e = errorOf(kValid, {parseOverride("render.reference.pixel_filter=gauss")});
  EXPECT_NE(e.find("must be box or point"), std::string::npos) << e;
}

TEST_F(RunConfigTest, ReferenceSamplingDefaultsToBrdfAndRoundTrips) {
  const RunConfig c = loadRunConfig(write(kValid));
  EXPECT_EQ(c.reference.sampling, ReferenceSampling::Brdf);
  EXPECT_NE(effectiveConfigYaml(c).find("sampling: brdf"), std::string::npos);
  const RunConfig p =
      loadRunConfig(write(kValid), {parseOverride("render.reference.sampling=cosine")});
  EXPECT_EQ(p.reference.sampling, ReferenceSampling::Cosine);
  EXPECT_NE(effectiveConfigYaml(p).find("sampling: cosine"), std::string::npos);
  const std::string e = errorOf(kValid, {parseOverride("render.reference.sampling=vndf")});
  EXPECT_NE(e.find("must be brdf or cosine"), std::string::npos) << e;
}

TEST_F(RunConfigTest, EffectiveConfigRoundTrips) {
  const RunConfig c = loadRunConfig(write(kValid));
  const auto path = dir_ / "effective.yaml";
  std::ofstream(path) << effectiveConfigYaml(c);
  const RunConfig again = loadRunConfig(path);
  EXPECT_EQ(effectiveConfigYaml(again), effectiveConfigYaml(c));
  EXPECT_DOUBLE_EQ(again.render.time.bin_width_s, c.render.time.bin_width_s);
}

const char* kSensors = R"(sensors:
  - type: spad
    cycles: 500
    pulse_fwhm: 80 ps
  - type: cwtof
    name: tof
    frequencies: [20 MHz, 100 MHz]
)";

TEST_F(RunConfigTest, SensorsAreParsedAndWrittenBack) {
  const RunConfig c = loadRunConfig(write(std::string(kValid) + kSensors));
  ASSERT_EQ(c.sensors.size(), 2u);
  EXPECT_EQ(c.sensors[0].name, "spad");
  EXPECT_EQ(std::get<sensors::SpadParams>(c.sensors[0].params).cycles, 500);
  EXPECT_EQ(c.sensors[1].name, "tof");
  EXPECT_EQ(std::get<sensors::CwTofParams>(c.sensors[1].params).frequencies_Hz.size(), 2u);
  const auto path = dir_ / "effective.yaml";
  std::ofstream(path) << effectiveConfigYaml(c);
  const RunConfig again = loadRunConfig(path);
  EXPECT_EQ(effectiveConfigYaml(again), effectiveConfigYaml(c));
  EXPECT_DOUBLE_EQ(std::get<sensors::SpadParams>(again.sensors[0].params).pulse_fwhm_s, 80e-12);
  EXPECT_TRUE(loadRunConfig(write(kValid)).sensors.empty());
}

TEST_F(RunConfigTest, SensorErrorsAreLocated) {
  const std::string typo = errorOf(std::string(kValid) + kSensors + "    pulse_fwhn: 1 ps\n");
  EXPECT_NE(typo.find("test.yaml:24:5"), std::string::npos) << typo;
  EXPECT_NE(typo.find("sensors[1].pulse_fwhn: unknown key"), std::string::npos) << typo;
  const std::string negative =
      errorOf(std::string(kValid) + kSensors, {parseOverride("sensors.0.pulse_fwhm=-1ps")});
  EXPECT_NE(negative.find("--set sensors.0.pulse_fwhm=-1ps"), std::string::npos) << negative;
  EXPECT_NE(negative.find("sensors[0].pulse_fwhm"), std::string::npos) << negative;
  const std::string twice =
      errorOf(std::string(kValid) + kSensors, {parseOverride("sensors.1.name=spad")});
  EXPECT_NE(twice.find("sensors[1].name"), std::string::npos) << twice;
  EXPECT_NE(twice.find("already used"), std::string::npos) << twice;
  const std::string path =
      errorOf(std::string(kValid) + kSensors, {parseOverride("sensors.1.name=a/b")});
  EXPECT_NE(path.find("sensors[1].name"), std::string::npos) << path;
}

TEST_F(RunConfigTest, SensorRowsAndPixelsOutsideTheImageAreRejectedBeforeRendering) {
  const std::string streak =
      errorOf(std::string(kValid) + "sensors:\n  - type: streak\n    rows: [30]\n");
  EXPECT_NE(streak.find("sensors[0].rows: row 30 is outside the image (height 24)"),
            std::string::npos)
      << streak;
  const std::string spad =
      errorOf(std::string(kValid) + "sensors:\n  - type: spad\n    plot_pixels: [[32, 0]]\n");
  EXPECT_NE(spad.find("sensors[0].plot_pixels"), std::string::npos) << spad;
  EXPECT_NE(spad.find("test.yaml:"), std::string::npos) << spad;
}

// SPAD timing that cannot work: a gate outside the TDC's window.
TEST_F(RunConfigTest, SpadGateOutsideTheWindowIsALocatedError) {
  const std::string gate = errorOf(std::string(kValid) +
                                   "sensors:\n  - type: spad\n    gate_start: 1 us\n"
                                   "    gate_width: 1 ns\n");
  EXPECT_NE(gate.find("sensors[0].gate_start"), std::string::npos) << gate;
  EXPECT_NE(gate.find("outside the TDC"), std::string::npos) << gate;
  // Afterpulses in both modes (synchronous: they spill into later cycles).
  EXPECT_NO_THROW(loadRunConfig(
      write(std::string(kValid) + "sensors:\n  - type: spad\n    afterpulse_probability: 0.1\n")));
  EXPECT_NO_THROW(
      loadRunConfig(write(std::string(kValid) + "sensors:\n  - type: spad\n    mode: free_running\n"
                                                "    afterpulse_probability: 0.1\n")));
}

TEST_F(RunConfigTest, VplCountIsBoundedWithALocatedError) {
  // A 30-degree spot uses one RSM view; a point light six cube faces.
  EXPECT_NO_THROW(
      loadRunConfig(write(kValid), {parseOverride("render.indirect.rsm_resolution=2048")}));
  const std::string e = errorOf(kValid, {parseOverride("light.type=point"),
                                         parseOverride("render.indirect.rsm_resolution=2048")});
  EXPECT_NE(e.find("render.indirect.rsm_resolution: 2048^2 x 6 light view(s) = 25165824 VPLs"),
            std::string::npos)
      << e;
}

TEST_F(RunConfigTest, BackendDefaultsToAutoParsesAndRoundTrips) {
  EXPECT_EQ(loadRunConfig(write(kValid)).backend, IrBackendKind::Auto);
  for (const auto& [name, kind] :
       {std::pair{"gl", IrBackendKind::Gl}, std::pair{"cpu", IrBackendKind::Cpu},
        std::pair{"auto", IrBackendKind::Auto}}) {
    const RunConfig c =
        loadRunConfig(write(std::string(kValid) + "render:\n  backend: " + name + "\n"));
    EXPECT_EQ(c.backend, kind) << name;
    EXPECT_NE(effectiveConfigYaml(c).find(std::string("backend: ") + name), std::string::npos);
  }
}

TEST_F(RunConfigTest, UnknownBackendIsALocatedError) {
  const std::string e = errorOf(std::string(kValid) + "render:\n  backend: vulkan\n");
  EXPECT_NE(e.find("test.yaml:18:12"), std::string::npos) << e;
  EXPECT_NE(e.find("render.backend"), std::string::npos) << e;
  EXPECT_NE(e.find("auto, gl or cpu"), std::string::npos) << e;
  EXPECT_NE(e.find("vulkan"), std::string::npos) << e;
}

TEST_F(RunConfigTest, BounceComponentsUpToTheBouncesParseAndRoundTrip) {
  const std::string yaml = std::string(kValid) +
                           "render:\n  indirect:\n    bounces: 2\n"
                           "output:\n  components: [bounce2, direct, bounce1, bounce2]\n";
  const RunConfig c = loadRunConfig(write(yaml));
  EXPECT_EQ(c.output.bounces, (std::vector<int32_t>{1, 2}));
  EXPECT_TRUE(c.output.direct);
  EXPECT_NE(effectiveConfigYaml(c).find("components: [direct, bounce1, bounce2]"),
            std::string::npos)
      << effectiveConfigYaml(c);
  // One bounce (the default): bounce1 is the indirect light.
  EXPECT_EQ(loadRunConfig(write(std::string(kValid) + "output:\n  components: [bounce1]\n"))
                .output.bounces,
            (std::vector<int32_t>{1}));
}

TEST_F(RunConfigTest, BounceComponentAboveTheBouncesIsALocatedError) {
  const std::string e = errorOf(std::string(kValid) +
                                "render:\n  indirect:\n    bounces: 2\n"
                                "output:\n  components: [bounce1, bounce3]\n");
  EXPECT_NE(e.find("test.yaml:21:25"), std::string::npos) << e;
  EXPECT_NE(e.find("output.components[1]"), std::string::npos) << e;
  EXPECT_NE(e.find("bounce3"), std::string::npos) << e;
  EXPECT_NE(e.find("render.indirect.bounces: 2"), std::string::npos) << e;
  for (const char* bad : {"bounce0", "bounce", "bounce01", "bounce1x"}) {
    const std::string b = errorOf(std::string(kValid) + "output:\n  components: [" + bad + "]\n");
    EXPECT_NE(b.find("output.components[0]"), std::string::npos) << bad << ": " << b;
  }
  const std::string r = errorOf(std::string(kValid) +
                                "render:\n  renderer: reference\n"
                                "output:\n  components: [bounce1]\n");
  EXPECT_NE(r.find("render.renderer: ir"), std::string::npos) << r;
}

// An nlos capture renders with IR on either backend (the GL one gathers from
// the driver's traced wall points) or with the reference path tracer.
TEST_F(RunConfigTest, NlosTakesTheReferenceAndEitherBackend) {
  const std::string nlos =
      "scene: scene.gltf\n"
      "nlos: {relay_wall: w, sensor_origin: [0, 0, 1], laser_origin: [0, 0, 1]}\ntime: {}\n";
  const RunConfig c = loadRunConfig(write(nlos + "render: {renderer: reference}\n"));
  EXPECT_EQ(c.renderer, RendererKind::Reference);
  EXPECT_EQ(loadRunConfig(write(nlos + "render: {backend: gl}\n")).backend, IrBackendKind::Gl);
  EXPECT_EQ(loadRunConfig(write(nlos + "render: {backend: cpu}\n")).backend, IrBackendKind::Cpu);
}

}  // namespace
}  // namespace tofsim::config
