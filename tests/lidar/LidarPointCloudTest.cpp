// The lidar's point clouds read back: binary little-endian PLY and PCL's
// binary PCD, by readers written here from the formats' specifications
// (the header's fields, sizes and types, then packed records).

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "support/TempDir.h"
#include "tofsim/lidar/PointCloudFiles.h"

namespace tofsim::lidar {
namespace {

std::vector<LidarPoint> somePoints() {
  std::vector<LidarPoint> points;
  for (int i = 0; i < 5; ++i) {
    LidarPoint p;
    p.x = 1.5f * i;
    p.y = -2.0f + i;
    p.z = 0.25f * i;
    p.intensity = 1e-3f * (i + 1);
    p.ring = static_cast<uint16_t>(300 + i);
    p.azimuth_deg = 0.2f * i;
    p.return_index = static_cast<uint8_t>(i % 2);
    p.time_offset_s = 5.5e-5f * i;
    points.push_back(p);
  }
  return points;
}

std::string readAll(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

template <typename T>
T take(const std::string& bytes, std::size_t& at) {
  T v;
  std::memcpy(&v, bytes.data() + at, sizeof(T));
  at += sizeof(T);
  return v;
}

// Records of the fields x y z intensity (f32) ring (u16) azimuth (f32)
// return_index (u8) time_offset (f32), from `at` on.
std::vector<LidarPoint> records(const std::string& bytes, std::size_t at, std::size_t n) {
  EXPECT_EQ(bytes.size() - at, n * 27);
  std::vector<LidarPoint> out(n);
  for (LidarPoint& p : out) {
    p.x = take<float>(bytes, at);
    p.y = take<float>(bytes, at);
    p.z = take<float>(bytes, at);
    p.intensity = take<float>(bytes, at);
    p.ring = take<uint16_t>(bytes, at);
    p.azimuth_deg = take<float>(bytes, at);
    p.return_index = take<uint8_t>(bytes, at);
    p.time_offset_s = take<float>(bytes, at);
  }
  return out;
}

void expectSame(const std::vector<LidarPoint>& a, const std::vector<LidarPoint>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].x, b[i].x);
    EXPECT_EQ(a[i].y, b[i].y);
    EXPECT_EQ(a[i].z, b[i].z);
    EXPECT_EQ(a[i].intensity, b[i].intensity);
    EXPECT_EQ(a[i].ring, b[i].ring);
    EXPECT_EQ(a[i].azimuth_deg, b[i].azimuth_deg);
    EXPECT_EQ(a[i].return_index, b[i].return_index);
    EXPECT_EQ(a[i].time_offset_s, b[i].time_offset_s);
  }
}

class LidarPointCloudTest : public test::TempDirTest {};

TEST_F(LidarPointCloudTest, PlyReadsBack) {
  const std::vector<LidarPoint> points = somePoints();
  writePly(dir_ / "p.ply", points, "test");
  const std::string bytes = readAll(dir_ / "p.ply");
  const std::size_t end = bytes.find("end_header\n");
  ASSERT_NE(end, std::string::npos);
  std::istringstream header(bytes.substr(0, end));
  std::string line;
  std::vector<std::string> properties;
  std::size_t count = 0;
  while (std::getline(header, line)) {
    if (line.rfind("format", 0) == 0) {
      EXPECT_EQ(line, "format binary_little_endian 1.0");
    }
    if (line.rfind("element vertex ", 0) == 0) count = std::stoul(line.substr(15));
    if (line.rfind("property ", 0) == 0) properties.push_back(line.substr(9));
  }
  EXPECT_EQ(count, points.size());
  EXPECT_EQ(properties, (std::vector<std::string>{"float x", "float y", "float z",
                                                  "float intensity", "ushort ring",
                                                  "float azimuth", "uchar return_index",
                                                  "float time_offset"}));
  expectSame(records(bytes, end + 11, count), points);
}

TEST_F(LidarPointCloudTest, PcdReadsBack) {
  const std::vector<LidarPoint> points = somePoints();
  writePcd(dir_ / "p.pcd", points);
  const std::string bytes = readAll(dir_ / "p.pcd");
  const std::string marker = "DATA binary\n";
  const std::size_t data = bytes.find(marker);
  ASSERT_NE(data, std::string::npos);
  std::istringstream header(bytes.substr(0, data));
  std::string line;
  std::map<std::string, std::string> keys;
  while (std::getline(header, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::size_t space = line.find(' ');
    keys[line.substr(0, space)] = line.substr(space + 1);
  }
  EXPECT_EQ(keys["VERSION"], "0.7");
  EXPECT_EQ(keys["FIELDS"], "x y z intensity ring azimuth return_index time_offset");
  EXPECT_EQ(keys["SIZE"], "4 4 4 4 2 4 1 4");
  EXPECT_EQ(keys["TYPE"], "F F F F U F U F");
  EXPECT_EQ(keys["COUNT"], "1 1 1 1 1 1 1 1");
  EXPECT_EQ(keys["HEIGHT"], "1");
  EXPECT_EQ(std::stoul(keys["WIDTH"]), points.size());
  EXPECT_EQ(std::stoul(keys["POINTS"]), points.size());
  expectSame(records(bytes, data + marker.size(), points.size()), points);
}

}  // namespace
}  // namespace tofsim::lidar
