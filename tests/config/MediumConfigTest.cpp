// Issue 42's `medium:` section (apps/config/src/MediumSection.cpp): each form
// reaches RenderSettings::medium (a scalar or [R, G, B] in 1/m, a unit form,
// the phase models), fog by visibility is Koschmieder's sigma_t = 3.912 / V
// with fog droplets' albedo and g, the medium's index of refraction is the
// time axis's, the effective config reloads to the same medium, and bad
// input is a located error at its line: negative coefficients, |g| >= 1, an
// unknown phase model, a visibility <= 0, a list of the wrong length,
// per-region `media:` scattering on GL or with `medium:` (MediaCliTest has the rest)
// and captures the renderers do not build a medium into (nlos, rays).

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "support/TempDir.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/physics/MediumPhysics.h"
#include "tofsim/util/Error.h"

namespace tofsim::config {
namespace {

// The config's first four lines; `medium` starts on line 5.
constexpr const char* kHead = "scene: scene.gltf\ncamera: {}\nlight: {}\ntime: {}\n";

class MediumConfigTest : public test::TempDirTest {
 protected:
  RunConfig load(const std::string& body, const std::vector<Override>& overrides = {},
                 const std::string& head = kHead) {
    std::ofstream(dir_ / "scene.gltf") << "{}";
    std::ofstream(dir_ / "c.yaml") << head << body;
    return loadRunConfig(dir_ / "c.yaml", overrides);
  }
  // The error a config gives: its line and its message (with the key).
  struct Failure {
    int line = 0;
    std::string what;
  };
  Failure errorOf(const std::string& body, const std::string& head = kHead) {
    try {
      load(body, {}, head);
    } catch (const InputError& e) {
      return {e.location().line, e.what()};
    }
    return {0, "no error"};
  }
};

void expectVec(const glm::vec3& v, float r, float g, float b) {
  EXPECT_FLOAT_EQ(v.r, r);
  EXPECT_FLOAT_EQ(v.g, g);
  EXPECT_FLOAT_EQ(v.b, b);
}

TEST_F(MediumConfigTest, ScalarAndPerChannelCoefficientsReachTheRenderSettings) {
  const RunConfig c = load(
      "medium: {sigma_a: 0.01, sigma_s: [0.04, 0.05, 0.06],\n"
      "         phase: {model: henyey_greenstein, g: 0.6}}\n");
  const capture::Medium& m = c.render.medium;
  EXPECT_TRUE(m.present());
  expectVec(m.sigma_a_per_m, 0.01f, 0.01f, 0.01f);
  expectVec(m.sigma_s_per_m, 0.04f, 0.05f, 0.06f);
  EXPECT_EQ(m.phase, physics::PHASE_HENYEY_GREENSTEIN);
  EXPECT_FLOAT_EQ(m.g, 0.6f);
  EXPECT_DOUBLE_EQ(c.render.time.index_of_refraction, 1.0);  // not given: vacuum's
  ASSERT_TRUE(c.medium.has_value());
  EXPECT_EQ(c.medium->visibility_m, 0.0);
  // Without `medium:` there is none.
  EXPECT_FALSE(load("").render.medium.present());
  EXPECT_FALSE(load("").medium.has_value());
}

TEST_F(MediumConfigTest, CoefficientsReadUnitsOfReciprocalLength) {
  const RunConfig c = load("medium: {sigma_a: 0.04 /m, sigma_s: [4 1/km, 0.1 /cm, 2 1/m]}\n");
  expectVec(c.render.medium.sigma_a_per_m, 0.04f, 0.04f, 0.04f);
  expectVec(c.render.medium.sigma_s_per_m, 0.004f, 10.0f, 2.0f);
}

TEST_F(MediumConfigTest, PhaseModels) {
  EXPECT_EQ(load("medium: {sigma_s: 1}\n").render.medium.phase, physics::PHASE_ISOTROPIC);
  EXPECT_EQ(load("medium: {sigma_s: 1, phase: {model: rayleigh}}\n").render.medium.phase,
            physics::PHASE_RAYLEIGH);
  EXPECT_EQ(load("medium: {sigma_s: 1, phase: rayleigh}\n").render.medium.phase,
            physics::PHASE_RAYLEIGH);
  const RunConfig iso = load("medium: {sigma_s: 1, phase: {model: isotropic}}\n");
  EXPECT_EQ(iso.render.medium.phase, physics::PHASE_ISOTROPIC);
  EXPECT_EQ(iso.render.medium.g, 0.0f);
  EXPECT_FLOAT_EQ(
      load("medium: {sigma_s: 1, phase: {model: henyey_greenstein, g: -0.3}}\n").render.medium.g,
      -0.3f);
}

TEST_F(MediumConfigTest, FogByVisibilityIsKoschmieder) {
  const RunConfig c = load("medium: {visibility: 50 m}\n");
  const capture::Medium& m = c.render.medium;
  const float sigmaT = static_cast<float>(3.912 / 50.0);  // 0.07824 / m
  for (int ch = 0; ch < 3; ++ch) {
    EXPECT_NEAR(m.sigmaT()[ch], sigmaT, 1e-7f);
    EXPECT_NEAR(m.albedo()[ch], 0.99996f, 1e-6f);  // fog droplets at 905 nm (Mie)
  }
  EXPECT_EQ(m.phase, physics::PHASE_HENYEY_GREENSTEIN);
  EXPECT_FLOAT_EQ(m.g, 0.845f);
  EXPECT_DOUBLE_EQ(c.medium->visibility_m, 50.0);
  // A length in any unit, a bare number in metres; the albedo and the
  // phase function may be given.
  const RunConfig km =
      load("medium: {visibility: 0.2 km, albedo: [0.9, 0.8, 1], phase: {model: isotropic}}\n");
  EXPECT_NEAR(km.render.medium.sigmaT().r, 3.912f / 200.0f, 1e-7f);
  EXPECT_NEAR(km.render.medium.sigma_s_per_m.g, 0.8f * 3.912f / 200.0f, 1e-7f);
  EXPECT_NEAR(km.render.medium.sigma_a_per_m.b, 0.0f, 1e-9f);
  EXPECT_EQ(km.render.medium.phase, physics::PHASE_ISOTROPIC);
  EXPECT_NEAR(load("medium: {visibility: 30}\n").render.medium.sigmaT().g, 3.912f / 30.0f, 1e-7f);
}

TEST_F(MediumConfigTest, TheMediumsIndexOfRefractionIsTheTimeAxiss) {
  EXPECT_DOUBLE_EQ(
      load("medium: {sigma_a: 0.3, index_of_refraction: 1.33}\n").render.time.index_of_refraction,
      1.33);
  // Given in both places, the same: fine.
  const std::string same =
      "scene: scene.gltf\ncamera: {}\nlight: {}\n"
      "time: {index_of_refraction: 1.33}\n";
  EXPECT_DOUBLE_EQ(load("medium: {sigma_a: 0.3, index_of_refraction: 1.33}\n", {}, same)
                       .render.time.index_of_refraction,
                   1.33);
  // Different: an error at the medium's key that names time's line.
  const std::string other =
      "scene: scene.gltf\ncamera: {}\nlight: {}\n"
      "time: {index_of_refraction: 1.5}\n";
  const Failure f = errorOf("medium:\n  sigma_a: 0.3\n  index_of_refraction: 1.33\n", other);
  EXPECT_EQ(f.line, 7) << f.what;
  EXPECT_NE(f.what.find("medium.index_of_refraction"), std::string::npos) << f.what;
  EXPECT_NE(f.what.find("c.yaml:4"), std::string::npos) << f.what;  // where time's is
  EXPECT_EQ(errorOf("medium: {sigma_a: 0.3, index_of_refraction: 0.9}\n").line, 5);
}

TEST_F(MediumConfigTest, BadInputIsALocatedError) {
  struct Case {
    const char* body;
    int line;
    const char* key;
    const char* says;
  };
  const Case cases[] = {
      {"medium:\n  sigma_a: -0.01\n", 6, "medium.sigma_a", ">= 0"},
      {"medium:\n  sigma_s: [0.1, -1, 0]\n", 6, "medium.sigma_s", ">= 0"},
      {"medium:\n  sigma_s: [0.1, 0.2]\n", 6, "medium.sigma_s", "list of 3"},
      {"medium:\n  sigma_s: [0.1, 0.2, 0.3, 0.4]\n", 6, "medium.sigma_s", "got 4 values"},
      {"medium:\n  sigma_s: 0.1 /s\n", 6, "medium.sigma_s", "unit"},
      {"medium:\n  sigma_s: 1e39\n", 6, "medium.sigma_s", "too large"},
      {"medium:\n  sigma_s: 1\n  phase: {model: henyey_greenstein, g: 1}\n", 7, "medium.phase.g",
       "(-1, 1)"},
      {"medium:\n  sigma_s: 1\n  phase: {model: henyey_greenstein, g: -1.5}\n", 7, "medium.phase.g",
       "(-1, 1)"},
      {"medium:\n  sigma_s: 1\n  phase: {model: henyey_greenstein}\n", 7, "medium.phase", "g"},
      {"medium:\n  sigma_s: 1\n  phase: {model: mie}\n", 7, "medium.phase.model", "rayleigh"},
      {"medium:\n  sigma_s: 1\n  phase: mie\n", 7, "medium.phase", "henyey_greenstein"},
      {"medium:\n  sigma_s: 1\n  phase: {model: isotropic, g: 0.5}\n", 7, "medium.phase.g",
       "henyey_greenstein"},
      {"medium:\n  visibility: 0 m\n", 6, "medium.visibility", "> 0"},
      {"medium:\n  visibility: -50 m\n", 6, "medium.visibility", "> 0"},
      {"medium:\n  visibility: 50 m\n  sigma_s: 0.04\n", 7, "medium.sigma_s", "not both"},
      {"medium:\n  visibility: 50 m\n  albedo: 1.2\n", 7, "medium.albedo", "[0, 1]"},
      {"medium:\n  sigma_s: 1\n  albedo: 0.9\n", 7, "medium.albedo", "visibility"},
      {"medium:\n  sigma_s: 1\n  sigma_x: 1\n", 7, "medium.sigma_x", ""},
      {"medium: [0.1]\n", 5, "medium", "mapping"},
      {"media:\n  - {region: tank, sigma_s: 0.3}\n", 6, "media[0].sigma_s", "render.backend: cpu"},
  };
  for (const Case& c : cases) {
    const Failure f = errorOf(c.body);
    EXPECT_EQ(f.line, c.line) << c.body << " -> " << f.what;
    EXPECT_NE(f.what.find(c.key), std::string::npos) << c.body << " -> " << f.what;
    EXPECT_NE(f.what.find(c.says), std::string::npos) << c.body << " -> " << f.what;
  }
}

TEST_F(MediumConfigTest, PerRegionMediaSayWhatIsBuilt) {
  // An absorbing region is built on every backend; a scattering one not on GL
  // (nor with auto, which may pick GL), whatever the CPU backend builds.
  for (const char* backend : {"auto", "gl", "cpu"}) {
    EXPECT_EQ(errorOf("render: {backend: " + std::string(backend) +
                      "}\nmedia:\n  - {region: tank, sigma_a: 0.3}\n")
                  .what,
              "no error")
        << backend;
  }
  for (const char* backend : {"auto", "gl"}) {
    const Failure gl = errorOf("render: {backend: " + std::string(backend) +
                               "}\nmedia:\n  - {region: tank, sigma_s: 0.3}\n");
    EXPECT_EQ(gl.line, 7) << gl.what;
    EXPECT_NE(gl.what.find("a scattering region (sigma_s > 0) is not built on the GL backend"),
              std::string::npos)
        << gl.what;
  }
  Failure f = errorOf("medium: {sigma_a: 0.1}\nmedia:\n  - {region: tank, sigma_a: 0.3}\n");
  EXPECT_NE(f.what.find("per-region media together are not built"), std::string::npos) << f.what;
  f = errorOf("render: {backend: cpu}\nmedia:\n  - {region: tank, sigma_s: 0.3}\n",
              "scene: scene.gltf\ncamera: {}\nlight: {}\ntime: {camera_unwarp: true}\n");
  EXPECT_NE(f.what.find("media[0].sigma_s: a scattering region (sigma_s > 0) with "
                        "time.camera_unwarp is not built in instant radiosity"),
            std::string::npos)
      << f.what;
}

TEST_F(MediumConfigTest, CapturesWithoutAMediumAreRefused) {
  std::ofstream(dir_ / "rays.csv") << "0,0,1,0,0,-1\n";
  const std::string nlos =
      "scene: scene.gltf\nnlos: {relay_wall: w, sensor_origin: [0, 0, 1], laser_origin: [0, 0, "
      "1]}\n"
      "time: {}\n";
  Failure f = errorOf("medium:\n  sigma_s: 0.1\n", nlos);
  EXPECT_EQ(f.line, 5) << f.what;
  EXPECT_NE(f.what.find("medium.sigma_s: a medium in an nlos capture is not built yet"),
            std::string::npos)
      << f.what;
  const std::string rays = "scene: scene.gltf\nrays: {file: rays.csv}\nlight: {}\ntime: {}\n";
  f = errorOf("medium:\n  sigma_s: 0.1\n", rays);
  EXPECT_EQ(f.line, 6) << f.what;
  EXPECT_NE(f.what.find("ray-list capture"), std::string::npos) << f.what;
  // A clear medium (its index alone) is no medium to refuse.
  std::ofstream(dir_ / "scene.gltf") << "{}";
  std::ofstream(dir_ / "n.yaml") << nlos << "medium: {index_of_refraction: 1.33}\n";
  EXPECT_DOUBLE_EQ(loadRunConfig(dir_ / "n.yaml").render.time.index_of_refraction, 1.33);
}

TEST_F(MediumConfigTest, EffectiveConfigReloadsToTheSameMedium) {
  for (const char* body :
       {"medium: {sigma_a: [0.3, 0.05, 0.02], sigma_s: 0.1, phase: {model: henyey_greenstein, "
        "g: 0.6}, index_of_refraction: 1.33}\n",
        "medium: {visibility: 42 m}\n", "medium: {visibility: 30 m, albedo: [0.9, 0.95, 1]}\n",
        "medium: {sigma_s: 0.2 /cm, phase: rayleigh}\n"}) {
    const RunConfig c = load(body);
    const std::string yaml = effectiveConfigYaml(c);
    std::ofstream(dir_ / "e.yaml") << yaml;
    const RunConfig again = loadRunConfig(dir_ / "e.yaml");
    EXPECT_EQ(effectiveConfigYaml(again), yaml) << body;
    EXPECT_EQ(again.render.medium.sigma_a_per_m, c.render.medium.sigma_a_per_m) << body;
    EXPECT_EQ(again.render.medium.sigma_s_per_m, c.render.medium.sigma_s_per_m) << body;
    EXPECT_EQ(again.render.medium.phase, c.render.medium.phase) << body;
    EXPECT_EQ(again.render.medium.g, c.render.medium.g) << body;
    EXPECT_EQ(again.render.time.index_of_refraction, c.render.time.index_of_refraction) << body;
  }
  // Fog keeps the form it was written in.
  EXPECT_NE(effectiveConfigYaml(load("medium: {visibility: 42 m}\n")).find("visibility: 42 m"),
            std::string::npos);
  // Without a medium the effective config has no `medium` key (its bytes as before).
  EXPECT_EQ(effectiveConfigYaml(load("")).find("medium"), std::string::npos);
}

TEST_F(MediumConfigTest, SetOverridesAMediumKey) {
  const RunConfig c = load("medium: {sigma_s: 0.04}\n", {parseOverride("medium.sigma_s=0.1")});
  EXPECT_FLOAT_EQ(c.render.medium.sigma_s_per_m.g, 0.1f);
  // On a config without one, --set makes the section.
  const RunConfig made = load("", {parseOverride("medium.visibility=50 m")});
  EXPECT_NEAR(made.render.medium.sigmaT().r, 3.912f / 50.0f, 1e-7f);
  // An error in it names the --set.
  try {
    load("", {parseOverride("medium.sigma_s=-1")});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--set medium.sigma_s=-1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tofsim::config
