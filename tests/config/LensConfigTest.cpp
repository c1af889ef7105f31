// camera.lens: OpenCV's intrinsics inline or from the calibration file
// cv::FileStorage writes, the effective config's round trip, and located
// errors for what OpenCV's model cannot mean (skew, a wrong number of
// coefficients, a fold inside the image, a size other than the calibration's).

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "support/TempDir.h"
#include "tofsim/config/RunConfig.h"

namespace tofsim::config {
namespace {

class LensConfigTest : public test::TempDirTest {
 protected:
  RunConfig load(const std::string& camera) {
    std::ofstream(dir_ / "scene.gltf") << "{}";
    std::ofstream(dir_ / "c.yaml") << "scene: scene.gltf\ncamera:\n"
                                   << camera << "light: {}\ntime: {}\n";
    return loadRunConfig(dir_ / "c.yaml");
  }
  std::string errorOf(const std::string& camera) {
    try {
      load(camera);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }
};

// What OpenCV's calibration sample writes (samples/cpp/calibration.cpp):
// the "%YAML:1.0" line, opencv-matrix tags and keys tofsim does not read.
constexpr const char* kCalibration =
    "%YAML:1.0\n"
    "---\n"
    "calibration_time: \"Tue 01 Dec 2026\"\n"
    "image_width: 80\n"
    "image_height: 60\n"
    "flags: 0\n"
    "camera_matrix: !!opencv-matrix\n"
    "   rows: 3\n"
    "   cols: 3\n"
    "   dt: d\n"
    "   data: [ 70.5, 0., 39.25, 0., 71.0, 29.75, 0., 0., 1. ]\n"
    "distortion_coefficients: !!opencv-matrix\n"
    "   rows: 5\n"
    "   cols: 1\n"
    "   dt: d\n"
    "   data: [ -0.21, 0.05, 0.001, -0.002, 0.01 ]\n"
    "avg_reprojection_error: 0.31\n";

TEST_F(LensConfigTest, InlineValuesAreOpenCvsOrder) {
  const RunConfig c = load(
      "  resolution: [64, 48]\n"
      "  lens:\n"
      "    camera_matrix: [[60, 0, 31.5], [0, 61, 23.5], [0, 0, 1]]\n"
      "    distortion: [-0.2, 0.04, 0.001, 0.002, 0.003, 0.01, 0.02, 0.03]\n");
  ASSERT_TRUE(c.camera.camera.lens.has_value());
  const capture::Lens& l = *c.camera.camera.lens;
  EXPECT_EQ(l.fx, 60.0);
  EXPECT_EQ(l.fy, 61.0);
  EXPECT_EQ(l.cx, 31.5);
  EXPECT_EQ(l.cy, 23.5);
  const double expected[14] = {-0.2, 0.04, 0.001, 0.002, 0.003, 0.01, 0.02, 0.03};
  for (int i = 0; i < 14; ++i) EXPECT_EQ(l.distortion[i], expected[i]) << i;
  EXPECT_TRUE(c.camera.lens_calibration.empty());
}

TEST_F(LensConfigTest, ReadsOpenCvsCalibrationFileAndItsImageSize) {
  write("calib.yaml", kCalibration);
  const RunConfig c = load("  lens: {calibration: calib.yaml}\n");
  ASSERT_TRUE(c.camera.camera.lens.has_value());
  const capture::Lens& l = *c.camera.camera.lens;
  EXPECT_EQ(l.fx, 70.5);
  EXPECT_EQ(l.fy, 71.0);
  EXPECT_EQ(l.cx, 39.25);
  EXPECT_EQ(l.cy, 29.75);
  EXPECT_EQ(l.distortion[0], -0.21);
  EXPECT_EQ(l.distortion[4], 0.01);
  EXPECT_EQ(l.distortion[5], 0.0);
  EXPECT_EQ(c.camera.camera.width, 80);  // the calibration's size, no resolution given
  EXPECT_EQ(c.camera.camera.height, 60);
  EXPECT_EQ(c.camera.lens_calibration, (dir_ / "calib.yaml").lexically_normal().string());
}

TEST_F(LensConfigTest, EffectiveConfigReloadsToTheSameLens) {
  write("calib.yaml", kCalibration);
  for (const std::string camera :
       {"  resolution: [64, 48]\n  lens: {camera_matrix: [60, 0, 31.5, 0, 61, 23.5, 0, 0, 1], "
        "distortion: [-0.2, 0.04, 0.001, 0.002, 0.003, 0.01, 0.02, 0.03, 1e-4, 2e-4, 3e-4, "
        "4e-4]}\n",
        "  lens: {calibration: calib.yaml}\n"}) {
    const RunConfig first = load(camera);
    std::ofstream(dir_ / "effective.yaml") << effectiveConfigYaml(first);
    const RunConfig again = loadRunConfig(dir_ / "effective.yaml");
    ASSERT_TRUE(again.camera.camera.lens.has_value()) << camera;
    const capture::Lens &a = *first.camera.camera.lens, &b = *again.camera.camera.lens;
    EXPECT_EQ(a.fx, b.fx);
    EXPECT_EQ(a.fy, b.fy);
    EXPECT_EQ(a.cx, b.cx);
    EXPECT_EQ(a.cy, b.cy);
    EXPECT_EQ(a.distortion, b.distortion);
    EXPECT_EQ(first.camera.camera.width, again.camera.camera.width);
  }
}

TEST_F(LensConfigTest, BadLensesAreLocatedErrors) {
  const std::string k = "camera_matrix: [60, 0, 31.5, 0, 60, 31.5, 0, 0, 1]";
  const std::string both = errorOf("  fov_y: 40\n  lens: {" + k + "}\n");
  EXPECT_NE(both.find("c.yaml:3"), std::string::npos) << both;
  const std::string skew =
      errorOf("  lens: {camera_matrix: [60, 1, 31.5, 0, 60, 31.5, 0, 0, 1]}\n");
  EXPECT_NE(skew.find("camera.lens.camera_matrix"), std::string::npos) << skew;
  EXPECT_NE(skew.find("no skew"), std::string::npos) << skew;
  EXPECT_NE(errorOf("  lens: {camera_matrix: [60, 0, 31.5, 0, 60, 31.5]}\n").find("9 numbers"),
            std::string::npos);
  EXPECT_NE(errorOf("  lens: {camera_matrix: [-60, 0, 31.5, 0, 60, 31.5, 0, 0, 1]}\n")
                .find("fx and fy must be > 0"),
            std::string::npos);
  const std::string count = errorOf("  lens: {" + k + ", distortion: [0.1, 0, 0]}\n");
  EXPECT_NE(count.find("camera.lens.distortion"), std::string::npos) << count;
  EXPECT_NE(count.find("4, 5, 8, 12 or 14"), std::string::npos) << count;
  EXPECT_NE(errorOf("  lens: {" + k + ", calibration: x.yaml}\n").find("not both"),
            std::string::npos);
  // k1 = -1 on a 90 degree wide image: the radius r (1 - r^2) turns back at
  // r = 0.577, inside the image (r up to 0.52 / 0.74 at the corners).
  const std::string fold =
      errorOf("  resolution: [64, 64]\n  lens: {" + k + ", distortion: [-1, 0, 0, 0]}\n");
  EXPECT_NE(fold.find("not invertible at pixel"), std::string::npos) << fold;
  EXPECT_NE(fold.find("camera.lens"), std::string::npos) << fold;
  EXPECT_EQ(errorOf("  resolution: [64, 64]\n  lens: {" + k + ", distortion: [-0.1, 0, 0, 0]}\n"),
            "");
}

TEST_F(LensConfigTest, BadCalibrationFilesAreLocatedInThem) {
  write("calib.yaml", kCalibration);
  const std::string size = errorOf("  resolution: [64, 48]\n  lens: {calibration: calib.yaml}\n");
  EXPECT_NE(size.find("camera.resolution"), std::string::npos) << size;
  EXPECT_NE(size.find("80 x 60"), std::string::npos) << size;
  write("nomatrix.yaml",
        "%YAML:1.0\n---\nimage_width: 80\ndistortion_coefficients: [0, 0, 0, 0]\n");
  const std::string none = errorOf("  lens: {calibration: nomatrix.yaml}\n");
  EXPECT_NE(none.find("nomatrix.yaml"), std::string::npos) << none;
  EXPECT_NE(none.find("camera_matrix"), std::string::npos) << none;
  write("rows.yaml",
        "%YAML:1.0\n---\ncamera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n"
        "   data: [ 70.5, 0., 39.25, 0., 71.0, 29.75, 0., 0. ]\n"
        "distortion_coefficients: [0, 0, 0, 0]\n");
  const std::string rows = errorOf("  lens: {calibration: rows.yaml}\n");
  EXPECT_NE(rows.find("rows.yaml:3"), std::string::npos) << rows;
  EXPECT_NE(rows.find("rows x cols"), std::string::npos) << rows;
  const std::string missing = errorOf("  lens: {calibration: missing.yaml}\n");
  EXPECT_NE(missing.find("calibration file not found"), std::string::npos) << missing;
  std::filesystem::create_directory(dir_ / "calib_folder.yaml");
  const std::string folder = errorOf("  lens: {calibration: calib_folder.yaml}\n");
  EXPECT_NE(folder.find("camera.lens.calibration"), std::string::npos) << folder;
  EXPECT_NE(folder.find("is a folder, not a file"), std::string::npos) << folder;
}

// Issue 39: a camera matrix is in pixels of the image it was calibrated on,
// so a calibration file must say which (it was accepted silently without).
TEST_F(LensConfigTest, CalibrationWithoutItsImageSizeIsALocatedError) {
  std::string text = kCalibration;
  text.erase(text.find("image_height: 60\n"), std::string("image_height: 60\n").size());
  write("noheight.yaml", text);
  const std::string e = errorOf("  resolution: [80, 60]\n  lens: {calibration: noheight.yaml}\n");
  EXPECT_NE(e.find("noheight.yaml"), std::string::npos) << e;
  EXPECT_NE(e.find("has no image_height"), std::string::npos) << e;
  EXPECT_NE(e.find("add image_width and image_height"), std::string::npos) << e;
}

// Issue 39: intrinsics far from the image (cx = 1e6 px, fx = 1e-300 px) are
// named as such, at the matrix, not reported as a distortion that does not
// invert.
TEST_F(LensConfigTest, IntrinsicsOutOfRangeForTheImageAreNamed) {
  const auto matrix = [](const std::string& fx, const std::string& cx) {
    return "  resolution: [64, 48]\n  lens: {camera_matrix: [" + fx + ", 0, " + cx +
           ", 0, 60, 23.5, 0, 0, 1], distortion: [-0.1, 0, 0, 0]}\n";
  };
  const std::string cx = errorOf(matrix("60", "1e6"));
  EXPECT_NE(cx.find("camera.lens.camera_matrix"), std::string::npos) << cx;
  EXPECT_NE(cx.find("cx = 1e+06 px is outside [-64, 128] px"), std::string::npos) << cx;
  EXPECT_EQ(cx.find("invertible"), std::string::npos) << cx;
  const std::string fx = errorOf(matrix("1e-300", "31.5"));
  EXPECT_NE(fx.find("fx = 1e-300 px is outside [0.064, 64000] px"), std::string::npos) << fx;
  EXPECT_NE(fx.find("64 x 48 image"), std::string::npos) << fx;
  EXPECT_EQ(errorOf(matrix("60", "31.5")), "");
  // In a calibration file: located there.
  std::string text = kCalibration;
  text.replace(text.find("39.25"), 5, "1e6");
  write("farcx.yaml", text);
  const std::string file = errorOf("  lens: {calibration: farcx.yaml}\n");
  EXPECT_NE(file.find("farcx.yaml:7"), std::string::npos) << file;
  EXPECT_NE(file.find("cx = 1e+06 px"), std::string::npos) << file;
}

}  // namespace
}  // namespace tofsim::config
