// `rays:` in place of `camera:` (RayFile.h): a capture whose pixels are the
// rays of a .npy (float32 or float64) or CSV file, directions normalised,
// and located errors for bad files (the key, the ray file and its line),
// both imagers at once, links and a zero direction.

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <string>

#include "support/TempDir.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/util/Error.h"

namespace tofsim::config {
namespace {

class RayListConfigTest : public test::TempDirTest {
 protected:
  std::filesystem::path writeConfig(const std::string& view) {
    std::filesystem::create_symlink(std::filesystem::path(TOFSIM_SOURCE_DIR) / "configs/scenes",
                                    dir_ / "scenes");
    const std::filesystem::path file = dir_ / "run.yaml";
    std::ofstream(file) << "scene: scenes/cornell_box.gltf\n"
                        << view
                        << "light: {type: point, position: [0.28, 0.5, 0.28]}\n"
                           "time: {start: 0 m, bin_width: 10 ps, bins: 64}\n";
    return file;
  }
  std::string errorOf(const std::string& view) {
    try {
      loadRunConfig(writeConfig(view));
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  void writeNpy64(const std::string& name, const std::vector<double>& values, std::size_t rows) {
    std::string dict = "{'descr': '<f8', 'fortran_order': False, 'shape': (" +
                       std::to_string(rows) + ", 6), }";
    dict.append(64 - (10 + dict.size() + 1) % 64, ' ');
    dict += '\n';
    std::string bytes = "\x93NUMPY\x01";
    bytes += '\0';
    bytes += static_cast<char>(dict.size() & 0xFF);
    bytes += static_cast<char>(dict.size() >> 8);
    bytes += dict;
    bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double));
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
  }
};

TEST_F(RayListConfigTest, ACsvGivesAnNx1ImageOfUnitRays) {
  std::ofstream(dir_ / "rays.csv") << "ox,oy,oz,dx,dy,dz\n0,0,1,0,0,-2\n# a comment\n1,2,3,3,0,4\n";
  const RunConfig c = loadRunConfig(writeConfig("rays: {file: rays.csv}\n"));
  ASSERT_TRUE(c.rays.has_value());
  const capture::RayListImager& r = c.rays->imager;
  EXPECT_EQ(r.width, 2);
  EXPECT_EQ(r.height, 1);
  EXPECT_EQ(c.camera.camera.width, 2);
  EXPECT_EQ(r.rays[0].direction, glm::vec3(0, 0, -1));
  EXPECT_EQ(r.rays[1].origin, glm::vec3(1, 2, 3));
  EXPECT_NEAR(r.rays[1].direction.x, 0.6f, 1e-7f);
  EXPECT_NEAR(r.rays[1].direction.z, 0.8f, 1e-7f);
  EXPECT_TRUE(r.last_leg_counts);
}

TEST_F(RayListConfigTest, AFloat64NpyWithAResolution) {
  std::vector<double> values;
  for (int i = 0; i < 4; ++i) values.insert(values.end(), {0.1 * i, 0, 1, 0, 1, 0});
  writeNpy64("rays.npy", values, 4);
  const RunConfig c = loadRunConfig(
      writeConfig("rays: {file: rays.npy, resolution: [2, 2], last_leg_counts: false}\n"));
  const capture::RayListImager& r = c.rays->imager;
  EXPECT_EQ(r.width, 2);
  EXPECT_EQ(r.height, 2);
  EXPECT_FLOAT_EQ(r.rays[3].origin.x, 0.3f);
  EXPECT_FALSE(r.last_leg_counts);
}

TEST_F(RayListConfigTest, TheEffectiveConfigRoundTrips) {
  std::ofstream(dir_ / "rays.csv") << "0,0,1,0,0,-1\n0,0,1,0,1,-1\n";
  const std::filesystem::path file = writeConfig(
      "rays: {file: rays.csv, resolution: [1, 2], last_leg_counts: false}\n");
  const std::string written = effectiveConfigYaml(loadRunConfig(file));
  EXPECT_EQ(written.find("\ncamera:"), std::string::npos) << written;
  std::ofstream(dir_ / "again.yaml") << written;
  const RunConfig again = loadRunConfig(dir_ / "again.yaml");
  ASSERT_TRUE(again.rays.has_value());
  EXPECT_EQ(again.rays->imager.height, 2);
  EXPECT_FALSE(again.rays->imager.last_leg_counts);
  EXPECT_EQ(effectiveConfigYaml(again), written);
}

TEST_F(RayListConfigTest, BadFilesAreLocatedErrors) {
  std::ofstream(dir_ / "zero.csv") << "0,0,1,0,0,-1\n0,0,1,0,0,0\n";
  std::string e = errorOf("rays: {file: zero.csv}\n");
  EXPECT_NE(e.find("run.yaml:2"), std::string::npos) << e;
  EXPECT_NE(e.find("zero.csv:2"), std::string::npos) << e;
  EXPECT_NE(e.find("direction is zero"), std::string::npos) << e;
}

TEST_F(RayListConfigTest, ShortRowsAndWrongShapesAndResolutions) {
  std::ofstream(dir_ / "short.csv") << "0,0,1,0,0\n";
  EXPECT_NE(errorOf("rays: {file: short.csv}\n").find("short.csv:1"), std::string::npos);
  std::filesystem::remove(dir_ / "scenes");
  writeNpy64("rays.npy", {0, 0, 1, 0, 0, -1}, 1);
  const std::string e = errorOf("rays: {file: rays.npy, resolution: [2, 1]}\n");
  EXPECT_NE(e.find("resolution"), std::string::npos) << e;
}

TEST_F(RayListConfigTest, OneImagerAndNoLinks) {
  std::ofstream(dir_ / "rays.csv") << "0,0,1,0,0,-1\n";
  std::string e = errorOf("rays: {file: rays.csv}\ncamera: {resolution: [4, 4]}\n");
  EXPECT_NE(e.find("not both"), std::string::npos) << e;
  std::filesystem::remove(dir_ / "scenes");
  std::filesystem::create_symlink(dir_ / "rays.csv", dir_ / "link.csv");
  e = errorOf("rays: {file: link.csv}\n");
  EXPECT_NE(e.find("symbolic link"), std::string::npos) << e;
}

}  // namespace
}  // namespace tofsim::config
