#include "tofsim/lidar/PointCloudFiles.h"

#include <bit>
#include <cstring>

#include "tofsim/util/AtomicFile.h"

namespace tofsim::lidar {

namespace {

static_assert(std::endian::native == std::endian::little,
              "the point-cloud writers copy little-endian values as they are in memory");

template <typename T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

// One point's record, the same packed layout in both formats (27 bytes).
void putPoint(std::string& out, const LidarPoint& p) {
  put(out, p.x);
  put(out, p.y);
  put(out, p.z);
  put(out, p.intensity);
  put(out, p.ring);
  put(out, p.azimuth_deg);
  put(out, p.return_index);
  put(out, p.time_offset_s);
}

}  // namespace

std::string plyBytes(const std::vector<LidarPoint>& points, const std::string& comment) {
  std::string out = "ply\nformat binary_little_endian 1.0\n";
  if (!comment.empty()) out += "comment " + comment + "\n";
  out += "element vertex " + std::to_string(points.size()) + "\n";
  out +=
      "property float x\nproperty float y\nproperty float z\nproperty float intensity\n"
      "property ushort ring\nproperty float azimuth\nproperty uchar return_index\n"
      "property float time_offset\nend_header\n";
  for (const LidarPoint& p : points) putPoint(out, p);
  return out;
}

std::string pcdBytes(const std::vector<LidarPoint>& points) {
  const std::string n = std::to_string(points.size());
  std::string out =
      "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\n"
      "FIELDS x y z intensity ring azimuth return_index time_offset\n"
      "SIZE 4 4 4 4 2 4 1 4\nTYPE F F F F U F U F\nCOUNT 1 1 1 1 1 1 1 1\n"
      "WIDTH " + n + "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + n + "\nDATA binary\n";
  for (const LidarPoint& p : points) putPoint(out, p);
  return out;
}

void writePly(const std::filesystem::path& path, const std::vector<LidarPoint>& points,
              const std::string& comment) {
  writeFileAtomically(path, plyBytes(points, comment));
}

void writePcd(const std::filesystem::path& path, const std::vector<LidarPoint>& points) {
  writeFileAtomically(path, pcdBytes(points));
}

}  // namespace tofsim::lidar
