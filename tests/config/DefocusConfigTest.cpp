// camera.aperture, focus_distance, aperture_samples: the thin lens's keys,
// their units, and located errors for what a thin lens cannot mean (a
// negative aperture, a plane in focus at or behind the camera, one aperture
// point) or what would be silently ignored (a focus without an aperture,
// defocus on the GL backend).

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "support/TempDir.h"
#include "tofsim/config/RunConfig.h"

namespace tofsim::config {
namespace {

class DefocusConfigTest : public test::TempDirTest {
 protected:
  RunConfig load(const std::string& camera, const std::string& render = "") {
    std::ofstream(dir_ / "scene.gltf") << "{}";
    std::ofstream(dir_ / "c.yaml")
        << "scene: scene.gltf\ncamera: " << camera << "\nlight: {}\ntime: {}\n"
        << (render.empty() ? "" : "render: " + render + "\n");
    return loadRunConfig(dir_ / "c.yaml");
  }
  std::string errorOf(const std::string& camera, const std::string& render = "") {
    try {
      load(camera, render);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(DefocusConfigTest, KeysTakeLengthUnits) {
  const capture::Camera c =
      load("{aperture: 8 mm, focus_distance: 150 cm, aperture_samples: 25}").camera.camera;
  EXPECT_FLOAT_EQ(c.aperture_m, 0.008f);
  EXPECT_FLOAT_EQ(c.focus_distance_m, 1.5f);
  EXPECT_EQ(c.aperture_samples, 25);
  EXPECT_TRUE(c.defocused());
  EXPECT_FALSE(load("{}").camera.camera.defocused());
}

TEST_F(DefocusConfigTest, BadValuesAreLocatedErrors) {
  const std::string negative = errorOf("{aperture: -1 mm, focus_distance: 1}");
  EXPECT_NE(negative.find("c.yaml:2"), std::string::npos) << negative;
  EXPECT_NE(negative.find("camera.aperture"), std::string::npos) << negative;
  for (const char* focus : {"0", "-2"}) {
    const std::string e = errorOf(std::string("{aperture: 0.01, focus_distance: ") + focus + "}");
    EXPECT_NE(e.find("camera.focus_distance"), std::string::npos) << e;
    EXPECT_NE(e.find("must be > 0"), std::string::npos) << e;
  }
  const std::string missing = errorOf("{aperture: 0.01}");
  EXPECT_NE(missing.find("needs camera.focus_distance"), std::string::npos) << missing;
  const std::string one = errorOf("{aperture: 0.01, focus_distance: 1, aperture_samples: 1}");
  EXPECT_NE(one.find("camera.aperture_samples"), std::string::npos) << one;
  // Meaningless without an aperture: an error, not silently ignored.
  for (const char* key : {"focus_distance: 2", "aperture_samples: 4"}) {
    const std::string e = errorOf(std::string("{") + key + "}");
    EXPECT_NE(e.find("needs camera.aperture > 0"), std::string::npos) << e;
  }
}

TEST_F(DefocusConfigTest, TheGlBackendIsRefused) {
  const std::string e = errorOf("{aperture: 0.01, focus_distance: 1}", "{backend: gl}");
  EXPECT_NE(e.find("camera.aperture"), std::string::npos) << e;
  EXPECT_NE(e.find("render.backend: cpu"), std::string::npos) << e;
  EXPECT_EQ(errorOf("{aperture: 0.01, focus_distance: 1}", "{backend: cpu}"), "");
  EXPECT_EQ(errorOf("{aperture: 0.01, focus_distance: 1}", "{backend: auto}"), "");
}

}  // namespace
}  // namespace tofsim::config
