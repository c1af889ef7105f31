#pragma once
// A lidar's returns as point clouds: binary little-endian PLY 1.0 (Open3D,
// CloudCompare, PCL read it) and PCD v0.7 `DATA binary` (PCL's own format),
// one point per return with the same fields in both:
//   x, y, z      float32  world frame, m (the lidar's position + range along
//                         the beam's axis)
//   intensity    float32  the echo's energy (W m^-2 per pulse, Echoes.h)
//   ring         uint16   the channel (LidarSpec.h)
//   azimuth      float32  the beam's azimuth, degrees
//   return_index uint8    0 for the mode's first return, 1 for its second, ...
//   time_offset  float32  the beam's firing time after the scan's start, s
//                         (azimuth steps at lidar.rotation_rate)
// Both written atomically (the util file helpers).

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tofsim::lidar {

struct LidarPoint {
  float x = 0.0f, y = 0.0f, z = 0.0f;
  float intensity = 0.0f;
  uint16_t ring = 0;
  float azimuth_deg = 0.0f;
  uint8_t return_index = 0;
  float time_offset_s = 0.0f;
};

/// The PLY file's bytes; `comment` is one line (no newline) or empty.
std::string plyBytes(const std::vector<LidarPoint>& points, const std::string& comment);
/// The PCD file's bytes.
std::string pcdBytes(const std::vector<LidarPoint>& points);

void writePly(const std::filesystem::path& path, const std::vector<LidarPoint>& points,
              const std::string& comment);
void writePcd(const std::filesystem::path& path, const std::vector<LidarPoint>& points);

}  // namespace tofsim::lidar
